import labelId from './labelId.glsl';

/** After a flood: each texel's site id, looked up in the id map at its label's site texel. */
export default /* glsl */ `
${labelId}
out vec4 id;

void main() {
  id = vec4(labelIdAt(ivec2(gl_FragCoord.xy)), 0.0, 0.0, 1.0);
}
`;
