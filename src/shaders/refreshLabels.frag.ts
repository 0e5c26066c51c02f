import labelId from './labelId.glsl';

/**
 * Warm start: the previous iteration's labels hold the sites' previous positions. Each is
 * mapped to its site's id through the previous id map, and replaced by that site's current
 * position from the site texture.
 */
export default /* glsl */ `
${labelId}
out vec4 label;

void main() {
  float id = labelIdAt(ivec2(gl_FragCoord.xy));
  label = id < 0.0 ? vec4(-1.0, -1.0, 0.0, 0.0) : vec4(siteAt(int(id)), 0.0, 1.0);
}
`;
