import cubeMetric from './cubeMetric.glsl';

/**
 * Centroid pass on a cube map, fast path (needs EXT_float_blend): one point per texel is sent
 * to its site's pixel in the sums target, where additive blending adds up, per site,
 *   energyPass false: (w (p - s).x, w (p - s).y, w (p - s).z, w)
 *   energyPass true:  (w |p - s|², 0, 0, 0)
 * with p the texel's surface point, s the site and w = density x area element (positions.w).
 * Offsets relative to the site keep the float32 sums small. Pairs with centroidScatter.frag.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${cubeMetric}
uniform highp sampler2D labels;
uniform ivec2 sumsSize;
uniform bool energyPass;
out vec4 contribution;

void main() {
  ivec2 p = ivec2(gl_VertexID % faceSize, gl_VertexID / faceSize);
  float id = texelFetch(labels, p, 0).r;
  gl_PointSize = 1.0;
  if (id < 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0);
    contribution = vec4(0.0);
    return;
  }
  int site = int(id);
  vec4 texel = texelFetch(positions, p, 0);
  vec3 d = texel.xyz - siteAt(site).xyz;
  float w = texel.w;
  contribution = energyPass ? vec4(w * dot(d, d), 0.0, 0.0, 0.0) : vec4(w * d, w);
  vec2 target = vec2(site % sumsSize.x, site / sumsSize.x) + 0.5;
  gl_Position = vec4(target / vec2(sumsSize) * 2.0 - 1.0, 0.0, 1.0);
}
`;
