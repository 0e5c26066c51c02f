import gridMetric from './gridMetric.glsl';

/**
 * One jump-flood step (Rong & Tan): every texel looks at the labels of its 8 neighbours at
 * distance stepSize (wrapped across periodic edges) and keeps the nearest site.
 *
 * A label is the nearest site's position (x, y) in RG32F, an exact copy of the site texture's
 * value (written by the splat or the refresh pass, never computed), so a step needs one 8-byte
 * fetch per neighbour, like the plainest jump flood. The site's id is looked up in the id map
 * by the passes that need it (centroids, the packed readback), never by the flood. Empty texels have x = -1. Distances are compared in units of
 * texelX (only y is scaled, by the texel aspect ratio), as cheap as the plainest flood. On an
 * exact tie the label found first in the fixed scan order stays: deterministic; the CPU
 * reference breaks ties by smaller id, and exact ties are rare enough to stay within the
 * tests' error bound.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
uniform highp sampler2D labels;
uniform int stepSize;
uniform float aspect;
out vec4 label;

float scaledDistanceSquared(vec2 a, vec2 b) {
  vec2 d = gridDelta(a, b);
  d.y *= aspect;
  return dot(d, d);
}

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 centre = vec2(p) + 0.5;
  vec2 best = texelFetch(labels, p, 0).xy;
  float bestDistance = best.x < 0.0 ? 3.4e38 : scaledDistanceSquared(centre, best);
  for (int k = 0; k < 8; ++k) {
    // The 8 neighbours: k = 0..7 -> (dx, dy) in {-1, 0, 1}² without (0, 0).
    int n = k < 4 ? k : k + 1;
    ivec2 q = p + (ivec2(n % 3, n / 3) - 1) * stepSize;
    if (!wrapTexel(q)) continue;
    vec2 candidate = texelFetch(labels, q, 0).xy;
    if (candidate.x < 0.0) continue;
    float d = scaledDistanceSquared(centre, candidate);
    if (d < bestDistance) {
      best = candidate;
      bestDistance = d;
    }
  }
  label = vec4(best, 0.0, 1.0);
}
`;
