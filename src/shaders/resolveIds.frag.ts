import gridMetric from './gridMetric.glsl';
import siteTexel from './siteTexel.glsl';

/** After a flood: each texel's site id, looked up in the id map at its label's site texel. */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
${siteTexel}
uniform highp sampler2D labels;
uniform highp sampler2D idMap;
out vec4 id;

void main() {
  vec2 site = texelFetch(labels, ivec2(gl_FragCoord.xy), 0).xy;
  id = vec4(site.x < 0.0 ? -1.0 : texelFetch(idMap, siteTexel(site), 0).r, 0.0, 0.0, 1.0);
}
`;
