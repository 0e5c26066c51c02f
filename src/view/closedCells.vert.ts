/**
 * Closed surfaces in the 3D view (three.js ShaderMaterial): passes the object-space point and
 * normal on, and the vertex's candidate cells (closedCandidates.ts) as a flat varying, which
 * every fragment of a triangle takes from the triangle's last (provoking) vertex.
 */
export default /* glsl */ `
#include <clipping_planes_pars_vertex>
attribute vec4 candidates;
flat varying vec4 vCandidates;
varying vec3 vPoint;
varying vec3 vNormal;

void main() {
  vCandidates = candidates;
  vPoint = position;
  vNormal = normal;
  vec4 mvPosition = modelViewMatrix * vec4(position, 1.0);
  gl_Position = projectionMatrix * mvPosition;
  #include <clipping_planes_vertex>
}
`;
