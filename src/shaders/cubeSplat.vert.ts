import cubeMetric from './cubeMetric.glsl';

/**
 * Splat on a cube map: one point per site (gl_VertexID = site id), drawn at the atlas texel the
 * site lies in (sites.w, computed on the CPU from the site's parameter direction), carrying its
 * id. Pairs with splat.frag.
 */
export default /* glsl */ `
precision highp float;
precision highp int;
${cubeMetric}
flat out float siteId;
void main() {
  int index = int(siteAt(gl_VertexID).w);
  vec2 texel = vec2(float(index % faceSize), float(index / faceSize)) + 0.5;
  vec2 size = vec2(float(faceSize), float(6 * faceSize));
  siteId = float(gl_VertexID);
  gl_Position = vec4(texel / size * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = 1.0;
}
`;
