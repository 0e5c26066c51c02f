import labelId from './labelId.glsl';

/**
 * Centroid pass, fast path (Rong et al., procedure 2 of the seed): one point per texel
 * (gl_VertexID = texel index) is sent to the pixel of its site in the sums target, where
 * additive blending adds up, per site:
 *   (w * dx, w * dy, w, w * |d|²)
 * with d the minimum-image offset from the site to the texel centre (texel units; small
 * numbers that unwrap across periodic seams), w = density x area element, and |d|² in µm²
 * (the site's share of the CVT energy). Needs EXT_float_blend for RGBA32F targets.
 *
 * The labels are the flood's output (each texel's site position); the site's id, which picks
 * the target pixel, is looked up here in the id map rather than in a separate resolve pass.
 */
export default /* glsl */ `
${labelId}
uniform highp sampler2D weights;
uniform ivec2 sumsSize;
out vec4 contribution;

void main() {
  ivec2 p = ivec2(gl_VertexID % gridSize.x, gl_VertexID / gridSize.x);
  vec2 position = texelFetch(labels, p, 0).xy;
  float id = position.x < 0.0 ? -1.0 : texelFetch(idMap, siteTexel(position), 0).r;
  gl_PointSize = 1.0;
  if (id < 0.0) {
    gl_Position = vec4(2.0, 2.0, 2.0, 1.0); // outside the clip volume: dropped
    contribution = vec4(0.0);
    return;
  }
  int site = int(id);
  vec2 d = gridDelta(position, vec2(p) + 0.5);
  float w = texelFetch(weights, p, 0).r;
  vec2 dPhysical = d * texelSize;
  contribution = vec4(w * d, w, w * dot(dPhysical, dPhysical));
  vec2 target = vec2(site % sumsSize.x, site / sumsSize.x) + 0.5;
  gl_Position = vec4(target / vec2(sumsSize) * 2.0 - 1.0, 0.0, 1.0);
}
`;
