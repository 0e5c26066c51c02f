/** Writes the splatted site's id into the id map. */
export default /* glsl */ `
precision highp float;
flat in vec3 siteLabel;
out vec4 id;
void main() {
  id = vec4(siteLabel.z, 0.0, 0.0, 1.0);
}
`;
