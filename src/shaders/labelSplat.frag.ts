/** Writes the splatted site's label (position, id) into the label target. */
export default /* glsl */ `
precision highp float;
flat in vec3 siteLabel;
out vec4 label;
void main() {
  label = vec4(siteLabel, 1.0);
}
`;
