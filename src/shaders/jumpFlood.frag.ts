import gridMetric from './gridMetric.glsl';

/**
 * One jump-flood step (Rong & Tan): every texel looks at the labels of its 8 neighbours at
 * distance stepSize (wrapped across periodic edges) and keeps the nearest site.
 *
 * A label is (site x, site y, site id, 1): the id is what the flood is about; the position is
 * an exact copy of the site texture's (written by the splat or the refresh pass, never
 * computed), carried along so a step needs one fetch per neighbour instead of two. Ties go to
 * the smaller id, as in the CPU reference. Empty texels have id -1.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
uniform highp sampler2D labels;
uniform int stepSize;
out vec4 label;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec2 centre = vec2(p) + 0.5;
  vec4 best = texelFetch(labels, p, 0);
  float bestDistance = best.z < 0.0 ? 3.4e38 : physicalDistanceSquared(centre, best.xy);
  for (int k = 0; k < 8; ++k) {
    // The 8 neighbours: k = 0..7 -> (dx, dy) in {-1, 0, 1}² without (0, 0).
    int n = k < 4 ? k : k + 1;
    ivec2 q = p + (ivec2(n % 3, n / 3) - 1) * stepSize;
    if (!wrapTexel(q)) continue;
    vec4 candidate = texelFetch(labels, q, 0);
    if (candidate.z < 0.0) continue;
    float d = physicalDistanceSquared(centre, candidate.xy);
    // Same site: same distance and same id, so no change; a tie goes to the smaller id.
    if (d < bestDistance || (d == bestDistance && candidate.z < best.z)) {
      best = candidate;
      bestDistance = d;
    }
  }
  label = best;
}
`;
