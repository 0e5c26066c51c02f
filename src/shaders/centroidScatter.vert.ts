/**
 * Centroid pass, fast path (Rong et al., procedure 2; needs EXT_float_blend for RGBA32F
 * targets): one point per texel (gl_VertexID = texel index) is sent to the pixel of its site in
 * the sums target, where additive blending adds up, per site, with d the metric's offset from
 * the site to the texel's point (small numbers, unwrapped across seams), w the texel's weight
 * (density x area element) and |d|² in µm² (the site's share of the CVT energy):
 *   planar grid (SPLIT_ENERGY 0): (w d.x, w d.y, w, w |d|²) in one pass;
 *   cube map (SPLIT_ENERGY 1):    (w d.x, w d.y, w d.z, w), then energyPass: (w |d|², 0, 0, 0).
 */
export default /* glsl */ `
uniform highp sampler2D labels;
uniform ivec2 sumsSize;
uniform bool energyPass;
flat out vec4 value;

void main() {
  ivec2 p = ivec2(gl_VertexID % atlasSize.x, gl_VertexID / atlasSize.x);
  vec4 label = texelFetch(labels, p, 0);
  gl_PointSize = 1.0;
  if (label.w < 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: dropped
    value = vec4(0.0);
    return;
  }
  int site = int(label.w);
  vec3 d = metricOffset(label.xyz, texelPoint(p));
  float w = texelWeight(p);
  float energy = w * physicalSquared(d);
#if SPLIT_ENERGY
  value = energyPass ? vec4(energy, 0.0, 0.0, 0.0) : vec4(w * d, w);
#else
  value = vec4(w * d.xy, w, energy);
#endif
  vec2 target = vec2(site % sumsSize.x, site / sumsSize.x) + 0.5;
  gl_Position = vec4(target / vec2(sumsSize) * 2.0 - 1.0, 0.0, 1.0);
}
`;
