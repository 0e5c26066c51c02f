/**
 * Shared GLSL: the texel a site position is splatted to, and where its id is kept
 * (the id map). Used by the splat and the refresh passes alike.
 */
export default /* glsl */ `
ivec2 siteTexel(vec2 site) {
  return ivec2(min(floor(site), vec2(gridSize) - 1.0));
}
`;
