/**
 * Length of a contact curve given as voxel edges (a staircase on the voxel surface), in µm.
 *
 * The edges form a graph over voxel corners. Every vertex with exactly two edges is smoothed
 * (Jacobi steps x <- x/2 + (x_prev + x_next)/4), the others (curve ends at triple junctions,
 * branch points) stay fixed; the curve's length is the sum of its smoothed edge lengths. A
 * staircase's zig-zag has a period of a few edges, which these steps damp by a factor of 2 to
 * 4 each (its period-2 part at once), so the smoothed path follows the curve the staircase
 * digitizes, and its length is the curve's own, not the staircase's (up to √3 times longer in
 * 3D). The steps are few enough (SMOOTHING_STEPS; spread about 4 edges) that a curve's bends on
 * the scale of a cell stay. Coordinates are in µm, so anisotropic voxels weigh their edges.
 */

export const SMOOTHING_STEPS = 30;

export interface CurveLength {
  /** Smoothed length, µm. */
  readonly length: number;
  /** Sum of the voxel-edge lengths (the staircase), µm. */
  readonly staircase: number;
  readonly edges: number;
  /** Connected pieces of the curve. */
  readonly pieces: number;
}

/**
 * @param v0,v1 end vertices of each edge (vertex ids, see contactEdges.ts)
 * @param list indices of this curve's edges in v0/v1
 * @param position writes vertex id's position in µm into out[o..o+2]
 */
export function curveLength(
  v0: ArrayLike<number>,
  v1: ArrayLike<number>,
  list: ArrayLike<number>,
  position: (vertex: number, out: Float64Array, o: number) => void,
): CurveLength {
  const m = list.length;
  const local = new Map<number, number>();
  const ends = new Int32Array(2 * m);
  for (let k = 0; k < m; k++) {
    const e = list[k];
    for (let s = 0; s < 2; s++) {
      const v = s === 0 ? v0[e] : v1[e];
      let id = local.get(v);
      if (id === undefined) {
        id = local.size;
        local.set(v, id);
      }
      ends[2 * k + s] = id;
    }
  }
  const n = local.size;
  let xyz = new Float64Array(3 * n);
  for (const [v, id] of local) position(v, xyz, 3 * id);
  const degree = new Int32Array(n);
  const nb = new Int32Array(2 * n).fill(-1);
  for (let k = 0; k < m; k++) {
    const p = ends[2 * k];
    const q = ends[2 * k + 1];
    if (degree[p] < 2) nb[2 * p + degree[p]] = q;
    if (degree[q] < 2) nb[2 * q + degree[q]] = p;
    degree[p]++;
    degree[q]++;
  }
  const staircase = sumLengths(xyz, ends, m);
  let next = new Float64Array(xyz);
  for (let step = 0; step < SMOOTHING_STEPS; step++) {
    for (let v = 0; v < n; v++) {
      if (degree[v] !== 2) continue;
      const p = 3 * nb[2 * v];
      const q = 3 * nb[2 * v + 1];
      const o = 3 * v;
      next[o] = 0.5 * xyz[o] + 0.25 * (xyz[p] + xyz[q]);
      next[o + 1] = 0.5 * xyz[o + 1] + 0.25 * (xyz[p + 1] + xyz[q + 1]);
      next[o + 2] = 0.5 * xyz[o + 2] + 0.25 * (xyz[p + 2] + xyz[q + 2]);
    }
    const t = xyz;
    xyz = next;
    next = t;
  }
  return { length: sumLengths(xyz, ends, m), staircase, edges: m, pieces: countPieces(n, ends, m) };
}

function sumLengths(xyz: Float64Array, ends: Int32Array, m: number): number {
  let total = 0;
  for (let k = 0; k < m; k++) {
    const p = 3 * ends[2 * k];
    const q = 3 * ends[2 * k + 1];
    total += Math.hypot(xyz[p] - xyz[q], xyz[p + 1] - xyz[q + 1], xyz[p + 2] - xyz[q + 2]);
  }
  return total;
}

function countPieces(n: number, ends: Int32Array, m: number): number {
  const parent = new Int32Array(n);
  for (let i = 0; i < n; i++) parent[i] = i;
  const find = (i: number): number => {
    while (parent[i] !== i) {
      parent[i] = parent[parent[i]];
      i = parent[i];
    }
    return i;
  };
  let pieces = n;
  for (let k = 0; k < m; k++) {
    const a = find(ends[2 * k]);
    const b = find(ends[2 * k + 1]);
    if (a !== b) {
      parent[a] = b;
      pieces--;
    }
  }
  return pieces;
}
