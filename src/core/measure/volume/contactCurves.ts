/** Contact edges grouped into one curve per pair of cells on one surface, with their lengths in µm. */
import type { ContactEdges } from './contactEdges';
import { curveLength } from './curveLength';
import type { VoxelSize } from './voxelSize';

/** Contact curves on one surface: per pair key a * 2^26 + b of dense ids (1-based), their lengths. */
export type Curves = Map<number, { a: number; b: number; length: number; staircase: number; edges: number; pieces: number }>;

export function contactCurves(edges: ContactEdges, surface: number, W: number, H: number, size: VoxelSize): Curves {
  const groups = new Map<number, number[]>();
  for (let e = 0; e < edges.count; e++) {
    if (edges.surface[e] !== surface) continue;
    const key = edges.a[e] * 2 ** 26 + edges.b[e];
    let list = groups.get(key);
    if (!list) groups.set(key, (list = []));
    list.push(e);
  }
  const VX = W + 1;
  const VXY = (W + 1) * (H + 1);
  const position = (v: number, out: Float64Array, o: number) => {
    out[o] = (v % VX) * size.x;
    out[o + 1] = (Math.floor(v / VX) % (H + 1)) * size.y;
    out[o + 2] = Math.floor(v / VXY) * size.z;
  };
  const curves: Curves = new Map();
  for (const [key, list] of groups) {
    const c = curveLength(edges.v0, edges.v1, list, position);
    curves.set(key, { a: edges.a[list[0]], b: edges.b[list[0]], ...c });
  }
  return curves;
}
