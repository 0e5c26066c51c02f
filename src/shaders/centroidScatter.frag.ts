/** Passes the texel's contribution on to the additive blend. */
export default /* glsl */ `
precision highp float;
in vec4 contribution;
out vec4 sums;
void main() {
  sums = contribution;
}
`;
