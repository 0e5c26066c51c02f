/**
 * What the page draws of a measured volume (docs/app.md, "Measure a volume"), built in the
 * measuring worker from the classified voxels (measureVolume's onVoxels); pure, no DOM, no GL.
 *
 * - A tissue surface (basal or apical) is the boundary of a mask (everything but the outside;
 *   or the lumen) as a smoothed triangle mesh: the same surface nets as the model's meshes
 *   (surfaceMesh.ts), at the finest block size that keeps it under `maxTriangles` (so a large
 *   volume stays drawable). Each triangle takes the cell of the nearest voxel that has a face on
 *   that surface (a cell voxel with a 6-neighbour of the surface's background class), searched a
 *   block and a voxel around the triangle's centre; triangles with none near (the caps where the
 *   volume cuts a tube open) are left out. Triangles are unshared (three vertices each) so that
 *   each is flat in its cell's colour.
 * - A picked cell's 3D shape: the boundary of its own voxels, at the voxel size.
 */
import { LUMEN, maskSurfaceMesh, OUTSIDE, type ClassifiedVolume } from '../core/measure';

/** A surface drawn as unshared triangles, each with the result's cell id (0-based) it belongs to. */
export interface DrawnSurface {
  readonly name: 'basal' | 'apical';
  readonly faces: 'outside' | 'lumen';
  /** x, y, z per vertex (three per triangle), µm from the volume's corner. */
  readonly positions: Float32Array;
  /** Cell id per triangle (the result's `cells[k].id`). */
  readonly cells: Int32Array;
  /** The block size the mesh was extracted at, µm. */
  readonly spacing: number;
}

/** A closed triangle mesh (indexed), µm from the volume's corner. */
export interface CellShape {
  readonly cell: number;
  readonly positions: Float32Array;
  readonly indices: Uint32Array;
}

const MAX_DRAWN_TRIANGLES = 300_000;

/**
 * The block size (µm) for drawing a surface of `area` µm² (measured as voxel faces): the
 * smallest voxel edge, or coarser where the mesh would pass `maxTriangles` (about two triangles
 * per block face).
 */
function drawingSpacing(area: number, voxel: { x: number; y: number; z: number }, maxTriangles = MAX_DRAWN_TRIANGLES): number {
  const finest = Math.min(voxel.x, voxel.y, voxel.z);
  return Math.max(finest, Math.sqrt((2 * area) / maxTriangles));
}

export function drawSurface(
  volume: ClassifiedVolume,
  name: 'basal' | 'apical',
  faces: 'outside' | 'lumen',
  area: number,
  maxTriangles = MAX_DRAWN_TRIANGLES,
): DrawnSurface {
  const { width: W, height: H, depth: D, voxelSize: v } = volume;
  const { classes, ids } = volume.classes;
  const background = faces === 'outside' ? OUTSIDE : LUMEN;
  const inMask = faces === 'outside' ? (c: number) => c !== OUTSIDE : (c: number) => c === LUMEN;
  let spacing = drawingSpacing(area, v, maxTriangles);
  let mesh = maskSurfaceMesh(classes, W, H, D, v, inMask, spacing);
  // The estimate from the area can fall short (folds, caps): coarser until the budget holds.
  for (let tries = 0; mesh.indices.length / 3 > maxTriangles && tries < 8; tries++) {
    spacing *= 1.1 * Math.sqrt(mesh.indices.length / 3 / maxTriangles);
    mesh = maskSurfaceMesh(classes, W, H, D, v, inMask, spacing);
  }
  const [bx, by, bz] = mesh.blocks;
  const rx = bx + 1;
  const ry = by + 1;
  const rz = bz + 1;
  const plane = W * H;
  /** A cell voxel with a face on the surface: a 6-neighbour inside the volume of its class. */
  const onSurface = (x: number, y: number, z: number, index: number): boolean =>
    (x > 0 && classes[index - 1] === background) ||
    (x < W - 1 && classes[index + 1] === background) ||
    (y > 0 && classes[index - W] === background) ||
    (y < H - 1 && classes[index + W] === background) ||
    (z > 0 && classes[index - plane] === background) ||
    (z < D - 1 && classes[index + plane] === background);
  const p = mesh.positions;
  const t = mesh.indices;
  const triangles = t.length / 3;
  const positions = new Float32Array(triangles * 9);
  const cells = new Int32Array(triangles);
  let kept = 0;
  for (let f = 0; f < triangles; f++) {
    const a = 3 * t[3 * f];
    const b = 3 * t[3 * f + 1];
    const c = 3 * t[3 * f + 2];
    const cx = (p[a] + p[b] + p[c]) / 3;
    const cy = (p[a + 1] + p[b + 1] + p[c + 1]) / 3;
    const cz = (p[a + 2] + p[b + 2] + p[c + 2]) / 3;
    // Voxel (i, j, k) has its centre at ((i + 0.5) v.x, ...).
    const i0 = Math.round(cx / v.x - 0.5);
    const j0 = Math.round(cy / v.y - 0.5);
    const k0 = Math.round(cz / v.z - 0.5);
    let best = -1;
    let bestDistance = Infinity;
    for (let k = Math.max(0, k0 - rz); k <= Math.min(D - 1, k0 + rz); k++) {
      const dz = ((k + 0.5) * v.z - cz) ** 2;
      for (let j = Math.max(0, j0 - ry); j <= Math.min(H - 1, j0 + ry); j++) {
        const dyz = dz + ((j + 0.5) * v.y - cy) ** 2;
        if (dyz >= bestDistance) continue;
        for (let i = Math.max(0, i0 - rx); i <= Math.min(W - 1, i0 + rx); i++) {
          const index = (k * H + j) * W + i;
          const id = ids[index];
          if (id === 0) continue;
          const d = dyz + ((i + 0.5) * v.x - cx) ** 2;
          if (d < bestDistance && onSurface(i, j, k, index)) {
            bestDistance = d;
            best = id - 1;
          }
        }
      }
    }
    if (best < 0) continue;
    for (let corner = 0; corner < 3; corner++) {
      const q = 3 * t[3 * f + corner];
      positions[9 * kept + 3 * corner] = p[q];
      positions[9 * kept + 3 * corner + 1] = p[q + 1];
      positions[9 * kept + 3 * corner + 2] = p[q + 2];
    }
    cells[kept++] = best;
  }
  return { name, faces, positions: positions.slice(0, 9 * kept), cells: cells.slice(0, kept), spacing };
}

/** The boundary of cell `cell`'s voxels (0-based result id), at the voxel size. */
export function cellShape(volume: ClassifiedVolume, cell: number): CellShape {
  const { width: W, height: H, depth: D, voxelSize: v } = volume;
  const { ids } = volume.classes;
  const id = cell + 1;
  let x0 = W,
    y0 = H,
    z0 = D,
    x1 = -1,
    y1 = -1,
    z1 = -1;
  for (let z = 0, index = 0; z < D; z++) {
    for (let y = 0; y < H; y++) {
      for (let x = 0; x < W; x++, index++) {
        if (ids[index] !== id) continue;
        if (x < x0) x0 = x;
        if (x > x1) x1 = x;
        if (y < y0) y0 = y;
        if (y > y1) y1 = y;
        if (z < z0) z0 = z;
        if (z > z1) z1 = z;
      }
    }
  }
  if (x1 < 0) return { cell, positions: new Float32Array(0), indices: new Uint32Array(0) };
  const w = x1 - x0 + 1;
  const h = y1 - y0 + 1;
  const d = z1 - z0 + 1;
  const mask = new Uint8Array(w * h * d);
  for (let z = 0; z < d; z++) {
    for (let y = 0; y < h; y++) {
      const row = ((z + z0) * H + y + y0) * W + x0;
      for (let x = 0; x < w; x++) if (ids[row + x] === id) mask[(z * h + y) * w + x] = 1;
    }
  }
  const mesh = maskSurfaceMesh(mask, w, h, d, v, (c) => c === 1, Math.min(v.x, v.y, v.z));
  const positions = new Float32Array(mesh.positions.length);
  for (let q = 0; q < positions.length; q += 3) {
    positions[q] = mesh.positions[q] + x0 * v.x;
    positions[q + 1] = mesh.positions[q + 1] + y0 * v.y;
    positions[q + 2] = mesh.positions[q + 2] + z0 * v.z;
  }
  return { cell, positions, indices: mesh.indices };
}
