import gridMetric from './gridMetric.glsl';
import siteTexel from './siteTexel.glsl';

/**
 * Shared GLSL preamble of every pass that reads flood labels: precision, the grid metric, the
 * site texel lookup, the \`labels\` (each texel's nearest site position) and \`idMap\` (each
 * site's id at its splat texel) samplers, and labelIdAt: the site id of a texel's flood label
 * (-1 for none). Used by the id packing, warm-start refresh and centroid passes. Compiled with
 * LABELS_ARE_IDS (the cube map's floods, which label texels with ids), labelIdAt reads the id
 * itself.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
${siteTexel}
uniform highp sampler2D labels;
uniform highp sampler2D idMap;

float labelIdAt(ivec2 texel) {
#ifdef LABELS_ARE_IDS
  return texelFetch(labels, texel, 0).r;
#else
  vec2 site = texelFetch(labels, texel, 0).xy;
  return site.x < 0.0 ? -1.0 : texelFetch(idMap, siteTexel(site), 0).r;
#endif
}
`;
