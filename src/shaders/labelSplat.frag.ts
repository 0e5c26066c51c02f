/** Writes the splatted site's position (the label) into the label target. */
export default /* glsl */ `
precision highp float;
flat in vec3 siteLabel;
out vec4 label;
void main() {
  label = vec4(siteLabel.xy, 0.0, 1.0);
}
`;
