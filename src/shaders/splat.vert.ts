/**
 * Splat: one point per site (gl_VertexID = site id), drawn at the texel the site lies in (the
 * metric's siteTexel), carrying the site's label. Pairs with point.frag.
 */
export default /* glsl */ `
flat out vec4 value;
void main() {
  vec4 site = siteAt(gl_VertexID);
  value = vec4(site.xyz, float(gl_VertexID));
  gl_Position = vec4((vec2(siteTexel(site)) + 0.5) / vec2(atlasSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;
