/**
 * Shared GLSL preamble of every engine pass, whatever the surface: the site lookup and the
 * label convention. A label (RGBA32F, one per texel of the geometry image) is the nearest
 * site's coordinates in the metric's space (xyz; z = 0 on a planar grid) and its id (w; -1 for
 * "no site"), exact copies of the site texture's values, so a flood step needs no dependent
 * fetch and every later pass reads the id directly. A metric chunk (gridMetric, cubeMetric)
 * follows it and gives every surface the same functions: siteTexel, texelPoint, texelWeight,
 * metricOffset, floodDistance, physicalSquared, stepTexel.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
uniform ivec2 atlasSize;
uniform highp sampler2D sites;
uniform int siteWidth;
uniform highp sampler2D geometry;

vec4 siteAt(int id) {
  return texelFetch(sites, ivec2(id % siteWidth, id / siteWidth), 0);
}
`;
