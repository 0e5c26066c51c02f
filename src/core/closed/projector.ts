/**
 * Closest-point projectors of closed surfaces: where a 3D point (a Euclidean centroid) lands on
 * the surface, the unit normal there and the point's parameter direction (the unit vector the
 * cube-map geometry image is indexed by). Du et al.'s constrained centroid is the closest
 * surface point to the Euclidean centroid of a cell.
 *
 * Parameter directions, consistent with sampleSurface (src/core/cubemap/sample.ts):
 * - sphere: the direction of the point from the centre;
 * - ellipsoid: the texel of direction (x, y, z) holds the point (a x, b y, c z), so a surface
 *   point p has direction normalize(p.x / a, p.y / b, p.z / c);
 * - mesh: closest point -> triangle + barycentric coordinates -> the same combination of the
 *   triangle's parameter-sphere vertices -> normalised.
 */
import { BufferAttribute, BufferGeometry, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import { CUBE_FACES, texelIndex, type Vec3 } from '../cubemap/cubemap';
import { closestPointOnEllipsoid } from '../cubemap/sample';
import { dotOfDifferences, vertexNormals, type TriangleMesh } from '../mesh/types';

/** Where a point landed: stride 9 [px, py, pz, nx, ny, nz, dx, dy, dz] in the caller's buffer. */
export const PROJECTION_STRIDE = 9;

export interface ClosedProjector {
  /** Projects (x, y, z); writes position, normal and parameter direction into out[9 o ..]. */
  project(x: number, y: number, z: number, out: Float64Array, o: number): void;
}

export function sphereProjector(radius: number): ClosedProjector {
  return {
    project(x, y, z, out, o) {
      const l = Math.hypot(x, y, z);
      const b = PROJECTION_STRIDE * o;
      // The centre has no direction: any pole will do (never reached by a centroid of a cell).
      const [nx, ny, nz] = l > 0 ? [x / l, y / l, z / l] : [0, 0, 1];
      out[b] = radius * nx;
      out[b + 1] = radius * ny;
      out[b + 2] = radius * nz;
      out[b + 3] = out[b + 6] = nx;
      out[b + 4] = out[b + 7] = ny;
      out[b + 5] = out[b + 8] = nz;
    },
  };
}

export function ellipsoidProjector(a: number, b: number, c: number): ClosedProjector {
  const point: Vec3 = [0, 0, 0];
  return {
    project(x, y, z, out, o) {
      point[0] = x;
      point[1] = y;
      point[2] = z;
      const [px, py, pz] = closestPointOnEllipsoid(point, a, b, c);
      const k = PROJECTION_STRIDE * o;
      out[k] = px;
      out[k + 1] = py;
      out[k + 2] = pz;
      let nx = px / (a * a),
        ny = py / (b * b),
        nz = pz / (c * c);
      let l = Math.hypot(nx, ny, nz) || 1;
      out[k + 3] = nx / l;
      out[k + 4] = ny / l;
      out[k + 5] = nz / l;
      nx = px / a;
      ny = py / b;
      nz = pz / c;
      l = Math.hypot(nx, ny, nz) || 1;
      out[k + 6] = nx / l;
      out[k + 7] = ny / l;
      out[k + 8] = nz / l;
    },
  };
}

/**
 * Mesh projector (three-mesh-bvh closest point). `mesh` must be oriented outward (its vertex
 * normals are the surface normals); `sphere` is its parameterization (unit point per vertex).
 */
export function meshProjector(mesh: TriangleMesh, sphere: Float64Array): ClosedProjector & { nearestVertex(x: number, y: number, z: number): number } {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(mesh.positions.slice(), 3));
  g.setIndex(new BufferAttribute(mesh.indices.slice(), 1));
  const bvh = new MeshBVH(g, { indirect: true });
  const normals = vertexNormals(mesh);
  const p = mesh.positions,
    t = mesh.indices;
  const q = new Vector3();
  const target = { point: new Vector3(), distance: 0, faceIndex: 0 };
  const w = [0, 0, 0];
  const ids = [0, 0, 0];
  const Q = new Float64Array(12);
  /** Closest point into `target`, its triangle's vertices into `ids`, barycentrics into `w`. */
  const locate = (x: number, y: number, z: number) => {
    bvh.closestPointToPoint(q.set(x, y, z), target);
    const f = target.faceIndex;
    const ia = t[3 * f],
      ib = t[3 * f + 1],
      ic = t[3 * f + 2];
    // Barycentric coordinates of the closest point in its triangle (Ericson, Real-Time Collision Detection).
    const P = target.point;
    // Q: the triangle's corners A, B, C and the point, for v0 = B - A, v1 = C - A, v2 = P - A.
    Q.set(p.subarray(3 * ia, 3 * ia + 3), 0);
    Q.set(p.subarray(3 * ib, 3 * ib + 3), 3);
    Q.set(p.subarray(3 * ic, 3 * ic + 3), 6);
    Q[9] = P.x;
    Q[10] = P.y;
    Q[11] = P.z;
    const d00 = dotOfDifferences(Q, 0, 1, 0, 1),
      d01 = dotOfDifferences(Q, 0, 1, 0, 2),
      d11 = dotOfDifferences(Q, 0, 2, 0, 2);
    const d20 = dotOfDifferences(Q, 0, 3, 0, 1),
      d21 = dotOfDifferences(Q, 0, 3, 0, 2);
    const den = d00 * d11 - d01 * d01 || 1;
    let beta = (d11 * d20 - d01 * d21) / den,
      gamma = (d00 * d21 - d01 * d20) / den;
    beta = Math.min(1, Math.max(0, beta));
    gamma = Math.min(1 - beta, Math.max(0, gamma));
    w[0] = 1 - beta - gamma;
    w[1] = beta;
    w[2] = gamma;
    ids[0] = ia;
    ids[1] = ib;
    ids[2] = ic;
    return ids;
  };
  return {
    project(x, y, z, out, o) {
      const ids = locate(x, y, z);
      const k = PROJECTION_STRIDE * o;
      out[k] = target.point.x;
      out[k + 1] = target.point.y;
      out[k + 2] = target.point.z;
      for (let pass = 0; pass < 2; pass++) {
        const base = pass === 0 ? 3 : 6;
        const src: ArrayLike<number> = pass === 0 ? normals : sphere;
        let sx = 0,
          sy = 0,
          sz = 0;
        for (let v = 0; v < 3; v++) {
          sx += w[v] * src[3 * ids[v]];
          sy += w[v] * src[3 * ids[v] + 1];
          sz += w[v] * src[3 * ids[v] + 2];
        }
        const l = Math.hypot(sx, sy, sz) || 1;
        out[k + base] = sx / l;
        out[k + base + 1] = sy / l;
        out[k + base + 2] = sz / l;
      }
    },
    nearestVertex(x, y, z) {
      const ids = locate(x, y, z);
      return w[0] >= w[1] && w[0] >= w[2] ? ids[0] : w[1] >= w[2] ? ids[1] : ids[2];
    },
  };
}

/**
 * Atlas index of the texel a parameter direction falls in, on an n-texel cube map: the same
 * as directionToTexel (cubemap.ts; same face choice and tie rules), without allocating, for
 * the Lloyd loop.
 */
export function directionTexel(dx: number, dy: number, dz: number, n: number): number {
  const ax = Math.abs(dx),
    ay = Math.abs(dy),
    az = Math.abs(dz);
  let face: number;
  if (ax >= ay && ax >= az) face = dx >= 0 ? 0 : 1;
  else if (ay >= az) face = dy >= 0 ? 2 : 3;
  else face = dz >= 0 ? 4 : 5;
  const F = CUBE_FACES[face];
  const m = dx * F.normal[0] + dy * F.normal[1] + dz * F.normal[2];
  const u = (dx * F.s[0] + dy * F.s[1] + dz * F.s[2]) / m;
  const v = (dx * F.t[0] + dy * F.t[1] + dz * F.t[2]) / m;
  const i = Math.min(n - 1, Math.max(0, Math.floor(((u + 1) / 2) * n)));
  const j = Math.min(n - 1, Math.max(0, Math.floor(((v + 1) / 2) * n)));
  return texelIndex(face, i, j, n);
}
