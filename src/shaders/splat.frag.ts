/** Writes the splatted site's id into the label target. */
export default /* glsl */ `
precision highp float;
flat in float siteId;
out vec4 label;
void main() {
  label = vec4(siteId, 0.0, 0.0, 1.0);
}
`;
