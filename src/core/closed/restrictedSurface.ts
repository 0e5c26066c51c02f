/**
 * The surfaces a restricted Voronoi diagram is computed on, and what a mesh needs for the
 * per-seed traversal (triangle neighbours across edges).
 *
 * - `{ kind: 'ellipsoid', a, b, c }`: the analytic ellipsoid x²/a² + y²/b² + z²/c² = 1
 *   centred at the origin, axis-aligned (a sphere is a = b = c). Contacts are conic arcs.
 * - `{ kind: 'mesh', positions, indices }`: a closed triangle mesh (3 vertex ids per
 *   triangle). `triangleNeighbours` may be passed in (from `triangleNeighbours(indices, …)`)
 *   so that the layers of a stack, which share the topology, build it once.
 */

/** The analytic ellipsoid (the config's ellipsoid surface describes it; this is its geometry, µm). */
export interface EllipsoidGeometry {
  readonly kind: 'ellipsoid';
  readonly a: number;
  readonly b: number;
  readonly c: number;
}

/** A loaded triangle mesh in µm (the config's `MeshSurface` names its file and scale). */
export interface MeshGeometry {
  readonly kind: 'mesh';
  readonly positions: ArrayLike<number>;
  readonly indices: ArrayLike<number>;
  /** 3 per triangle: the triangle across edge e (vertices e, e + 1 mod 3), -1 on an open edge. */
  readonly triangleNeighbours?: Int32Array;
}

export type RestrictedSurface = EllipsoidGeometry | MeshGeometry;

export function sphereSurface(radius: number): EllipsoidGeometry {
  return { kind: 'ellipsoid', a: radius, b: radius, c: radius };
}

/**
 * Triangle across each edge of each triangle, through a vertex → triangles index (no hash
 * map): for edge (u, v) of triangle f, the other triangle incident to u that also has v.
 * Closed manifold meshes have exactly one; -1 where none (an open edge).
 */
export function triangleNeighbours(indices: ArrayLike<number>, vertexCount: number): Int32Array {
  const nf = indices.length / 3;
  const start = new Int32Array(vertexCount + 1);
  for (let k = 0; k < indices.length; k++) start[indices[k] + 1]++;
  for (let v = 0; v < vertexCount; v++) start[v + 1] += start[v];
  const cursor = start.slice(0, vertexCount);
  const faces = new Int32Array(indices.length);
  for (let f = 0; f < nf; f++) for (let e = 0; e < 3; e++) faces[cursor[indices[3 * f + e]]++] = f;
  const out = new Int32Array(3 * nf).fill(-1);
  for (let f = 0; f < nf; f++) {
    for (let e = 0; e < 3; e++) {
      const u = indices[3 * f + e],
        v = indices[3 * f + ((e + 1) % 3)];
      for (let q = start[u]; q < start[u + 1]; q++) {
        const g = faces[q];
        if (g === f) continue;
        if (indices[3 * g] === v || indices[3 * g + 1] === v || indices[3 * g + 2] === v) {
          out[3 * f + e] = g;
          break;
        }
      }
    }
  }
  return out;
}

/** Checks a surface's fields; one line naming the field on bad input. */
export function checkRestrictedSurface(surface: RestrictedSurface): void {
  if (surface.kind === 'ellipsoid') {
    for (const key of ['a', 'b', 'c'] as const) {
      const v = surface[key];
      if (!(Number.isFinite(v) && v > 0)) throw new Error(`surface.${key}: ${v} is not a positive semi-axis in µm; give a finite number > 0`);
    }
    return;
  }
  if (surface.kind !== 'mesh') throw new Error(`surface.kind: "${(surface as { kind: string }).kind}" is not "ellipsoid" or "mesh"`);
  if (surface.indices.length % 3 !== 0 || surface.indices.length === 0) {
    throw new Error(`surface.indices: ${surface.indices.length} entries is not a positive multiple of 3 (3 vertex ids per triangle)`);
  }
  const nv = surface.positions.length / 3;
  for (let k = 0; k < surface.indices.length; k++) {
    const v = surface.indices[k];
    if (!(v >= 0 && v < nv)) throw new Error(`surface.indices: entry ${k} is ${v}, outside the ${nv} vertices`);
  }
}
