/**
 * The cube map's metric (closed surfaces), the conventions of src/core/cubemap/cubemap.ts: face
 * f has n x n texels; texel (f, i, j) sits at (i, f n + j) of an n x 6n atlas (the "vertical
 * strip"); stepping off a face edge continues on the neighbour face through the integer edge
 * table texelEdgeTable(n) (6 faces x 4 edges x 7 ints: [face', A, B, C, D, E, F],
 * i' = A i + B j + C, j' = D i + E j + F), uploaded as a uniform array. The geometry texture
 * holds each texel's surface point (xyz, µm) and weight (w); distances are 3D Euclidean (Du et
 * al.'s CCVT on surfaces uses the distance of the embedding); sites.w holds the atlas index of
 * the texel the site lies in.
 */
export default /* glsl */ `
uniform int edgeTable[168];

ivec2 siteTexel(vec4 site) {
  int index = int(site.w);
  return ivec2(index % atlasSize.x, index / atlasSize.x);
}

vec3 texelPoint(ivec2 p) {
  return texelFetch(geometry, p, 0).xyz;
}

float texelWeight(ivec2 p) {
  return texelFetch(geometry, p, 0).w;
}

vec3 metricOffset(vec3 a, vec3 b) {
  return b - a;
}

float floodDistance(vec3 site, vec3 point) {
  vec3 d = point - site;
  return dot(d, d);
}

float physicalSquared(vec3 offset) {
  return dot(offset, offset);
}

// Brings (face, i, j), which may lie up to one face beyond an edge, back onto the cube map
// by crossing edges one at a time (at most 3: a step past a corner crosses two).
ivec2 cubeWrap(int face, int i, int j) {
  int n = atlasSize.x;
  for (int k = 0; k < 3; ++k) {
    int edge = i < 0 ? 0 : (i >= n ? 1 : (j < 0 ? 2 : (j >= n ? 3 : -1)));
    if (edge < 0) break;
    int o = (face * 4 + edge) * 7;
    int ni = edgeTable[o + 1] * i + edgeTable[o + 2] * j + edgeTable[o + 3];
    int nj = edgeTable[o + 4] * i + edgeTable[o + 5] * j + edgeTable[o + 6];
    face = edgeTable[o];
    i = ni;
    j = nj;
  }
  return ivec2(clamp(i, 0, n - 1), face * n + clamp(j, 0, n - 1));
}

// A closed surface has no edge: every step lands on a texel (inside the face: no table).
bool stepTexel(ivec2 p, ivec2 offset, out ivec2 q) {
  int n = atlasSize.x;
  int face = p.y / n;
  int i = p.x + offset.x, j = p.y - face * n + offset.y;
  q = (i >= 0 && i < n && j >= 0 && j < n) ? ivec2(i, face * n + j) : cubeWrap(face, i, j);
  return true;
}
`;
