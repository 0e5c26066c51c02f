/**
 * Shared GLSL: the site id of a texel's flood label (-1 for none), found through the id map at
 * the label's site texel. Needs siteTexel.glsl and the uniforms `labels` and `idMap` declared
 * before it. Used by the id resolve, the id packing and the warm-start refresh passes.
 */
export default /* glsl */ `
float labelIdAt(ivec2 texel) {
  vec2 site = texelFetch(labels, texel, 0).xy;
  return site.x < 0.0 ? -1.0 : texelFetch(idMap, siteTexel(site), 0).r;
}
`;
