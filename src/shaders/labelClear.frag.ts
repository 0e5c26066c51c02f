/** Marks every texel as belonging to no site (id -1) before a cold jump flood. */
export default /* glsl */ `
precision highp float;
out vec4 label;
void main() {
  label = vec4(0.0, 0.0, -1.0, 0.0);
}
`;
