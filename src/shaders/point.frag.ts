/**
 * The fragment of every point pass (splat, centroid scatter): writes the value its vertex
 * computed. Flat, so a label's coordinates and id arrive bit for bit.
 */
export default /* glsl */ `
precision highp float;
flat in vec4 value;
out vec4 color;
void main() {
  color = value;
}
`;
