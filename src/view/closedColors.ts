/**
 * Vertex colours of a closed surface's mesh (cubeAtlasMesh.ts): each vertex in the side colour of
 * its texel's cell, the picked cell white, scutoids striped, boundaries darkened, and a fixed
 * light baked in that leaves the lit side exactly in the legend's colours.
 */
import * as THREE from 'three';
import type { closedSurfaceMesh } from './cubeAtlasMesh';
import { RGB, SELECTED_RGB, sideColorIndex } from './sideColors';

/** A fixed light (world space, from the default camera's side) baked into closed surfaces' colours. */
const LIGHT = new THREE.Vector3(0.35, 0.6, 0.75).normalize();
/**
 * Shading of closed surfaces: 1 (the legend's colour exactly) wherever the surface faces the
 * light by at least LIT_FROM (n·l), darker only towards the back, down to SHADE_MIN at n·l = -1,
 * so the shape reads without changing the colours a reader matches to the legend.
 */
const LIT_FROM = 0.2;
const SHADE_MIN = 0.7;

/** RGB (linear, 0..1) per vertex of `built`. */
export function closedVertexColors(
  built: ReturnType<typeof closedSurfaceMesh>,
  sides: ArrayLike<number>,
  scutoid: ArrayLike<number>,
  selected: number,
  highlight: boolean,
): Float32Array {
  const { positions, normals, cells, boundary } = built;
  const colors = new Float32Array(positions.length);
  const period = Math.max(1e-6, 3 * built.edgeLength);
  const color = new THREE.Color();
  for (let v = 0; v < cells.length; v++) {
    const id = cells[v];
    let [r, g, b] = id >= 0 ? RGB[sideColorIndex(sides[id] ?? 0)] : [40, 40, 40];
    const x = positions[3 * v], y = positions[3 * v + 1], z = positions[3 * v + 2];
    if (id >= 0 && id === selected) [r, g, b] = SELECTED_RGB;
    else if (highlight && id >= 0 && scutoid[id]) {
      const phase = (x + y + z) / period;
      if (phase - Math.floor(phase) < 0.4) r = g = b = 20;
    }
    if (boundary[v]) {
      r *= 0.25;
      g *= 0.25;
      b *= 0.25;
    }
    const facing = normals[3 * v] * LIGHT.x + normals[3 * v + 1] * LIGHT.y + normals[3 * v + 2] * LIGHT.z;
    const light = facing >= LIT_FROM ? 1 : SHADE_MIN + ((1 - SHADE_MIN) * (facing + 1)) / (LIT_FROM + 1);
    color.setRGB((r / 255) * light, (g / 255) * light, (b / 255) * light, THREE.SRGBColorSpace);
    colors[3 * v] = color.r;
    colors[3 * v + 1] = color.g;
    colors[3 * v + 2] = color.b;
  }
  return colors;
}
