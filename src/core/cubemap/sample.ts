/**
 * Geometry images on the cube map: per texel, the 3D point of the surface, its unit normal and
 * the surface area the texel stands for. These are the textures the GPU Lloyd loop reads
 * (DESIGN.md: "a surface is a geometry image"): the jump flood measures distances between 3D
 * positions, and the centroid pass weights each texel by density × area element.
 *
 * The area element is defined so that summing it over all 6 n² texels gives the surface area
 * (up to the sampling error of the texels that straddle a triangle edge, for a mesh):
 * - sphere of radius R: area = R² Ω_texel (exact);
 * - ellipsoid (a, b, c), parameterized by p = (a x, b y, c z) for the texel's unit direction
 *   (x, y, z): the Jacobian of this map restricted to the sphere is
 *   a b c √(x²/a² + y²/b² + z²/c²) (the area factor |det S| |S⁻ᵀ n| of the linear map
 *   S = diag(a, b, c)), times the exact texel solid angle;
 * - parameterized mesh: the texel's direction is located in the spherical triangle that
 *   contains it; position and normal are interpolated barycentrically, and the area element
 *   is Ω_texel × (triangle area / its solid angle on the parameter sphere), i.e. the map's
 *   piecewise-constant area scale.
 */
import { BufferAttribute, BufferGeometry, DoubleSide, Ray, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import { sphericalTriangleArea } from '../mesh/spherical';
import { faceAreas, vertexNormals, type TriangleMesh } from '../mesh/types';
import { texelDirection, texelSolidAngle, type Vec3 } from './cubemap';

export type CubeSurface =
  | { kind: 'sphere'; radius: number }
  | { kind: 'ellipsoid'; a: number; b: number; c: number }
  /** `sphere`: unit-sphere point per vertex, from sphericalParameterization. */
  | { kind: 'mesh'; mesh: TriangleMesh; sphere: Float64Array };

export interface CubeGeometryImage {
  /** Texels per face edge; 6 n² texels in the order of cubemap.ts (index (f n + j) n + i). */
  n: number;
  /** x, y, z per texel. */
  position: Float32Array;
  /** Unit outward normal per texel. */
  normal: Float32Array;
  /** Surface area represented by the texel (same units² as the positions). */
  area: Float32Array;
  /** Sum of `area` accumulated in float64. */
  totalArea: number;
  /** Mesh only: the triangle each texel lies in, and the barycentric coordinates (3 per texel). */
  triangle?: Int32Array;
  barycentric?: Float32Array;
}

function allocate(n: number): CubeGeometryImage {
  const count = 6 * n * n;
  return { n, position: new Float32Array(3 * count), normal: new Float32Array(3 * count), area: new Float32Array(count), totalArea: 0 };
}

/** Exact texel solid angles of one face (all faces are alike), row-major j * n + i. */
function faceSolidAngles(n: number): Float64Array {
  const out = new Float64Array(n * n);
  for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) out[j * n + i] = texelSolidAngle(i, j, n);
  return out;
}

/** Samples an analytic or meshed closed surface on an n × n × 6 cube map. */
export function sampleSurface(surface: CubeSurface, n: number): CubeGeometryImage {
  if (!(Number.isInteger(n) && n >= 1)) throw new Error(`sampleSurface: n must be a positive integer, got ${n}`);
  if (surface.kind === 'mesh') return sampleParameterizedMesh(surface.mesh, surface.sphere, n);
  const [a, b, c] = surface.kind === 'sphere' ? [surface.radius, surface.radius, surface.radius] : [surface.a, surface.b, surface.c];
  if (!(a > 0 && b > 0 && c > 0)) throw new Error(`sampleSurface: radii must be positive, got ${a}, ${b}, ${c}`);
  const img = allocate(n);
  const omega = faceSolidAngles(n);
  let total = 0;
  for (let f = 0; f < 6; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const k = (f * n + j) * n + i;
        const [x, y, z] = texelDirection(f, i, j, n);
        img.position[3 * k] = a * x;
        img.position[3 * k + 1] = b * y;
        img.position[3 * k + 2] = c * z;
        const nx = x / a,
          ny = y / b,
          nz = z / c;
        const l = Math.hypot(nx, ny, nz);
        img.normal[3 * k] = nx / l;
        img.normal[3 * k + 1] = ny / l;
        img.normal[3 * k + 2] = nz / l;
        const area = a * b * c * l * omega[j * n + i];
        img.area[k] = area;
        total += area;
      }
    }
  }
  img.totalArea = total;
  return img;
}

/** A BVH over the chordal triangles of the parameter sphere, for point location. */
function sphereBvh(mesh: TriangleMesh, sphere: Float64Array): MeshBVH {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(Float32Array.from(sphere), 3));
  g.setIndex(new BufferAttribute(mesh.indices.slice(), 1));
  // indirect: keep the index buffer in the caller's triangle order, so faceIndex is ours.
  return new MeshBVH(g, { indirect: true });
}

/**
 * Barycentric coordinates of direction d in the cone over triangle (A, B, C) (points on the
 * unit sphere): solve d = α A + β B + γ C and normalise α + β + γ = 1. This is where the ray
 * from the origin along d crosses the flat triangle ABC, so it is exact point location.
 */
function coneBarycentric(s: Float64Array, ia: number, ib: number, ic: number, d: Vec3): Vec3 {
  const A = [s[3 * ia], s[3 * ia + 1], s[3 * ia + 2]];
  const B = [s[3 * ib], s[3 * ib + 1], s[3 * ib + 2]];
  const C = [s[3 * ic], s[3 * ic + 1], s[3 * ic + 2]];
  const det = (u: number[], v: number[], w: number[]) =>
    u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) + u[2] * (v[0] * w[1] - v[1] * w[0]);
  const D = det(A, B, C);
  let al = det(d, B, C) / D,
    be = det(A, d, C) / D,
    ga = det(A, B, d) / D;
  al = Math.max(al, 0);
  be = Math.max(be, 0);
  ga = Math.max(ga, 0);
  const sum = al + be + ga || 1;
  return [al / sum, be / sum, ga / sum];
}

/** Geometry image of a mesh through its spherical parameterization. */
function sampleParameterizedMesh(mesh: TriangleMesh, sphere: Float64Array, n: number): CubeGeometryImage {
  const t = mesh.indices,
    p = mesh.positions;
  const nf = t.length / 3;
  if (sphere.length !== p.length) throw new Error('sampleParameterizedMesh: sphere must have one point per mesh vertex');
  const bvh = sphereBvh(mesh, sphere);
  const areas = faceAreas(mesh);
  const scale = new Float64Array(nf);
  for (let f = 0; f < nf; f++) {
    const omega = sphericalTriangleArea(sphere, t[3 * f], t[3 * f + 1], t[3 * f + 2]);
    scale[f] = omega > 0 ? areas[f] / omega : 0;
  }
  const normals = vertexNormals(mesh);
  const img = allocate(n);
  img.triangle = new Int32Array(6 * n * n);
  img.barycentric = new Float32Array(18 * n * n);
  const omega = faceSolidAngles(n);
  const ray = new Ray(new Vector3(0, 0, 0), new Vector3());
  const target = { point: new Vector3(), distance: 0, faceIndex: 0 };
  const q = new Vector3();
  let total = 0;
  for (let f = 0; f < 6; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const k = (f * n + j) * n + i;
        const d = texelDirection(f, i, j, n);
        ray.direction.set(d[0], d[1], d[2]);
        const hit = bvh.raycastFirst(ray, DoubleSide);
        let tri: number;
        if (hit && hit.faceIndex !== undefined && hit.faceIndex !== null) tri = hit.faceIndex;
        else {
          // A ray exactly through a float32 crack between triangles: take the nearest one.
          bvh.closestPointToPoint(q.set(d[0], d[1], d[2]), target);
          tri = target.faceIndex;
        }
        const ia = t[3 * tri],
          ib = t[3 * tri + 1],
          ic = t[3 * tri + 2];
        const w = coneBarycentric(sphere, ia, ib, ic, d);
        img.triangle[k] = tri;
        img.barycentric.set(w, 3 * k);
        let nx = 0,
          ny = 0,
          nz = 0;
        for (let c = 0; c < 3; c++) {
          const o = 3 * k + c;
          img.position[o] = w[0] * p[3 * ia + c] + w[1] * p[3 * ib + c] + w[2] * p[3 * ic + c];
        }
        nx = w[0] * normals[3 * ia] + w[1] * normals[3 * ib] + w[2] * normals[3 * ic];
        ny = w[0] * normals[3 * ia + 1] + w[1] * normals[3 * ib + 1] + w[2] * normals[3 * ic + 1];
        nz = w[0] * normals[3 * ia + 2] + w[1] * normals[3 * ib + 2] + w[2] * normals[3 * ic + 2];
        const l = Math.hypot(nx, ny, nz) || 1;
        img.normal[3 * k] = nx / l;
        img.normal[3 * k + 1] = ny / l;
        img.normal[3 * k + 2] = nz / l;
        const area = scale[tri] * omega[j * n + i];
        img.area[k] = area;
        total += area;
      }
    }
  }
  img.totalArea = total;
  return img;
}

/**
 * Closest point on the ellipsoid x²/a² + y²/b² + z²/c² = 1 to p (used to project sites back onto
 * an analytic ellipsoidal sheet after each Lloyd step).
 * The minimiser is x_i = a_i² p_i / (a_i² + λ) with λ the root of
 * F(λ) = Σ (a_i p_i / (a_i² + λ))² - 1 on (-min a_i², ∞), where F is convex and decreasing, so
 * Newton's method from the left of the root converges monotonically; we safeguard it with
 * bisection. When p lies (nearly) in the plane of the smallest axis inside the ellipsoid, the
 * root is at the pole of that axis and the closed form for that degenerate case is used.
 */
export function closestPointOnEllipsoid(p: Vec3, a: number, b: number, c: number): Vec3 {
  const r = [a, b, c];
  // Work in the octant of p (symmetry) with the smallest semi-axis first in the loop.
  const s = p.map((x) => (x < 0 ? -1 : 1));
  const q = p.map(Math.abs);
  const minAxis = r[0] <= r[1] && r[0] <= r[2] ? 0 : r[1] <= r[2] ? 1 : 2;
  const rmin2 = r[minAxis] * r[minAxis];
  const F = (l: number) => {
    let v = -1;
    for (let k = 0; k < 3; k++) if (q[k] !== 0) v += ((r[k] * q[k]) / (r[k] * r[k] + l)) ** 2;
    return v;
  };
  const dF = (l: number) => {
    let v = 0;
    for (let k = 0; k < 3; k++) if (q[k] !== 0) v -= (2 * (r[k] * q[k]) ** 2) / (r[k] * r[k] + l) ** 3;
    return v;
  };
  const norm = Math.hypot(q[0], q[1], q[2]);
  if (norm === 0) {
    const out: Vec3 = [0, 0, 0];
    out[minAxis] = r[minAxis];
    return out;
  }
  // Degenerate case: q_min ≈ 0 and the candidate with λ = -r_min² lies inside the ellipse.
  if (q[minAxis] <= 1e-12 * norm) {
    let sum = 0;
    const x: number[] = [0, 0, 0];
    let ok = true;
    for (let k = 0; k < 3; k++) {
      if (k === minAxis) continue;
      const den = r[k] * r[k] - rmin2;
      if (den <= 0) {
        // Another axis as short as the shortest (a spheroid's b = c), with the point on it too:
        // the closest points form a circle around the long axis; its point along minAxis serves.
        if (q[k] <= 1e-12 * norm) continue;
        ok = false;
        break;
      }
      x[k] = (r[k] * r[k] * q[k]) / den;
      sum += (x[k] / r[k]) ** 2;
    }
    if (ok && sum < 1) {
      x[minAxis] = r[minAxis] * Math.sqrt(1 - sum);
      return [s[0] * x[0], s[1] * x[1], s[2] * x[2]];
    }
  }
  let lo = -rmin2 + r[minAxis] * q[minAxis]; // F(lo) >= 0
  let hi = Math.max(r[0], r[1], r[2]) * norm; // F(hi) <= 0
  let l = F(0) > 0 ? 0 : lo;
  if (l < lo) l = lo;
  for (let it = 0; it < 100; it++) {
    const f = F(l);
    if (f > 0) lo = Math.max(lo, l);
    else hi = Math.min(hi, l);
    if (Math.abs(f) < 1e-15) break;
    let next = l - f / dF(l);
    if (!(next > lo && next < hi)) next = (lo + hi) / 2;
    if (Math.abs(next - l) <= 1e-15 * Math.max(1, Math.abs(l))) {
      l = next;
      break;
    }
    l = next;
  }
  // A zero coordinate stays zero (and avoids 0/0 when λ = -r_min²).
  return [0, 1, 2].map((k) => (q[k] === 0 ? 0 : (s[k] * r[k] * r[k] * q[k]) / (r[k] * r[k] + l))) as Vec3;
}
