/**
 * Exact Voronoi diagram of sites on a sphere: the spherical Delaunay triangulation is the 3D
 * convex hull of the unit site directions (three.js's ConvexHull addon, quickhull), and each
 * hull edge (i, j) between faces F and G is the Voronoi edge joining the circumcentres of F and
 * G (the outward face normals). Cell areas are sums of the spherical triangles (site,
 * circumcentre F, circumcentre G) over the cell's edges; lengths are arcs.
 */
import { Vector3 } from 'three';
import { ConvexHull } from 'three/examples/jsm/math/ConvexHull.js';

export interface SphericalVoronoi {
  readonly count: number;
  /** Neighbours of cell i: neighbours[offsets[i] .. offsets[i + 1]), with the arc lengths (µm). */
  readonly adjacency: { readonly offsets: Int32Array; readonly neighbours: Int32Array; readonly lengths: Float64Array };
  /** Cell areas on the sphere of the given radius, µm². */
  readonly areas: Float64Array;
  readonly touchesBorder: Uint8Array;
}

/** Solid angle of the spherical triangle of unit vectors a, b, c (Van Oosterom & Strackee). */
function solidAngle(a: Vector3, b: Vector3, c: Vector3): number {
  const triple = a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  const den = 1 + a.dot(b) + b.dot(c) + c.dot(a);
  return Math.abs(2 * Math.atan2(triple, den));
}

/** `directions`: x, y, z per site (any length > 0; normalised here). */
export function sphericalVoronoi(directions: ArrayLike<number>, count: number, radius: number): SphericalVoronoi {
  const points: Vector3[] = [];
  const ids = new Map<Vector3, number>();
  for (let i = 0; i < count; i++) {
    const v = new Vector3(directions[3 * i], directions[3 * i + 1], directions[3 * i + 2]).normalize();
    points.push(v);
    ids.set(v, i);
  }
  const hull = new ConvexHull().setFromPoints(points);
  const centre = new Map<object, Vector3>();
  for (const face of hull.faces) centre.set(face, face.normal.clone().normalize());
  const lists: number[][] = Array.from({ length: count }, () => []);
  const lengths: number[][] = Array.from({ length: count }, () => []);
  const areas = new Float64Array(count);
  for (const face of hull.faces) {
    let edge = face.edge;
    do {
      const a = ids.get(edge.tail().point)!;
      const b = ids.get(edge.head().point)!;
      if (a < b && edge.twin) {
        const c1 = centre.get(face)!;
        const c2 = centre.get(edge.twin.face)!;
        const length = radius * Math.acos(Math.max(-1, Math.min(1, c1.dot(c2))));
        lists[a].push(b);
        lengths[a].push(length);
        lists[b].push(a);
        lengths[b].push(length);
        const r2 = radius * radius;
        areas[a] += r2 * solidAngle(points[a], c1, c2);
        areas[b] += r2 * solidAngle(points[b], c1, c2);
      }
      edge = edge.next;
    } while (edge !== face.edge);
  }
  const offsets = new Int32Array(count + 1);
  for (let i = 0; i < count; i++) offsets[i + 1] = offsets[i] + lists[i].length;
  const adjacency = { offsets, neighbours: Int32Array.from(lists.flat()), lengths: Float64Array.from(lengths.flat()) };
  return { count, adjacency, areas, touchesBorder: new Uint8Array(count) };
}
