/**
 * Closed surfaces (sphere, ellipsoid, mesh) for the 3D view and the PLY export: a triangle mesh
 * of every surface of the stack, each vertex labelled with the cell of the nearest site on that
 * surface. Nearest site in 3D is exactly the engine's labelling (its Voronoi on a closed surface
 * uses the 3D Euclidean distance between a surface point and the sites, see
 * docs/closed-surfaces.md), so the view shows the engine's cells, only sampled at the vertices.
 *
 * - sphere: an icosphere of radius R + offset; ellipsoid: the icosphere mapped onto the
 *   ellipsoid and moved `offset` along its normals (an offset ellipsoid is not an ellipsoid);
 * - mesh: the mesh file itself (parseMesh, scaled, oriented outward, subdivided once when small,
 *   for finer colouring) moved `offset` along its vertex normals.
 * Pure data (no three.js, no DOM).
 */
import type { AnyConfig } from '../../core/config';
import { flipOrientation, icosphere } from '../../core/mesh/generate';
import { parseMesh } from '../../core/mesh/parse';
import { meanEdgeLength, signedVolume, vertexNormals, type TriangleMesh } from '../../core/mesh/types';
import type { ViewStack, ViewSurface } from '../model/stack';

/** A surface as triangles, outward normals, and the cell of every vertex. */
export interface ClosedSurfaceMesh {
  positions: Float32Array;
  normals: Float32Array;
  indices: Uint32Array;
  /** Cell id of the nearest site on this surface, per vertex. */
  cells: Int32Array;
  /** 1 where a vertex sits on a cell boundary (a neighbour vertex belongs to a cell of lower id). */
  boundary: Uint8Array;
}

/** The seeded surface, before any offset: points and outward unit normals. */
export interface BaseSurface {
  mesh: TriangleMesh;
  normals: Float32Array;
}

const baseCache = new WeakMap<object, BaseSurface>();

/** Icosphere frequency for `cells` cells: about 60 vertices per cell, 10 f² + 2 vertices. */
function frequencyFor(cells: number): number {
  return Math.max(24, Math.min(64, Math.ceil(Math.sqrt(6 * cells))));
}

/** The seeded surface of a closed stack (cached per stack). */
export function baseSurface(stack: ViewStack): BaseSurface {
  const cached = baseCache.get(stack);
  if (cached) return cached;
  const config = stack.result.config as unknown as AnyConfig;
  const surface = config.surface;
  let base: BaseSurface;
  if (surface.kind === 'sphere' || surface.kind === 'ellipsoid') {
    const unit = icosphere(frequencyFor(config.cells));
    const [a, b, c] = surface.kind === 'sphere' ? [surface.radius, surface.radius, surface.radius] : [surface.a, surface.b, surface.c];
    const p = unit.positions;
    const positions = new Float32Array(p.length);
    const normals = new Float32Array(p.length);
    for (let i = 0; i < p.length; i += 3) {
      const x = a * p[i], y = b * p[i + 1], z = c * p[i + 2];
      positions[i] = x;
      positions[i + 1] = y;
      positions[i + 2] = z;
      const nx = x / (a * a), ny = y / (b * b), nz = z / (c * c);
      const l = Math.hypot(nx, ny, nz) || 1;
      normals[i] = nx / l;
      normals[i + 1] = ny / l;
      normals[i + 2] = nz / l;
    }
    base = { mesh: { positions, indices: unit.indices }, normals };
  } else if (surface.kind === 'mesh') {
    if (!stack.meshFile) throw new Error('the mesh file of this result is not available');
    let mesh = parseMesh(stack.meshFile.data, { fileName: stack.meshFile.name });
    if (surface.scale !== 1) {
      const p = mesh.positions.slice();
      for (let k = 0; k < p.length; k++) p[k] *= surface.scale;
      mesh = { positions: p, indices: mesh.indices };
    }
    if (signedVolume(mesh) < 0) mesh = flipOrientation(mesh);
    // Normals of the mesh itself (the engine offsets along them), then a finer copy for colour.
    let normals = vertexNormals(mesh);
    while (mesh.indices.length / 3 < 20_000) ({ mesh, normals } = subdivide(mesh, normals));
    base = { mesh, normals };
  } else {
    throw new Error(`not a closed surface: ${surface.kind}`);
  }
  baseCache.set(stack, base);
  return base;
}

/** Midpoint subdivision (each triangle into 4); new normals interpolated and normalised. */
function subdivide(mesh: TriangleMesh, normals: Float32Array): BaseSurface {
  const p = Array.from(mesh.positions);
  const n = Array.from(normals);
  const t = mesh.indices;
  const mid = new Map<number, number>();
  const nv = mesh.positions.length / 3;
  const midpoint = (i: number, j: number) => {
    const key = i < j ? i * nv + j : j * nv + i;
    let m = mid.get(key);
    if (m === undefined) {
      m = p.length / 3;
      for (let k = 0; k < 3; k++) p.push((p[3 * i + k] + p[3 * j + k]) / 2);
      const nx = n[3 * i] + n[3 * j], ny = n[3 * i + 1] + n[3 * j + 1], nz = n[3 * i + 2] + n[3 * j + 2];
      const l = Math.hypot(nx, ny, nz) || 1;
      n.push(nx / l, ny / l, nz / l);
      mid.set(key, m);
    }
    return m;
  };
  const out: number[] = [];
  for (let f = 0; f < t.length; f += 3) {
    const a = t[f], b = t[f + 1], c = t[f + 2];
    const ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
    out.push(a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca);
  }
  return { mesh: { positions: new Float32Array(p), indices: new Uint32Array(out) }, normals: new Float32Array(n) };
}

/** The surface `surface` of the stack, offset and labelled by nearest site. */
export function closedSurfaceMesh(stack: ViewStack, surface: ViewSurface): ClosedSurfaceMesh {
  const base = baseSurface(stack);
  const p = base.mesh.positions;
  const nrm = base.normals;
  const t = surface.offset;
  const positions = new Float32Array(p.length);
  for (let i = 0; i < p.length; i++) positions[i] = p[i] + t * nrm[i];
  const sites = new Float64Array(surface.cells.length * 3);
  surface.cells.forEach((cell, i) => sites.set(cell.position, 3 * i));
  const cells = nearestSites(positions, sites);
  const indices = base.mesh.indices;
  const boundary = new Uint8Array(cells.length);
  for (let f = 0; f < indices.length; f += 3) {
    for (let k = 0; k < 3; k++) {
      const i = indices[f + k], j = indices[f + ((k + 1) % 3)];
      if (cells[i] < cells[j]) boundary[i] = 1;
      else if (cells[j] < cells[i]) boundary[j] = 1;
    }
  }
  return { positions, normals: nrm, indices, cells, boundary };
}

/** A length scale of the surface's triangles (for stripes). */
export function edgeLength(stack: ViewStack): number {
  return meanEdgeLength(baseSurface(stack).mesh);
}

/**
 * Nearest site (Euclidean, 3D) of every point: a uniform grid of buckets over the sites,
 * searched in growing shells until no unsearched bucket can hold a closer site. Exact.
 */
export function nearestSites(points: ArrayLike<number>, sites: Float64Array): Int32Array {
  const count = sites.length / 3;
  const out = new Int32Array(points.length / 3).fill(-1);
  if (count === 0) return out;
  const min = [Infinity, Infinity, Infinity];
  const max = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < sites.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      min[k] = Math.min(min[k], sites[i + k]);
      max[k] = Math.max(max[k], sites[i + k]);
    }
  }
  const extent = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2], 1e-9);
  // About 2 sites per bucket on a surface: buckets a little larger than the site spacing.
  const size = Math.max(extent / 64, extent / Math.sqrt(count / 2));
  const dims = [0, 1, 2].map((k) => Math.max(1, Math.floor((max[k] - min[k]) / size) + 1));
  const buckets = new Map<number, number[]>();
  const key = (x: number, y: number, z: number) => (z * dims[1] + y) * dims[0] + x;
  const cellOf = (v: number, k: number) => Math.max(0, Math.min(dims[k] - 1, Math.floor((v - min[k]) / size)));
  for (let s = 0; s < count; s++) {
    const k = key(cellOf(sites[3 * s], 0), cellOf(sites[3 * s + 1], 1), cellOf(sites[3 * s + 2], 2));
    let list = buckets.get(k);
    if (!list) buckets.set(k, (list = []));
    list.push(s);
  }
  const maxShell = Math.max(dims[0], dims[1], dims[2]);
  for (let v = 0; v < out.length; v++) {
    const x = points[3 * v], y = points[3 * v + 1], z = points[3 * v + 2];
    const cx = Math.floor((x - min[0]) / size), cy = Math.floor((y - min[1]) / size), cz = Math.floor((z - min[2]) / size);
    let best = -1;
    let bestD = Infinity;
    for (let r = 0; r <= maxShell + Math.max(Math.abs(cx), Math.abs(cy), Math.abs(cz)); r++) {
      for (let dz = -r; dz <= r; dz++) {
        const bz = cz + dz;
        if (bz < 0 || bz >= dims[2]) continue;
        for (let dy = -r; dy <= r; dy++) {
          const by = cy + dy;
          if (by < 0 || by >= dims[1]) continue;
          for (let dx = -r; dx <= r; dx++) {
            if (Math.max(Math.abs(dx), Math.abs(dy), Math.abs(dz)) !== r) continue; // the shell only
            const bx = cx + dx;
            if (bx < 0 || bx >= dims[0]) continue;
            const list = buckets.get(key(bx, by, bz));
            if (!list) continue;
            for (const s of list) {
              const ex = sites[3 * s] - x, ey = sites[3 * s + 1] - y, ez = sites[3 * s + 2] - z;
              const d = ex * ex + ey * ey + ez * ez;
              if (d < bestD || (d === bestD && s < best)) {
                bestD = d;
                best = s;
              }
            }
          }
        }
      }
      // Buckets beyond shell r are farther than r * size from the point's bucket.
      if (best >= 0 && Math.sqrt(bestD) <= r * size) break;
    }
    out[v] = best;
  }
  return out;
}
