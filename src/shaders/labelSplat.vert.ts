import gridMetric from './gridMetric.glsl';
import siteTexel from './siteTexel.glsl';

/**
 * Splat: one point per site (gl_VertexID = site id), drawn at the texel that contains the
 * site. With labelSplat.frag it writes the site's position into the labels; with
 * idSplat.frag its id into the id map.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
${siteTexel}
flat out vec3 siteLabel;
void main() {
  vec2 site = siteAt(gl_VertexID);
  siteLabel = vec3(site, float(gl_VertexID));
  gl_Position = vec4((vec2(siteTexel(site)) + 0.5) / vec2(gridSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;
