/** Empties a label or id target (-1 everywhere: no site) before a cold flood or a new splat. */
export default /* glsl */ `
precision highp float;
out vec4 empty;
void main() {
  empty = vec4(-1.0, -1.0, -1.0, 0.0);
}
`;
