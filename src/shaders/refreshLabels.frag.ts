import gridMetric from './gridMetric.glsl';

/**
 * Warm start: the previous iteration's labels keep their ids, but their copied site positions
 * are stale once the sites moved. Re-read every texel's site position from the site texture.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${gridMetric}
uniform highp sampler2D labels;
out vec4 label;

void main() {
  vec4 previous = texelFetch(labels, ivec2(gl_FragCoord.xy), 0);
  label = previous.z < 0.0 ? previous : vec4(siteAt(int(previous.z)), previous.z, 1.0);
}
`;
