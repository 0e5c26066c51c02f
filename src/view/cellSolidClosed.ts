/**
 * Cross-sections of a cell's solid on closed surfaces (sphere, ellipsoid, mesh): the cell on a
 * surface is its restricted Voronoi cell (the surface ∩ the 3D Voronoi cell of the site among
 * that surface's sites). Traced, not exact: the 3D Voronoi cell cut by the site's tangent plane
 * (a half-plane per nearby site), each traced point then put on the surface (sphere: radially,
 * which keeps bisector planes through the centre, so corners and borders lie on the exact cell;
 * ellipsoid and mesh: onto the plane fitted to the nearest texels of the surface's geometry
 * image, `LabelImage.positions`). Pure geometry.
 */
import { clipHalfPlane, cross, dist2, dot, normalize, scale, square, sub, type Section, type Vec3 } from './cellSolidSection';
import type { ViewStack, ViewSurface } from './stack';

/** Closed surfaces: the 3D Voronoi cell cut by the tangent plane at the site, put on the surface. */
export function closedSections(stack: ViewStack, id: number): Section[] | null {
  const sphere = stack.result.config.surface.kind === 'sphere';
  const sections: Section[] = [];
  let previous: { normal: Vec3; e1: Vec3 } | null = null;
  for (const surface of stack.surfaces) {
    const cell = surface.cells[id];
    const points = surface.image.positions;
    if (!cell || !points) return null;
    const p: Vec3 = [cell.position[0], cell.position[1], cell.position[2]];
    const candidates = candidateSites(surface, id);
    let reach = 0;
    for (const q of candidates) reach = Math.max(reach, Math.hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]));
    let normal = fitPlane(nearestPoints(points, p, 12)).normal;
    if (!previous) {
      const centroid = meanPoint(points);
      if (dot(normal, sub(p, centroid)) < 0) normal = scale(normal, -1);
    } else if (dot(normal, previous.normal) < 0) normal = scale(normal, -1);
    const reference = previous?.e1 ?? leastAlignedAxis(normal);
    const e1 = normalize(sub(reference, scale(normal, dot(reference, normal))));
    const e2 = cross(normal, e1);
    previous = { normal, e1 };

    // Half-plane per candidate: (q - p)·x <= |q - p|² / 2, x = u e1 + v e2.
    let polygon = square(reach > 0 ? reach : 1);
    for (const q of candidates) {
      const d = sub(q, p);
      polygon = clipHalfPlane(polygon, dot(d, e1), dot(d, e2), dot(d, d) / 2);
      if (polygon.length < 6) return null;
    }
    let extent = 0;
    for (let v = 0; v < polygon.length; v += 2) extent = Math.max(extent, Math.hypot(polygon[v], polygon[v + 1]));
    const local = sphere ? new Float32Array(0) : nearbyTexels(points, p, 1.5 * extent);
    const radius = Math.hypot(p[0], p[1], p[2]);
    const toSpace = (x: number, y: number): Vec3 => {
      const point: Vec3 = [p[0] + x * e1[0] + y * e2[0], p[1] + x * e1[1] + y * e2[1], p[2] + x * e1[2] + y * e2[2]];
      if (sphere) return scale(point, radius / Math.hypot(point[0], point[1], point[2]));
      const plane = fitPlane(nearestPoints(local, point, 8));
      return sub(point, scale(plane.normal, dot(sub(point, plane.centre), plane.normal)));
    };
    sections.push({ polygon, centre: toSpace(0, 0), toSpace });
  }
  return sections;
}

/** The sites that can bound cell `id` on a closed surface: all of them, or neighbours to depth 2. */
function candidateSites(surface: ViewSurface, id: number): Vec3[] {
  const cells = surface.cells;
  const ids = new Set<number>();
  if (cells.length <= 3000) cells.forEach((_, i) => ids.add(i));
  else {
    for (const n of cells[id].neighbours) {
      ids.add(n.id);
      for (const m of cells[n.id]?.neighbours ?? []) ids.add(m.id);
    }
  }
  ids.delete(id);
  const p = cells[id].position;
  const out: Vec3[] = [];
  for (const i of ids) {
    const q = cells[i]?.position;
    if (q && (q[0] !== p[0] || q[1] !== p[1] || q[2] !== p[2])) out.push([q[0], q[1], q[2]]);
  }
  if (cells.length <= 3000 && out.length > 64) {
    // Far sites cannot bound the cell once the nearest ones do: keep the 64 nearest.
    out.sort((a, b) => dist2(a, p) - dist2(b, p));
    out.length = 64;
  }
  return out;
}

/** Geometry-image points (xyz) within `radius` of `p`, and at least the 64 nearest. */
function nearbyTexels(points: Float32Array, p: Vec3, radius: number): Float32Array {
  const r2 = radius * radius;
  const out: number[] = [];
  for (let i = 0; i < points.length; i += 3) {
    if ((points[i] - p[0]) ** 2 + (points[i + 1] - p[1]) ** 2 + (points[i + 2] - p[2]) ** 2 <= r2) out.push(points[i], points[i + 1], points[i + 2]);
  }
  if (out.length >= 3 * 64) return Float32Array.from(out);
  return Float32Array.from(nearestPoints(points, p, 64).flat());
}

/** The `k` points (xyz) nearest `x`: one pass, a sorted list of k. */
function nearestPoints(points: Float32Array, x: Vec3, k: number): Vec3[] {
  const best: { d: number; q: Vec3 }[] = [];
  for (let i = 0; i < points.length; i += 3) {
    const d = (points[i] - x[0]) ** 2 + (points[i + 1] - x[1]) ** 2 + (points[i + 2] - x[2]) ** 2;
    if (best.length === k && d >= best[k - 1].d) continue;
    let j = best.length < k ? best.length : k - 1;
    while (j > 0 && best[j - 1].d > d) {
      if (j < k) best[j] = best[j - 1];
      j--;
    }
    best[j] = { d, q: [points[i], points[i + 1], points[i + 2]] };
  }
  return best.map((b) => b.q);
}

/** The least-squares plane of `nearest` (its normal is the covariance's smallest axis). */
function fitPlane(nearest: Vec3[]): { centre: Vec3; normal: Vec3 } {
  const centre = meanOf(nearest);
  const m = [0, 0, 0, 0, 0, 0]; // xx xy xz yy yz zz
  for (const q of nearest) {
    const d = sub(q, centre);
    m[0] += d[0] * d[0];
    m[1] += d[0] * d[1];
    m[2] += d[0] * d[2];
    m[3] += d[1] * d[1];
    m[4] += d[1] * d[2];
    m[5] += d[2] * d[2];
  }
  return { centre, normal: smallestEigenvector(m) };
}

/** Smallest eigenvector of a symmetric 3x3 matrix: power iteration on a shifted matrix. */
function smallestEigenvector(m: number[]): Vec3 {
  const trace = m[0] + m[3] + m[5];
  // B = trace·I - M has the same eigenvectors, the smallest of M the largest of B (power iteration).
  const b = [trace - m[0], -m[1], -m[2], trace - m[3], -m[4], trace - m[5]];
  let v: Vec3 = [0.577, 0.578, 0.576];
  for (let it = 0; it < 64; it++) {
    const w: Vec3 = [b[0] * v[0] + b[1] * v[1] + b[2] * v[2], b[1] * v[0] + b[3] * v[1] + b[4] * v[2], b[2] * v[0] + b[4] * v[1] + b[5] * v[2]];
    const length = Math.hypot(...w);
    if (length === 0) break;
    v = scale(w, 1 / length);
  }
  return v;
}

function meanPoint(points: Float32Array): Vec3 {
  const m: Vec3 = [0, 0, 0];
  const n = points.length / 3;
  for (let i = 0; i < points.length; i += 3) for (let c = 0; c < 3; c++) m[c] += points[i + c] / n;
  return m;
}

function meanOf(points: Vec3[]): Vec3 {
  const m: Vec3 = [0, 0, 0];
  for (const q of points) for (let c = 0; c < 3; c++) m[c] += q[c] / points.length;
  return m;
}

function leastAlignedAxis(n: Vec3): Vec3 {
  const a = n.map(Math.abs);
  if (a[0] <= a[1] && a[0] <= a[2]) return [1, 0, 0];
  return a[1] <= a[2] ? [0, 1, 0] : [0, 0, 1];
}
