/**
 * The surface of the stack at signed offset t (µm, along the outward normal) and the sites on
 * it, for the restricted Voronoi diagram (restrictedVoronoi.ts).
 *
 * `offset: "normal"` (today's rule, the default): the parallel surface.
 * - mesh: every vertex moved t along its area-weighted vertex normal (the normal the cube-map
 *   geometry image interpolates; src/core/mesh/types.ts vertexNormals), topology shared, so
 *   `triangleNeighbours` carries over; sites moved t along their normals (as offsetSites in
 *   src/run/closedSheet.ts).
 * - sphere: the concentric sphere R + t, sites moved radially (analytic).
 * - ellipsoid: the parallel surface of an ellipsoid is not an ellipsoid; it is triangulated:
 *   an icosphere mapped onto the ellipsoid, every vertex moved t along the exact normal, fine
 *    enough that the chord deviation h² / (6 ρ) (h the longest edge, ρ = smallest radius of
 *   curvature of the parallel surface = reach + t) stays below `maxDeviation`. Sites:
 *   s + t n(s), on the exact parallel surface.
 *
 * `offset: "axes"` (the lab's spheroid model; sphere and ellipsoid only): the ellipsoid with
 * semi-axes a + t, b + t, c + t (analytic), every site moved to its closest point on it.
 */
import { ConfigError } from '../config/configError';
import { closestPointOnEllipsoid } from '../cubemap/sample';
import { icosphere } from '../mesh/generate';
import { areaWeightedVertexNormals } from '../mesh/types';
import type { EllipsoidGeometry, MeshGeometry, RestrictedSurface } from './restrictedSurface';
import { triangleNeighbours } from './restrictedSurface';

export type OffsetMode = 'normal' | 'axes';

export interface OffsetOptions {
  /** Largest distance (µm) a triangulated parallel surface may deviate from the exact one. */
  maxDeviation?: number;
  /** Largest triangle count a triangulated parallel surface may have (work bound). */
  maxTriangles?: number;
}

export interface OffsetSurface {
  readonly surface: RestrictedSurface;
  /** Sites on the offset surface, x, y, z per site (µm). */
  readonly sites: Float64Array;
  /** Unit outward normal at each moved site. */
  readonly normals: Float64Array;
  /** 'analytic' (sphere, ellipsoid, "axes"), 'mesh' (an offset input mesh) or 'triangulated'. */
  readonly representation: 'analytic' | 'mesh' | 'triangulated';
  /** Bound on the triangulation's distance to the exact parallel surface (0 when exact). */
  readonly deviation: number;
}

/**
 * `surface` at t = 0, `sites` and their unit outward `normals` on it (x, y, z per site);
 * t > 0 is outward. Throws one line naming the field when the offset is impossible.
 */
export function offsetClosedSurface(
  surface: RestrictedSurface,
  sites: ArrayLike<number>,
  normals: ArrayLike<number>,
  count: number,
  t: number,
  mode: OffsetMode = 'normal',
  options: OffsetOptions = {},
): OffsetSurface {
  if (!Number.isFinite(t)) throw new Error(`sheet.thickness: offset ${t} µm is not a finite number`);
  if (mode !== 'normal' && mode !== 'axes') throw new Error(`sheet.offset: "${mode}" is not "normal" or "axes"`);
  if (surface.kind === 'mesh') {
    if (mode === 'axes')
      throw new Error('sheet.offset: "axes" (semi-axes a + t, b + t, c + t) is defined for a sphere or an ellipsoid only; use "normal" for a mesh');
    return {
      surface: offsetMesh(surface, t),
      sites: moveAlong(sites, normals, count, t),
      normals: Float64Array.from({ length: 3 * count }, (_, k) => normals[k]),
      representation: 'mesh',
      deviation: 0,
    };
  }
  const { a, b, c } = surface;
  const sphere = a === b && b === c;
  if (mode === 'axes' || sphere) {
    const A = a + t,
      B = b + t,
      C = c + t;
    if (!(Math.min(A, B, C) > 0))
      throw new Error(`sheet.thickness: an inward offset of ${-t} µm reaches the smallest semi-axis (${Math.min(a, b, c)} µm); use less`);
    const out = new Float64Array(3 * count),
      nrm = new Float64Array(3 * count);
    for (let i = 0; i < count; i++) {
      const p = closestPointOnEllipsoid([sites[3 * i], sites[3 * i + 1], sites[3 * i + 2]], A, B, C);
      for (let k = 0; k < 3; k++) out[3 * i + k] = p[k];
      ellipsoidNormal(p[0], p[1], p[2], A, B, C, nrm, 3 * i);
    }
    return { surface: { kind: 'ellipsoid', a: A, b: B, c: C }, sites: out, normals: nrm, representation: 'analytic', deviation: 0 };
  }
  return parallelEllipsoid(surface, sites, count, t, options);
}

function ellipsoidNormal(x: number, y: number, z: number, a: number, b: number, c: number, out: Float64Array, o: number): void {
  const nx = x / (a * a),
    ny = y / (b * b),
    nz = z / (c * c);
  const l = Math.hypot(nx, ny, nz) || 1;
  out[o] = nx / l;
  out[o + 1] = ny / l;
  out[o + 2] = nz / l;
}

function moveAlong(sites: ArrayLike<number>, normals: ArrayLike<number>, count: number, t: number): Float64Array {
  if (normals.length < 3 * count) throw new Error(`normals: ${normals.length} values for ${count} sites; give a unit normal (x, y, z) per site`);
  const out = new Float64Array(3 * count);
  for (let k = 0; k < 3 * count; k++) out[k] = sites[k] + t * normals[k];
  return out;
}

/** The mesh's vertices moved t along their area-weighted normals (t = 0: the mesh itself). */
function offsetMesh(mesh: MeshGeometry, t: number): MeshGeometry {
  const neighbours = mesh.triangleNeighbours ?? triangleNeighbours(mesh.indices, mesh.positions.length / 3);
  if (t === 0) return { ...mesh, triangleNeighbours: neighbours };
  const normals = areaWeightedVertexNormals(mesh.positions, mesh.indices);
  const positions = new Float64Array(mesh.positions.length);
  for (let k = 0; k < positions.length; k++) positions[k] = mesh.positions[k] + t * normals[k];
  return { kind: 'mesh', positions, indices: mesh.indices, triangleNeighbours: neighbours };
}

/** Triangulated parallel surface of an ellipsoid at offset t, and the sites moved onto the exact one. */
function parallelEllipsoid(surface: EllipsoidGeometry, sites: ArrayLike<number>, count: number, t: number, options: OffsetOptions): OffsetSurface {
  const { a, b, c } = surface;
  const lo = Math.min(a, b, c),
    hi = Math.max(a, b, c);
  const rho = (lo * lo) / hi + t; // smallest radius of curvature of the parallel surface
  if (!(rho > 0))
    throw new Error(
      `sheet.thickness: an inward offset of ${-t} µm reaches the smallest radius of curvature of the ellipsoid (${((lo * lo) / hi).toPrecision(4)} µm), where the offset surface folds over itself; use less or direction "outward"`,
    );
  // 1 % of the cell spacing: against 0.1 % it changed no neighbour set after the minimum contact
  // length (3,200 cells: 90:45:45, offsets -8 to 16 µm, 4 seeds) and contact lengths by < 0.4 %,
  // at a quarter of the cost (the diagram of every layer of a stack triangulates one).
  const maxDeviation = options.maxDeviation ?? 1e-2 * Math.sqrt((4 * Math.PI * (hi + Math.abs(t)) ** 2) / Math.max(1, count));
  const maxTriangles = options.maxTriangles ?? 2_000_000;
  if (!(maxDeviation > 0)) throw new Error(`maxDeviation: ${maxDeviation} µm is not a positive distance`);
  // Longest edge of an icosphere of frequency f on the unit sphere is about 1.15 / f rad; the
  // estimate (largest radius) is a lower bound for f, the measured edges decide.
  // Frequencies rounded up to a multiple of 16, so that the layers of a stack share one
  // icosphere (cachedIcosphere) instead of building one each.
  let f = roundFrequency(Math.max(2, Math.ceil((1.15 * (hi + Math.max(0, t))) / Math.sqrt(6 * rho * maxDeviation))));
  for (;;) {
    if (20 * f * f > maxTriangles) {
      if (options.maxDeviation === undefined && t < 0) {
        // Near the smallest radius of curvature the parallel surface bends too sharply for the
        // triangles the exact method may use: the config's thickness, refused naming what fits.
        // The largest frequency the budget allows (frequencies go in steps of 16), and the
        // smallest radius of curvature it meshes, with room for edges longer than estimated.
        const fMax = 16 * Math.floor(Math.sqrt(maxTriangles / 20) / 16);
        const rhoMin = (1.5 * (1.15 * hi) ** 2) / (6 * maxDeviation * fMax * fMax);
        const fits = Math.floor(((lo * lo) / hi - rhoMin) * 1e3) / 1e3;
        throw new ConfigError(
          'sheet.thickness',
          `sheet.thickness: an inward offset of ${-t} µm comes so close to the ellipsoid's smallest radius of curvature (${((lo * lo) / hi).toPrecision(4)} µm) that the exact method's parallel surface would need about ${20 * f * f} triangles (at most ${maxTriangles}); use an inward thickness up to about ${Math.max(0, fits)} µm, or sheet.adjacency "labels"`,
        );
      }
      throw new Error(
        `maxDeviation: ${maxDeviation} µm would need about ${20 * f * f} triangles for the parallel surface at ${t} µm (more than maxTriangles ${maxTriangles}); allow a larger deviation`,
      );
    }
    const mesh = cachedIcosphere(f);
    const P = new Float64Array(mesh.positions.length);
    const N = new Float64Array(3);
    for (let v = 0; v < P.length; v += 3) {
      // Normalise in float64 (icosphere stores float32).
      const ux = mesh.positions[v],
        uy = mesh.positions[v + 1],
        uz = mesh.positions[v + 2];
      const l = Math.hypot(ux, uy, uz);
      const x = (a * ux) / l,
        y = (b * uy) / l,
        z = (c * uz) / l;
      ellipsoidNormal(x, y, z, a, b, c, N, 0);
      P[v] = x + t * N[0];
      P[v + 1] = y + t * N[1];
      P[v + 2] = z + t * N[2];
    }
    let h = 0;
    const T = mesh.indices;
    for (let k = 0; k < T.length; k += 3) {
      for (let e = 0; e < 3; e++) {
        const u = 3 * T[k + e],
          w = 3 * T[k + ((e + 1) % 3)];
        h = Math.max(h, Math.hypot(P[w] - P[u], P[w + 1] - P[u + 1], P[w + 2] - P[u + 2]));
      }
    }
    // A triangle with longest edge h has circumradius ≤ h / √3 (acute) or its farthest point
    // at the longest edge's midpoint (obtuse): its distance to the surface ≤ h² / (6 ρ).
    const deviation = (h * h) / (6 * rho);
    if (deviation <= maxDeviation) {
      const out = new Float64Array(3 * count),
        nrm = new Float64Array(3 * count);
      for (let i = 0; i < count; i++) {
        // Sites are expected on the ellipsoid; their closest point makes that exact.
        const p = closestPointOnEllipsoid([sites[3 * i], sites[3 * i + 1], sites[3 * i + 2]], a, b, c);
        ellipsoidNormal(p[0], p[1], p[2], a, b, c, nrm, 3 * i);
        for (let k = 0; k < 3; k++) out[3 * i + k] = p[k] + t * nrm[3 * i + k];
      }
      const triangulated: MeshGeometry = { kind: 'mesh', positions: P, indices: T, triangleNeighbours: mesh.triangleNeighbours };
      return { surface: triangulated, sites: out, normals: nrm, representation: 'triangulated', deviation };
    }
    f = roundFrequency(Math.ceil(f * Math.sqrt(deviation / maxDeviation) * 1.05));
  }
}

/**
 * Icospheres with their triangle neighbours, kept for the next call: every layer of a stack (and
 * every run on the same ellipsoid) triangulates its parallel surface at about the same frequency,
 * and building the icosphere and its neighbour table cost more than the diagram itself.
 */
const icospheres = new Map<number, { positions: Float32Array; indices: Uint32Array; triangleNeighbours: Int32Array }>();
const KEPT_ICOSPHERES = 4;

function cachedIcosphere(frequency: number): { positions: Float32Array; indices: Uint32Array; triangleNeighbours: Int32Array } {
  let mesh = icospheres.get(frequency);
  if (!mesh) {
    const built = icosphere(frequency);
    mesh = { positions: built.positions, indices: built.indices, triangleNeighbours: triangleNeighbours(built.indices, built.positions.length / 3) };
    if (icospheres.size >= KEPT_ICOSPHERES) icospheres.delete(icospheres.keys().next().value as number);
    icospheres.set(frequency, mesh);
  }
  return mesh;
}

function roundFrequency(f: number): number {
  return Math.ceil(f / 16) * 16;
}
