/**
 * Shared GLSL: the grid's metric and the site lookup, exactly the conventions of
 * src/core/grid.ts (texel units, centres at i + 0.5, minimum image on periodic axes,
 * physical distance scaled by the texel size in µm).
 *
 * Which axes wrap is compiled in (defines PERIODIC_X, PERIODIC_Y = 0 or 1), not a uniform:
 * software renderers run both sides of a uniform branch, and the jump flood's inner loop is
 * the hot spot of the whole engine.
 */
export default /* glsl */ `
uniform ivec2 gridSize;
uniform vec2 texelSize;
const bvec2 periodic = bvec2(PERIODIC_X == 1, PERIODIC_Y == 1);
uniform highp sampler2D sites;
uniform int siteWidth;

vec2 siteAt(int id) {
  return texelFetch(sites, ivec2(id % siteWidth, id / siteWidth), 0).xy;
}

// Minimum-image offset from a to b, in texel units.
vec2 gridDelta(vec2 a, vec2 b) {
  vec2 d = b - a;
  vec2 size = vec2(gridSize);
  if (periodic.x) d.x -= size.x * floor(d.x / size.x + 0.5);
  if (periodic.y) d.y -= size.y * floor(d.y / size.y + 0.5);
  return d;
}

float physicalDistanceSquared(vec2 a, vec2 b) {
  vec2 d = gridDelta(a, b) * texelSize;
  return dot(d, d);
}

// Wraps a texel index on a periodic axis; returns false when it falls off an open edge.
bool wrapTexel(inout ivec2 q) {
  if (periodic.x) q.x -= gridSize.x * int(floor(float(q.x) / float(gridSize.x)));
  else if (q.x < 0 || q.x >= gridSize.x) return false;
  if (periodic.y) q.y -= gridSize.y * int(floor(float(q.y) / float(gridSize.y)));
  else if (q.y < 0 || q.y >= gridSize.y) return false;
  return true;
}
`;
