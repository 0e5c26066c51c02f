/**
 * The contact curves of cells on the outside and lumen surfaces, as voxel edges.
 *
 * A surface (outside or lumen) is the set of voxel faces between a cell voxel and a voxel of
 * that background class. Around each voxel edge lie four voxels (in cyclic order); the
 * surface passes the edge once per maximal run of that class in the cycle, and the two faces
 * bounding a run are adjacent on the surface. When both voxels bounding a run are cells with
 * different ids a, b, the edge is on the curve where a and b meet on that surface: a contact
 * edge of (a, b). Edges on the volume's faces (fewer than four voxels around them) are skipped.
 *
 * Edges are returned with their two end vertices: vertex (X, Y, Z), the corner shared by
 * voxels X-1..X, Y-1..Y, Z-1..Z, has id (Z * (H + 1) + Y) * (W + 1) + X.
 */
import { CELL, LUMEN, OUTSIDE } from './voxelClasses';
import type { VolumeArray } from './tiffVolume';

export interface ContactEdges {
  count: number;
  /** OUTSIDE or LUMEN per edge. */
  surface: Uint8Array;
  /** Dense ids a < b per edge. */
  a: Int32Array;
  b: Int32Array;
  v0: Float64Array;
  v1: Float64Array;
}

function grow(edges: ContactEdges): void {
  const size = edges.surface.length * 2;
  const copy = <T extends Uint8Array | Int32Array | Float64Array>(old: T, make: (n: number) => T): T => {
    const next = make(size);
    next.set(old);
    return next;
  };
  edges.surface = copy(edges.surface, (n) => new Uint8Array(n));
  edges.a = copy(edges.a, (n) => new Int32Array(n));
  edges.b = copy(edges.b, (n) => new Int32Array(n));
  edges.v0 = copy(edges.v0, (n) => new Float64Array(n));
  edges.v1 = copy(edges.v1, (n) => new Float64Array(n));
}

export function scanContactEdges(ids: VolumeArray, classes: Uint8Array, width: number, height: number, depth: number): ContactEdges {
  const W = width;
  const H = height;
  const plane = W * H;
  const VX = W + 1;
  const VXY = (W + 1) * (H + 1);
  const initial = 1 << 12;
  const edges: ContactEdges = {
    count: 0,
    surface: new Uint8Array(initial),
    a: new Int32Array(initial),
    b: new Int32Array(initial),
    v0: new Float64Array(initial),
    v1: new Float64Array(initial),
  };
  const cls = new Uint8Array(4);
  const id = new Int32Array(4);

  /** The four voxels q0..q3 (cyclic) around an edge from vertex u to vertex v. */
  const edge = (q0: number, q1: number, q2: number, q3: number, u: number, v: number) => {
    cls[0] = classes[q0];
    cls[1] = classes[q1];
    cls[2] = classes[q2];
    cls[3] = classes[q3];
    id[0] = ids[q0];
    id[1] = ids[q1];
    id[2] = ids[q2];
    id[3] = ids[q3];
    for (let s = OUTSIDE; s <= LUMEN; s++) {
      // Each maximal run of class s: the voxels just before and after it.
      for (let k = 0; k < 4; k++) {
        if (cls[k] !== s || cls[(k + 3) & 3] === s) continue; // not the start of a run
        let e = k;
        while (cls[(e + 1) & 3] === s) e = (e + 1) & 3;
        const before = (k + 3) & 3;
        const after = (e + 1) & 3;
        if (cls[before] !== CELL || cls[after] !== CELL || id[before] === id[after]) continue;
        const a = Math.min(id[before], id[after]);
        const b = Math.max(id[before], id[after]);
        // Two runs of s around one edge (a checkerboard) bound the same two cells: one edge.
        const n = edges.count;
        if (n > 0 && edges.v0[n - 1] === u && edges.v1[n - 1] === v && edges.surface[n - 1] === s && edges.a[n - 1] === a && edges.b[n - 1] === b) continue;
        if (n === edges.surface.length) grow(edges);
        edges.surface[n] = s;
        edges.a[n] = a;
        edges.b[n] = b;
        edges.v0[n] = u;
        edges.v1[n] = v;
        edges.count = n + 1;
      }
    }
  };

  for (let z = 0; z < depth; z++) {
    for (let y = 0; y < H; y++) {
      const row = z * plane + y * W;
      for (let x = 0; x < W; x++) {
        const i = row + x;
        const c = classes[i];
        // Edge along z through corner (x+1, y+1): voxels i, i+1, i+1+W, i+W.
        if (x < W - 1 && y < H - 1) {
          const c1 = classes[i + 1],
            c2 = classes[i + 1 + W],
            c3 = classes[i + W];
          if (!(c === c1 && c === c2 && c === c3)) {
            const u = (z * (H + 1) + y + 1) * VX + x + 1;
            edge(i, i + 1, i + 1 + W, i + W, u, u + VXY);
          }
        }
        // Edge along x through corner (y+1, z+1): voxels i, i+W, i+W+plane, i+plane.
        if (y < H - 1 && z < depth - 1) {
          const c1 = classes[i + W],
            c2 = classes[i + W + plane],
            c3 = classes[i + plane];
          if (!(c === c1 && c === c2 && c === c3)) {
            const u = ((z + 1) * (H + 1) + y + 1) * VX + x;
            edge(i, i + W, i + W + plane, i + plane, u, u + 1);
          }
        }
        // Edge along y through corner (x+1, z+1): voxels i, i+1, i+1+plane, i+plane.
        if (x < W - 1 && z < depth - 1) {
          const c1 = classes[i + 1],
            c2 = classes[i + 1 + plane],
            c3 = classes[i + plane];
          if (!(c === c1 && c === c2 && c === c3)) {
            const u = ((z + 1) * (H + 1) + y) * VX + x + 1;
            edge(i, i + 1, i + 1 + plane, i + plane, u, u + VX);
          }
        }
      }
    }
  }
  return edges;
}
