/**
 * After a flood: each texel's site id (the label's w) packed into the four bytes of an RGBA8
 * target, least significant byte in red, so that a readback (RGBA / UNSIGNED_BYTE, 4 bytes a
 * texel, a sixteenth of a float readback) viewed as a little-endian Int32Array is the id itself.
 * An empty texel is 0xFFFFFFFF, which that view reads as -1. Each byte k is written as k / 255,
 * which UNORM8 stores exactly.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
uniform highp sampler2D labels;
out vec4 packedId;

void main() {
  float id = texelFetch(labels, ivec2(gl_FragCoord.xy), 0).w;
  uint bits = id < 0.0 ? 0xFFFFFFFFu : uint(id);
  packedId = vec4(uvec4(bits, bits >> 8u, bits >> 16u, bits >> 24u) & 255u) / 255.0;
}
`;
