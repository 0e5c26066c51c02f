/**
 * One jump-flood step (Rong & Tan) on any surface: every texel looks at the labels of its 8
 * neighbours at distance stepSize (the metric's stepTexel: wrapped across periodic edges or
 * continued across cube faces) and keeps the nearest site. Labels carry the site's coordinates,
 * so a neighbour costs one fetch. Exact ties go to the smaller id, as in the CPU references.
 */
export default /* glsl */ `
uniform highp sampler2D labels;
uniform int stepSize;
out vec4 label;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  vec3 here = texelPoint(p);
  vec4 best = texelFetch(labels, p, 0);
  float bestDistance = best.w < 0.0 ? 3.4e38 : floodDistance(best.xyz, here);
  for (int k = 0; k < 8; ++k) {
    // The 8 neighbours: k = 0..7 -> (dx, dy) in {-1, 0, 1}² without (0, 0).
    int n = k < 4 ? k : k + 1;
    ivec2 q;
    if (!stepTexel(p, (ivec2(n % 3, n / 3) - 1) * stepSize, q)) continue;
    vec4 candidate = texelFetch(labels, q, 0);
    if (candidate.w < 0.0) continue;
    float d = floodDistance(candidate.xyz, here);
    if (d < bestDistance || (d == bestDistance && candidate.w < best.w)) {
      best = candidate;
      bestDistance = d;
    }
  }
  label = best;
}
`;
