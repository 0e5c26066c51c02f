/**
 * A tissue surface as a triangle mesh, from the classified volume: the boundary of a mask (the
 * lumen; or everything but the outside) extracted by surface nets, then Taubin-smoothed.
 *
 * - The mask is first averaged over blocks of about `spacing` µm along every axis (so
 *   anisotropic voxels give a mesh of even resolution, and the mesh has the size the model runs
 *   on instead of one vertex per voxel face: the simplification is the averaging).
 * - Surface nets (Gibson 1998): one vertex per block cube whose corners straddle 1/2, at the
 *   mean of the points where its edges cross 1/2 (linear interpolation); one quad (two
 *   triangles) per block edge that crosses 1/2, joining the four cubes around it. A ring of
 *   empty blocks around the volume closes the surface.
 * - Taubin smoothing (lambda 0.5, mu -0.53, 10 rounds over the mesh edges) removes the
 *   blocks' terraces without shrinking the surface.
 * Triangles are oriented with their normals leaving the mask.
 */
import { signedVolume } from '../../mesh/types';

export interface SurfaceMesh {
  /** x, y, z per vertex, µm from the volume's corner. */
  readonly positions: Float64Array;
  readonly indices: Uint32Array;
  /** The block size used, in voxels per axis. */
  readonly blocks: [number, number, number];
}

export function maskSurfaceMesh(
  classes: Uint8Array,
  width: number,
  height: number,
  depth: number,
  voxel: { x: number; y: number; z: number },
  inMask: (cls: number) => boolean,
  spacing: number,
): SurfaceMesh {
  const bx = Math.max(1, Math.round(spacing / voxel.x));
  const by = Math.max(1, Math.round(spacing / voxel.y));
  const bz = Math.max(1, Math.round(spacing / voxel.z));
  // Block grid with one empty block all round.
  const cw = Math.ceil(width / bx) + 2;
  const ch = Math.ceil(height / by) + 2;
  const cd = Math.ceil(depth / bz) + 2;
  const field = new Float32Array(cw * ch * cd);
  const counts = new Float32Array(cw * ch * cd);
  const inside = new Uint8Array(256);
  for (let c = 0; c < 256; c++) inside[c] = inMask(c) ? 1 : 0;
  for (let z = 0; z < depth; z++) {
    const gz = Math.floor(z / bz) + 1;
    for (let y = 0; y < height; y++) {
      const gy = Math.floor(y / by) + 1;
      const row = (z * height + y) * width;
      const grow = (gz * ch + gy) * cw + 1;
      for (let x = 0; x < width; x++) {
        const g = grow + Math.floor(x / bx);
        field[g] += inside[classes[row + x]];
        counts[g]++;
      }
    }
  }
  for (let g = 0; g < field.length; g++) if (counts[g] > 0) field[g] /= counts[g];
  // Block centre positions (µm); the padding blocks continue the lattice.
  const px = (i: number) => ((i - 1) * bx + bx / 2) * voxel.x;
  const py = (j: number) => ((j - 1) * by + by / 2) * voxel.y;
  const pz = (k: number) => ((k - 1) * bz + bz / 2) * voxel.z;

  // One vertex per straddling cube (cube (i, j, k) has corners i..i+1, j..j+1, k..k+1).
  const vertexOf = new Int32Array(cw * ch * cd).fill(-1);
  const positions: number[] = [];
  const at = (i: number, j: number, k: number) => (k * ch + j) * cw + i;
  const corner = [
    [0, 0, 0],
    [1, 0, 0],
    [0, 1, 0],
    [1, 1, 0],
    [0, 0, 1],
    [1, 0, 1],
    [0, 1, 1],
    [1, 1, 1],
  ];
  const cubeEdges = [
    [0, 1],
    [2, 3],
    [4, 5],
    [6, 7],
    [0, 2],
    [1, 3],
    [4, 6],
    [5, 7],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
  ];
  const values = new Float64Array(8);
  for (let k = 0; k < cd - 1; k++) {
    for (let j = 0; j < ch - 1; j++) {
      for (let i = 0; i < cw - 1; i++) {
        let above = 0;
        for (let c = 0; c < 8; c++) {
          values[c] = field[at(i + corner[c][0], j + corner[c][1], k + corner[c][2])];
          if (values[c] > 0.5) above++;
        }
        if (above === 0 || above === 8) continue;
        let sx = 0;
        let sy = 0;
        let sz = 0;
        let n = 0;
        for (const [a, b] of cubeEdges) {
          if (values[a] > 0.5 === values[b] > 0.5) continue;
          const t = (0.5 - values[a]) / (values[b] - values[a]);
          sx += px(i + corner[a][0] + t * (corner[b][0] - corner[a][0]));
          sy += py(j + corner[a][1] + t * (corner[b][1] - corner[a][1]));
          sz += pz(k + corner[a][2] + t * (corner[b][2] - corner[a][2]));
          n++;
        }
        vertexOf[at(i, j, k)] = positions.length / 3;
        positions.push(sx / n, sy / n, sz / n);
      }
    }
  }
  // One quad per crossing block edge, between the four cubes around it.
  const indices: number[] = [];
  const quad = (a: number, b: number, c: number, d: number, flip: boolean) => {
    if (a < 0 || b < 0 || c < 0 || d < 0) return;
    if (flip) indices.push(a, c, b, a, d, c);
    else indices.push(a, b, c, a, c, d);
  };
  for (let k = 0; k < cd - 1; k++) {
    for (let j = 0; j < ch - 1; j++) {
      for (let i = 0; i < cw - 1; i++) {
        const v = field[at(i, j, k)] > 0.5;
        // Edge along x to (i+1, j, k): cubes (i, j-1..j, k-1..k). Edges in the empty ring never cross.
        if (j > 0 && k > 0 && v !== field[at(i + 1, j, k)] > 0.5)
          quad(vertexOf[at(i, j - 1, k - 1)], vertexOf[at(i, j, k - 1)], vertexOf[at(i, j, k)], vertexOf[at(i, j - 1, k)], !v);
        if (i > 0 && k > 0 && v !== field[at(i, j + 1, k)] > 0.5)
          quad(vertexOf[at(i - 1, j, k - 1)], vertexOf[at(i - 1, j, k)], vertexOf[at(i, j, k)], vertexOf[at(i, j, k - 1)], !v);
        if (i > 0 && j > 0 && v !== field[at(i, j, k + 1)] > 0.5)
          quad(vertexOf[at(i - 1, j - 1, k)], vertexOf[at(i, j - 1, k)], vertexOf[at(i, j, k)], vertexOf[at(i - 1, j, k)], !v);
      }
    }
  }
  const mesh = { positions: Float64Array.from(positions), indices: Uint32Array.from(indices), blocks: [bx, by, bz] as [number, number, number] };
  taubin(mesh.positions, mesh.indices, 10);
  if (signedVolume(mesh) < 0) {
    for (let t = 0; t < mesh.indices.length; t += 3) [mesh.indices[t + 1], mesh.indices[t + 2]] = [mesh.indices[t + 2], mesh.indices[t + 1]];
  }
  return mesh;
}

/** Taubin's lambda|mu smoothing with uniform weights over the mesh edges. */
function taubin(p: Float64Array, t: Uint32Array, rounds: number): void {
  const n = p.length / 3;
  const neighbours: Set<number>[] = Array.from({ length: n }, () => new Set());
  for (let f = 0; f < t.length; f += 3) {
    for (let e = 0; e < 3; e++) {
      const a = t[f + e];
      const b = t[f + ((e + 1) % 3)];
      neighbours[a].add(b);
      neighbours[b].add(a);
    }
  }
  const lists = neighbours.map((s) => Int32Array.from(s));
  const next = new Float64Array(p.length);
  for (let r = 0; r < 2 * rounds; r++) {
    const factor = r % 2 === 0 ? 0.5 : -0.53;
    for (let v = 0; v < n; v++) {
      const list = lists[v];
      for (let c = 0; c < 3; c++) {
        if (list.length === 0) {
          next[3 * v + c] = p[3 * v + c];
          continue;
        }
        let mean = 0;
        for (const u of list) mean += p[3 * u + c];
        mean /= list.length;
        next[3 * v + c] = p[3 * v + c] + factor * (mean - p[3 * v + c]);
      }
    }
    p.set(next);
  }
}
