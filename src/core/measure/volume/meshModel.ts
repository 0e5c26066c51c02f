/**
 * The Voronoi model on a tissue's own surface mesh (closed shells, `--compare`): sites placed at
 * random with a minimum spacing, Lloyd steps, the restricted Voronoi diagram (exact on the
 * mesh: src/core/closed), and sites carried along the surface normal to the other surface.
 *
 * Lloyd on the mesh is sampled: each triangle goes, whole, to the site nearest its centroid;
 * a site moves to the area-weighted mean of its triangles' centroids, put back on the mesh at
 * the closest point (three-mesh-bvh). With tens of triangles per cell this is the CVT step
 * up to the triangles' size.
 */
import { BufferAttribute, BufferGeometry, DoubleSide, Ray, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import type { SurfaceAdjacency } from '../../analysis';
import { KdTree3 } from '../../closed/kdTree';
import { restrictedVoronoi } from '../../closed/restrictedVoronoi';
import { triangleNeighbours } from '../../closed/restrictedSurface';
import { createRandom } from '../../random';
import type { SurfaceMesh } from './surfaceMesh';
import { triangleCross } from '../../mesh/types';

export interface PreparedMesh {
  readonly positions: Float64Array;
  readonly indices: Uint32Array;
  readonly neighbours: Int32Array;
  readonly centroids: Float64Array;
  readonly areas: Float64Array;
  /** Unit normal per triangle (leaving the mask the mesh bounds). */
  readonly normals: Float64Array;
  readonly area: number;
  readonly bvh: MeshBVH;
}

export function prepareMesh(mesh: SurfaceMesh): PreparedMesh {
  const p = mesh.positions;
  const t = mesh.indices;
  const nf = t.length / 3;
  const centroids = new Float64Array(3 * nf);
  const areas = new Float64Array(nf);
  const normals = new Float64Array(3 * nf);
  let area = 0;
  const cross = new Float64Array(3);
  for (let f = 0; f < nf; f++) {
    const [nx, ny, nz] = triangleCross(p, t, f, cross);
    const len = Math.hypot(nx, ny, nz);
    areas[f] = len / 2;
    area += len / 2;
    if (len > 0) normals.set([nx / len, ny / len, nz / len], 3 * f);
    for (let k = 0; k < 3; k++) centroids[3 * f + k] = (p[3 * t[3 * f] + k] + p[3 * t[3 * f + 1] + k] + p[3 * t[3 * f + 2] + k]) / 3;
  }
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(Float32Array.from(p), 3));
  g.setIndex(new BufferAttribute(Uint32Array.from(t), 1));
  // indirect: the BVH leaves the index order alone, so faceIndex is our triangle number.
  return {
    positions: p,
    indices: t,
    neighbours: triangleNeighbours(t, p.length / 3),
    centroids,
    areas,
    normals,
    area,
    bvh: new MeshBVH(g, { indirect: true }),
  };
}

const point = new Vector3();
const target = { point: new Vector3(), distance: 0, faceIndex: 0 };

/** Closest point of the mesh to (x, y, z) into out[o..o+2]; returns its triangle. */
function closestOnMesh(mesh: PreparedMesh, x: number, y: number, z: number, out: Float64Array, o: number): number {
  mesh.bvh.closestPointToPoint(point.set(x, y, z), target);
  out[o] = target.point.x;
  out[o + 1] = target.point.y;
  out[o + 2] = target.point.z;
  return target.faceIndex;
}

/** `count` random points on the mesh (uniform by area), no two closer than `minSpacing` (µm). */
export function randomSitesOnMesh(mesh: PreparedMesh, count: number, minSpacing: number, seed: number): Float64Array {
  const random = createRandom(seed);
  const nf = mesh.areas.length;
  const cumulative = new Float64Array(nf);
  let sum = 0;
  for (let f = 0; f < nf; f++) cumulative[f] = sum += mesh.areas[f];
  const sites = new Float64Array(3 * count);
  // Spatial hash of accepted sites, cells of minSpacing.
  const cell = Math.max(minSpacing, 1e-9);
  const grid = new Map<string, number[]>();
  const key = (x: number, y: number, z: number) => `${Math.floor(x / cell)},${Math.floor(y / cell)},${Math.floor(z / cell)}`;
  let n = 0;
  let spacing = minSpacing;
  for (let tries = 0; n < count; tries++) {
    if (tries > 0 && tries % (200 * count) === 0) spacing *= 0.9; // too dense for this spacing: relax it
    const r = random.next() * sum;
    let lo = 0;
    let hi = nf - 1;
    while (lo < hi) {
      const mid = (lo + hi) >> 1;
      if (cumulative[mid] < r) lo = mid + 1;
      else hi = mid;
    }
    const t = mesh.indices;
    const a = 3 * t[3 * lo],
      b = 3 * t[3 * lo + 1],
      c = 3 * t[3 * lo + 2];
    let u = random.next();
    let v = random.next();
    if (u + v > 1) {
      u = 1 - u;
      v = 1 - v;
    }
    const p = mesh.positions;
    const x = p[a] + u * (p[b] - p[a]) + v * (p[c] - p[a]);
    const y = p[a + 1] + u * (p[b + 1] - p[a + 1]) + v * (p[c + 1] - p[a + 1]);
    const z = p[a + 2] + u * (p[b + 2] - p[a + 2]) + v * (p[c + 2] - p[a + 2]);
    let ok = true;
    const gx = Math.floor(x / cell),
      gy = Math.floor(y / cell),
      gz = Math.floor(z / cell);
    for (let dz = -1; dz <= 1 && ok; dz++) {
      for (let dy = -1; dy <= 1 && ok; dy++) {
        for (let dx = -1; dx <= 1 && ok; dx++) {
          for (const s of grid.get(`${gx + dx},${gy + dy},${gz + dz}`) ?? []) {
            if ((sites[3 * s] - x) ** 2 + (sites[3 * s + 1] - y) ** 2 + (sites[3 * s + 2] - z) ** 2 < spacing * spacing) {
              ok = false;
              break;
            }
          }
        }
      }
    }
    if (!ok) continue;
    sites.set([x, y, z], 3 * n);
    const k = key(x, y, z);
    const list = grid.get(k);
    if (list) list.push(n);
    else grid.set(k, [n]);
    n++;
  }
  return sites;
}

/** One sampled Lloyd step (see the module comment). */
export function lloydStepOnMesh(mesh: PreparedMesh, sites: Float64Array): Float64Array {
  const count = sites.length / 3;
  const tree = new KdTree3(sites, count);
  const ids = new Int32Array(1);
  const d2 = new Float64Array(1);
  const sum = new Float64Array(4 * count);
  const nf = mesh.areas.length;
  for (let f = 0; f < nf; f++) {
    const c = mesh.centroids;
    tree.knn(c[3 * f], c[3 * f + 1], c[3 * f + 2], 1, ids, d2);
    const s = ids[0];
    const w = mesh.areas[f];
    sum[4 * s] += w * c[3 * f];
    sum[4 * s + 1] += w * c[3 * f + 1];
    sum[4 * s + 2] += w * c[3 * f + 2];
    sum[4 * s + 3] += w;
  }
  const out = new Float64Array(sites.length);
  for (let s = 0; s < count; s++) {
    const w = sum[4 * s + 3];
    if (w > 0) closestOnMesh(mesh, sum[4 * s] / w, sum[4 * s + 1] / w, sum[4 * s + 2] / w, out, 3 * s);
    else out.set(sites.subarray(3 * s, 3 * s + 3), 3 * s);
  }
  return out;
}

/** The restricted Voronoi diagram of the sites on the mesh, as analysis input (no border: closed). */
export function meshSurface(mesh: PreparedMesh, sites: Float64Array, label: string): SurfaceAdjacency {
  const count = sites.length / 3;
  const rvd = restrictedVoronoi({ kind: 'mesh', positions: mesh.positions, indices: mesh.indices, triangleNeighbours: mesh.neighbours }, sites, count);
  return { ...rvd.adjacency, label };
}

/**
 * Each site carried along its triangle's outward normal to the first point of `other` within `maxDistance` µm; where the ray meets nothing, the point
 * at `thicknessAt(x, y, z)` along the normal (the parallel surface at the local measured thickness).
 */
export function carryAlongNormals(
  from: PreparedMesh,
  sites: Float64Array,
  other: PreparedMesh,
  maxDistance: number,
  thicknessAt: (x: number, y: number, z: number) => number,
): { sites: Float64Array; alongNormal: number; parallel: number } {
  const count = sites.length / 3;
  const out = new Float64Array(sites.length);
  const on = new Float64Array(3);
  const ray = new Ray();
  let alongNormal = 0;
  let parallel = 0;
  for (let s = 0; s < count; s++) {
    const f = closestOnMesh(from, sites[3 * s], sites[3 * s + 1], sites[3 * s + 2], on, 0);
    const n = from.normals.subarray(3 * f, 3 * f + 3);
    ray.origin.set(on[0], on[1], on[2]);
    ray.direction.set(n[0], n[1], n[2]);
    const hit = other.bvh.raycastFirst(ray, DoubleSide, 0, maxDistance);
    if (hit) {
      out.set([hit.point.x, hit.point.y, hit.point.z], 3 * s);
      alongNormal++;
    } else {
      const h = thicknessAt(on[0], on[1], on[2]);
      for (let k = 0; k < 3; k++) out[3 * s + k] = on[k] + n[k] * h;
      parallel++;
    }
  }
  return { sites: out, alongNormal, parallel };
}
