import gridMetric from './gridMetric.glsl';

/**
 * One jump-flood step (Rong & Tan): every texel looks at the labels of its 8 neighbours
 * at distance stepSize (wrapped across periodic edges) and keeps the nearest site.
 * Labels are site ids; positions come from the site texture, so nothing drifts.
 * Ties go to the smaller id, as in the CPU reference.
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
  float best = texelFetch(labels, p, 0).r;
  float bestDistance = best < 0.0 ? 3.4e38 : physicalDistanceSquared(centre, siteAt(int(best)));
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      ivec2 q = p + ivec2(dx, dy) * stepSize;
      if (!wrapTexel(q)) continue;
      float candidate = texelFetch(labels, q, 0).r;
      if (candidate < 0.0 || candidate == best) continue;
      float d = physicalDistanceSquared(centre, siteAt(int(candidate)));
      if (d < bestDistance || (d == bestDistance && candidate < best)) {
        best = candidate;
        bestDistance = d;
      }
    }
  }
  label = vec4(best, 0.0, 0.0, 1.0);
}
`;
