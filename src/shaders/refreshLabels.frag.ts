/**
 * Warm start: the previous iteration's labels hold the sites' previous coordinates. Each is
 * replaced by its site's current coordinates from the site texture (the id stays).
 */
export default /* glsl */ `
uniform highp sampler2D labels;
out vec4 label;

void main() {
  float id = texelFetch(labels, ivec2(gl_FragCoord.xy), 0).w;
  label = id < 0.0 ? vec4(0.0, 0.0, 0.0, -1.0) : vec4(siteAt(int(id)).xyz, id);
}
`;
