import cubeMetric from './cubeMetric.glsl';

/**
 * One jump-flood step on a cube map: every texel looks at the labels of its 8 neighbours at
 * distance stepSize on its face, continued across face edges by the edge table, and keeps the
 * site nearest to its surface point in 3D (Du et al.'s CCVT on surfaces uses the Euclidean
 * distance of the embedding). Ties go to the smaller id, as in the CPU reference.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${cubeMetric}
uniform highp sampler2D labels;
uniform int stepSize;
out vec4 label;

void main() {
  ivec2 p = ivec2(gl_FragCoord.xy);
  int face = p.y / faceSize;
  int j = p.y - face * faceSize;
  vec3 here = positionAt(p);
  float best = texelFetch(labels, p, 0).r;
  float bestDistance = 3.4e38;
  if (best >= 0.0) { vec3 d = siteAt(int(best)).xyz - here; bestDistance = dot(d, d); }
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      if (dx == 0 && dy == 0) continue;
      int qi = p.x + dx * stepSize, qj = j + dy * stepSize;
      // Inside the face (most fetches): no edge table needed.
      ivec2 q = (qi >= 0 && qi < faceSize && qj >= 0 && qj < faceSize) ? ivec2(qi, face * faceSize + qj) : cubeWrap(face, qi, qj);
      float candidate = texelFetch(labels, q, 0).r;
      if (candidate < 0.0 || candidate == best) continue;
      vec3 d = siteAt(int(candidate)).xyz - here;
      float distance = dot(d, d);
      if (distance < bestDistance || (distance == bestDistance && candidate < best)) {
        best = candidate;
        bestDistance = distance;
      }
    }
  }
  label = vec4(best, 0.0, 0.0, 1.0);
}
`;
