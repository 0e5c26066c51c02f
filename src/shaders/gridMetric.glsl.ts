/**
 * The planar grid's metric (plane, tube, torus), the conventions of src/core/grid.ts: texel
 * units, centres at i + 0.5, minimum image on periodic axes, physical distance scaled by the
 * texel size in µm. The geometry texture holds the per-texel weight (R32F).
 *
 * Which axes wrap is compiled in (defines PERIODIC_X, PERIODIC_Y = 0 or 1), not a uniform:
 * software renderers run both sides of a uniform branch, and the flood's inner loop is the hot
 * spot of the whole engine. Flood distances are in units of texelX (only y is scaled, by the
 * texel aspect ratio): as cheap as the plainest flood.
 */
export default /* glsl */ `
uniform vec2 texelSize;
uniform float aspect;
const bvec2 periodic = bvec2(PERIODIC_X == 1, PERIODIC_Y == 1);

ivec2 siteTexel(vec4 site) {
  return ivec2(min(floor(site.xy), vec2(atlasSize) - 1.0));
}

vec3 texelPoint(ivec2 p) {
  return vec3(vec2(p) + 0.5, 0.0);
}

float texelWeight(ivec2 p) {
  return texelFetch(geometry, p, 0).r;
}

// Minimum-image offset from site a to point b, texel units.
vec3 metricOffset(vec3 a, vec3 b) {
  vec2 d = b.xy - a.xy;
  vec2 size = vec2(atlasSize);
  if (periodic.x) d.x -= size.x * floor(d.x / size.x + 0.5);
  if (periodic.y) d.y -= size.y * floor(d.y / size.y + 0.5);
  return vec3(d, 0.0);
}

float floodDistance(vec3 site, vec3 point) {
  vec2 d = metricOffset(site, point).xy;
  d.y *= aspect;
  return dot(d, d);
}

float physicalSquared(vec3 offset) {
  vec2 d = offset.xy * texelSize;
  return dot(d, d);
}

// Wraps a texel index on a periodic axis; returns false when it falls off an open edge.
bool wrapTexel(inout ivec2 q) {
  if (periodic.x) q.x -= atlasSize.x * int(floor(float(q.x) / float(atlasSize.x)));
  else if (q.x < 0 || q.x >= atlasSize.x) return false;
  if (periodic.y) q.y -= atlasSize.y * int(floor(float(q.y) / float(atlasSize.y)));
  else if (q.y < 0 || q.y >= atlasSize.y) return false;
  return true;
}

bool stepTexel(ivec2 p, ivec2 offset, out ivec2 q) {
  q = p + offset;
  return wrapTexel(q);
}
`;
