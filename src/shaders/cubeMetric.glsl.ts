/**
 * Shared GLSL for cube-map geometry images (closed surfaces), the conventions of
 * src/core/cubemap/cubemap.ts: face f has n x n texels; texel (f, i, j) sits at (i, f n + j) of
 * an n x 6n atlas (the "vertical strip"); stepping off a face edge continues on the neighbour
 * face through the integer edge table texelEdgeTable(n) (6 faces x 4 edges x 7 ints:
 * [face', A, B, C, D, E, F], i' = A i + B j + C, j' = D i + E j + F), uploaded as a uniform
 * array. Distances are 3D Euclidean between a texel's surface point (positions texture, xyz)
 * and a site (sites texture, xyz); sites.w holds the atlas index of the texel the site lies in.
 */
export default /* glsl */ `
uniform int faceSize;
uniform int edgeTable[168];
uniform highp sampler2D positions;
uniform highp sampler2D sites;
uniform int siteWidth;

vec4 siteAt(int id) {
  return texelFetch(sites, ivec2(id % siteWidth, id / siteWidth), 0);
}

// Brings (face, i, j), which may lie up to one face beyond an edge, back onto the cube map
// by crossing edges one at a time (at most 3: a step past a corner crosses two).
ivec2 cubeWrap(int face, int i, int j) {
  for (int k = 0; k < 3; ++k) {
    int edge = i < 0 ? 0 : (i >= faceSize ? 1 : (j < 0 ? 2 : (j >= faceSize ? 3 : -1)));
    if (edge < 0) break;
    int o = (face * 4 + edge) * 7;
    int ni = edgeTable[o + 1] * i + edgeTable[o + 2] * j + edgeTable[o + 3];
    int nj = edgeTable[o + 4] * i + edgeTable[o + 5] * j + edgeTable[o + 6];
    face = edgeTable[o];
    i = ni;
    j = nj;
  }
  i = clamp(i, 0, faceSize - 1);
  j = clamp(j, 0, faceSize - 1);
  return ivec2(i, face * faceSize + j);
}

vec3 positionAt(ivec2 atlas) {
  return texelFetch(positions, atlas, 0).xyz;
}
`;
