import gridMetric from './gridMetric.glsl';

/**
 * Splat: one point per site (gl_VertexID = site id), drawn at the texel that contains
 * the site, carrying its label (exact position, id). The label target has the grid's size.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
flat out vec3 siteLabel;
void main() {
  vec2 site = siteAt(gl_VertexID);
  vec2 texel = min(floor(site), vec2(gridSize) - 1.0) + 0.5;
  siteLabel = vec3(site, float(gl_VertexID));
  gl_Position = vec4(texel / vec2(gridSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;
