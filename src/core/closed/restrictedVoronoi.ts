/**
 * Exact neighbours on a closed surface: the restricted Voronoi diagram (RVD) of sites on a
 * triangle mesh or on the analytic ellipsoid / sphere, with true contact lengths in µm and
 * cell areas in µm², as the adjacency record (`SurfaceAdjacency`, src/core/analysis/adjacency.ts;
 * `border` all 0: a closed surface has no open edge).
 *
 *   restrictedVoronoi(surface, sites, count, options?) → { count, adjacency, surfaceArea, stats }
 *
 * - Mesh: restrictedMesh.ts (geogram's per-seed triangle clipping, radius of security,
 *   coverage repair for cells in several pieces).
 * - Ellipsoid / sphere: restrictedEllipsoid.ts (bisector-plane ∩ ellipsoid conic arcs,
 *   clipped analytically; lengths and areas by adaptive quadrature).
 *
 * Sites are 3D points (x, y, z per site, µm). On an ellipsoid they must lie on it (the
 * radius-of-security proof uses that); on a mesh they may be anywhere (the cells are the
 * surface points nearest to each site). A contact is a neighbour when its length exceeds
 * `lengthTolerance` (default 1e-9 × sqrt(area / count), i.e. rounding level): the result is
 * the exact diagram, no minimum contact length applied — `withMinBoundaryLength` does that.
 */
import type { SurfaceAdjacency } from '../analysis/adjacency';
import { ellipsoidArea } from './conicArc';
import { KdTree3 } from './kdTree';
import { ContactRecorder } from './restrictedContacts';
import { EllipsoidRestrictedVoronoi, type EllipsoidRvdStats } from './restrictedEllipsoid';
import { MeshRestrictedVoronoi, type MeshRvdStats, type PieceCallback } from './restrictedMesh';
import { checkRestrictedSurface, type RestrictedSurface } from './restrictedSurface';
import { meshArea } from '../mesh/types';

export interface RestrictedVoronoiOptions {
  /** Contacts at or below this length (µm) are rounding, not neighbours. */
  lengthTolerance?: number;
  /**
   * Mesh only: per site, a triangle to start its cell from, e.g. `startTriangles` of the
   * diagram on another surface of the stack with the same triangles (offset meshes keep the
   * topology, and sites move along their normals); saves building a k-d tree of triangles.
   * A wrong hint costs one clip, never correctness.
   */
  startTriangles?: ArrayLike<number>;
  /** Mesh only: called with every clipped piece of every cell, as it is found (drawing the diagram). */
  onPiece?: PieceCallback;
}

export interface RestrictedVoronoi {
  readonly count: number;
  /** Neighbours, contact lengths (µm), cell areas on the surface (µm²); no border (closed). */
  readonly adjacency: SurfaceAdjacency;
  /** Mesh only: per site, the triangle its cell started in (-1: none); a hint for the next layer. */
  readonly startTriangles?: Int32Array;
  /** Surface area, µm² (sum of triangle areas, or the ellipsoid's). */
  readonly surfaceArea: number;
  readonly stats: { method: 'mesh'; mesh: MeshRvdStats; ms: number } | { method: 'ellipsoid'; ellipsoid: EllipsoidRvdStats; ms: number };
}

/** Relative distance off the ellipsoid a site may have (float32 round trips). */
const ON_SURFACE_TOLERANCE = 1e-6;

export function restrictedVoronoi(
  surface: RestrictedSurface,
  sites: ArrayLike<number>,
  count: number,
  options: RestrictedVoronoiOptions = {},
): RestrictedVoronoi {
  const start = performance.now();
  checkRestrictedSurface(surface);
  if (!(Number.isInteger(count) && count >= 1)) throw new Error(`count: ${count} is not a positive whole number of sites`);
  if (sites.length < 3 * count) throw new Error(`sites: ${sites.length} values for ${count} sites; give x, y, z per site (${3 * count} values)`);
  const xyz = new Float64Array(3 * count);
  for (let k = 0; k < 3 * count; k++) {
    const v = sites[k];
    if (!Number.isFinite(v)) throw new Error(`sites: value ${k} (site ${Math.floor(k / 3)}) is ${v}; give finite coordinates in µm`);
    xyz[k] = v;
  }
  const surfaceArea = surface.kind === 'ellipsoid' ? ellipsoidArea(surface.a, surface.b, surface.c) : meshArea(surface.positions, surface.indices);
  const tolerance = options.lengthTolerance ?? 1e-9 * Math.sqrt(surfaceArea / count);
  const tree = new KdTree3(xyz, count);
  const recorder = new ContactRecorder(count);
  const areas = new Float64Array(count);
  let stats: RestrictedVoronoi['stats'];
  let startTriangles: Int32Array | undefined;
  if (surface.kind === 'ellipsoid') {
    const { a, b, c } = surface;
    for (let i = 0; i < count; i++) {
      const x = xyz[3 * i] / a,
        y = xyz[3 * i + 1] / b,
        z = xyz[3 * i + 2] / c;
      const off = Math.abs(Math.hypot(x, y, z) - 1);
      if (off > ON_SURFACE_TOLERANCE) {
        throw new Error(
          `sites: site ${i} (${xyz[3 * i]}, ${xyz[3 * i + 1]}, ${xyz[3 * i + 2]}) is not on the ellipsoid (${a}, ${b}, ${c}) (relative ${off.toExponential(2)}); move the sites onto the surface first (closestPointOnEllipsoid)`,
        );
      }
    }
    const rvd = new EllipsoidRestrictedVoronoi(surface, xyz, count, tree, recorder, areas, tolerance);
    rvd.run();
    stats = { method: 'ellipsoid', ellipsoid: rvd.stats, ms: 0 };
  } else {
    const rvd = new MeshRestrictedVoronoi(surface, xyz, count, tree, recorder, areas, options.startTriangles, options.onPiece);
    rvd.run();
    startTriangles = rvd.startTriangles;
    stats = { method: 'mesh', mesh: rvd.stats, ms: 0 };
  }
  const adjacency: SurfaceAdjacency = { count, ...recorder.finish(tolerance), areas, border: new Uint8Array(count) };
  stats.ms = performance.now() - start;
  return { count, adjacency, surfaceArea, stats, ...(startTriangles ? { startTriangles } : {}) };
}
