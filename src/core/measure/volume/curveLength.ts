/**
 * Length of a contact curve given as voxel edges (a staircase on the voxel surface), in µm.
 *
 * The edges form a graph over voxel corners. Every vertex with exactly two edges is smoothed
 * (Jacobi steps x <- x/2 + (x_prev + x_next)/4), the others (curve ends at triple junctions,
 * branch points) stay fixed; the curve's length is the sum of its smoothed edge lengths. A
 * staircase's zig-zag has a period of a few edges; a period of p edges is damped by
 * (1 + cos(2 pi / p)) / 2 per step (period 2 at once, 4 by half, 6 by a quarter), so after
 * SMOOTHING_STEPS the path follows the curve the staircase digitizes, and its length is the
 * curve's own, not the staircase's (up to √3 times longer in 3D). The steps spread about 4
 * edges, so a curve's bends on the scale of a cell stay. A closed loop (a cell enclosed by one
 * other on the surface) has no fixed end and would shrink: its round shape's known decay is
 * undone. Coordinates are in µm, so anisotropic voxels weigh their edges.
 */
import { disjointSets } from './disjointSets';

const SMOOTHING_STEPS = 30;

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
  const original = new Float64Array(xyz);
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
  // Pieces, and the closed loops among them (every vertex with two edges: nothing held fixed).
  const root = pieceRoots(n, ends, m);
  let pieces = 0;
  const vertices = new Map<number, number>();
  const open = new Set<number>();
  for (let v = 0; v < n; v++) {
    if (root[v] === v) pieces++;
    vertices.set(root[v], (vertices.get(root[v]) ?? 0) + 1);
    if (degree[v] !== 2) open.add(root[v]);
  }
  // A loop of k vertices shrinks under the steps: its round (fundamental) shape by
  // (1 - (1 - cos(2 pi / k)) / 2) per step, which is undone; its zig-zag decays far faster.
  // Loops under 8 vertices (a voxel's size) are noise: their staircase is kept.
  let length = 0;
  for (let e = 0; e < m; e++) {
    const r = root[ends[2 * e]];
    const k = vertices.get(r)!;
    const loop = !open.has(r);
    const p = 3 * ends[2 * e];
    const q = 3 * ends[2 * e + 1];
    const smoothed = Math.hypot(xyz[p] - xyz[q], xyz[p + 1] - xyz[q + 1], xyz[p + 2] - xyz[q + 2]);
    if (!loop) length += smoothed;
    else if (k < 8) length += Math.hypot(original[p] - original[q], original[p + 1] - original[q + 1], original[p + 2] - original[q + 2]);
    else length += smoothed / Math.pow(1 - (1 - Math.cos((2 * Math.PI) / k)) / 2, SMOOTHING_STEPS);
  }
  return { length, staircase, edges: m, pieces };
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

/** The root vertex of each vertex's connected piece. */
function pieceRoots(n: number, ends: Int32Array, m: number): Int32Array {
  const { parent, find } = disjointSets(n);
  for (let k = 0; k < m; k++) {
    const a = find(ends[2 * k]);
    const b = find(ends[2 * k + 1]);
    if (a !== b) parent[a] = b;
  }
  for (let i = 0; i < n; i++) parent[i] = find(i);
  return parent;
}
