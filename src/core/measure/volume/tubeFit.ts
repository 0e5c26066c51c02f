/**
 * The fitted tube of an open piece (a gland or tube cut by the volume), from the measurement:
 * - axis: each cell's radial direction is its lumen-side-to-outside-side centroid vector; the
 *   axis is the direction least along them (smallest eigenvector of sum d d^T);
 * - radii: a least-squares circle through the lumen-side centroids projected across the axis
 *   (inner), the outside-side centroids' mean distance from its centre (outer), each corrected
 *   for a curved cell's centroid lying inside its arc: a cell of angular width w has its
 *   centroid at R sin(w/2) / (w/2) ≈ R (1 - w²/24), w² ≈ mean cell area / R²;
 * - length: the lumen-side area over 2 pi R_inner; thickness: the valid cells' heights.
 */
import type { VolumeMeasuredResult } from './volumeResult';

export interface TubeGeometry {
  readonly kind: 'tube';
  /** Unit vector along the fitted axis, and a point on it (µm, volume coordinates). */
  readonly axis: [number, number, number];
  readonly centre: [number, number, number];
  readonly innerRadius: number;
  readonly outerRadius: number;
  /** Seeded (inner) surface area over 2 pi innerRadius, µm. */
  readonly length: number;
  /** Which measured layer is the inner (seeded) surface. */
  readonly seededLayer: 'basal' | 'apical';
  readonly seededCells: number;
  /** RMS distance of the inner centroids from their fitted circle, µm (how tube-like the piece is). */
  readonly innerResidual: number;
  readonly thickness: { readonly mean: number; readonly sd: number; readonly cells: number };
}

/** Eigenvector of the smallest eigenvalue of a symmetric 3x3 matrix (cyclic Jacobi). */
export function smallestEigenvector(m: number[][]): [number, number, number] {
  const a = m.map((row) => [...row]);
  const v = [
    [1, 0, 0],
    [0, 1, 0],
    [0, 0, 1],
  ];
  for (let sweep = 0; sweep < 50; sweep++) {
    const off = a[0][1] ** 2 + a[0][2] ** 2 + a[1][2] ** 2;
    if (off < 1e-24) break;
    for (const [p, q] of [
      [0, 1],
      [0, 2],
      [1, 2],
    ]) {
      if (Math.abs(a[p][q]) < 1e-300) continue;
      const theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
      const t = Math.sign(theta || 1) / (Math.abs(theta) + Math.sqrt(theta * theta + 1));
      const c = 1 / Math.sqrt(t * t + 1);
      const s = t * c;
      for (let k = 0; k < 3; k++) {
        const akp = a[k][p];
        const akq = a[k][q];
        a[k][p] = c * akp - s * akq;
        a[k][q] = s * akp + c * akq;
      }
      for (let k = 0; k < 3; k++) {
        const apk = a[p][k];
        const aqk = a[q][k];
        a[p][k] = c * apk - s * aqk;
        a[q][k] = s * apk + c * aqk;
      }
      for (let k = 0; k < 3; k++) {
        const vkp = v[k][p];
        const vkq = v[k][q];
        v[k][p] = c * vkp - s * vkq;
        v[k][q] = s * vkp + c * vkq;
      }
    }
  }
  const i = [0, 1, 2].reduce((best, k) => (a[k][k] < a[best][best] ? k : best), 0);
  return [v[0][i], v[1][i], v[2][i]];
}

/** Least-squares circle through 2D points (Kasa): centre and radius. */
export function fitCircle(points: [number, number][]): { cx: number; cy: number; r: number } {
  // Minimise sum (x² + y² + D x + E y + F)²: normal equations of a 3x3 system.
  const M = [
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0],
  ];
  const rhs = [0, 0, 0];
  for (const [x, y] of points) {
    const row = [x, y, 1];
    const z = -(x * x + y * y);
    for (let i = 0; i < 3; i++) {
      for (let j = 0; j < 3; j++) M[i][j] += row[i] * row[j];
      rhs[i] += row[i] * z;
    }
  }
  const [D, E, F] = solve3(M, rhs);
  const cx = -D / 2;
  const cy = -E / 2;
  return { cx, cy, r: Math.sqrt(Math.max(0, cx * cx + cy * cy - F)) };
}

function solve3(M: number[][], b: number[]): number[] {
  const a = M.map((row, i) => [...row, b[i]]);
  for (let c = 0; c < 3; c++) {
    let p = c;
    for (let r = c + 1; r < 3; r++) if (Math.abs(a[r][c]) > Math.abs(a[p][c])) p = r;
    [a[c], a[p]] = [a[p], a[c]];
    for (let r = 0; r < 3; r++) {
      if (r === c) continue;
      const f = a[r][c] / a[c][c];
      for (let k = c; k < 4; k++) a[r][k] -= f * a[c][k];
    }
  }
  return [a[0][3] / a[0][0], a[1][3] / a[1][1], a[2][3] / a[2][2]];
}

const sub = (a: number[], b: number[]) => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
const dot = (a: number[], b: number[]) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
const cross = (a: number[], b: number[]): [number, number, number] => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
const normalize = (a: number[]): [number, number, number] => {
  const n = Math.hypot(a[0], a[1], a[2]);
  return [a[0] / n, a[1] / n, a[2] / n];
};

/** The surface's radius from the radius of its cells' centroids (see the module comment). */
function archRadius(centroidRadius: number, meanCellArea: number): number {
  let r = centroidRadius;
  for (let k = 0; k < 3; k++) r = centroidRadius / Math.max(0.5, 1 - meanCellArea / (r * r) / 24);
  return r;
}

/** The fitted tube of an open piece, or a note saying why there is none. */
export function fitTube(result: VolumeMeasuredResult): { geometry: TubeGeometry | null; note: string } {
  const inner = result.inputs.layers.findIndex((l) => l.faces === 'lumen');
  const outer = 1 - inner;
  const both = result.cells.filter((c) => c.centroids[0] && c.centroids[1]);
  if (both.length < 6) return { geometry: null, note: `only ${both.length} cells reach both surfaces; a tube needs at least 6` };
  const M = [
    [0, 0, 0],
    [0, 0, 0],
    [0, 0, 0],
  ];
  for (const c of both) {
    const d = normalize(sub(c.centroids[outer]!, c.centroids[inner]!));
    for (let i = 0; i < 3; i++) for (let j = 0; j < 3; j++) M[i][j] += d[i] * d[j];
  }
  const axis = smallestEigenvector(M);
  const seed = Math.abs(axis[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const u = normalize(cross(axis, seed));
  const v = cross(axis, u);
  const across = (p: number[]): [number, number] => [dot(p, u), dot(p, v)];
  const innerPoints = result.cells.filter((c) => c.centroids[inner]).map((c) => across(c.centroids[inner]!));
  const circle = fitCircle(innerPoints);
  const outerPoints = result.cells.filter((c) => c.centroids[outer]).map((c) => across(c.centroids[outer]!));
  const outerRadius = outerPoints.reduce((a, [x, y]) => a + Math.hypot(x - circle.cx, y - circle.cy), 0) / outerPoints.length;
  const residual = Math.sqrt(innerPoints.reduce((a, [x, y]) => a + (Math.hypot(x - circle.cx, y - circle.cy) - circle.r) ** 2, 0) / innerPoints.length);
  const layer = result.inputs.layers[inner];
  const outerLayer = result.inputs.layers[outer];
  const innerRadius = archRadius(circle.r, layer.area / layer.cells);
  const outerRadiusTrue = archRadius(outerRadius, outerLayer.area / outerLayer.cells);
  const { mean, sd, cells: heightCells } = thicknessOf(result);
  // A point on the axis: the circle's centre in the (u, v) plane, at the mean height along the axis.
  const along = result.cells.filter((c) => c.centroids[inner]).reduce((a, c) => a + dot(c.centroids[inner]!, axis), 0) / innerPoints.length;
  const centre: [number, number, number] = [0, 1, 2].map((k) => circle.cx * u[k] + circle.cy * v[k] + along * axis[k]) as [number, number, number];
  if (!(innerRadius > 0) || !(outerRadiusTrue > innerRadius)) {
    return { geometry: null, note: `the fitted tube is not a tube (inner radius ${innerRadius.toFixed(2)} µm, outer ${outerRadiusTrue.toFixed(2)} µm)` };
  }
  return {
    geometry: {
      kind: 'tube',
      axis,
      centre,
      innerRadius,
      outerRadius: outerRadiusTrue,
      length: layer.area / (2 * Math.PI * innerRadius),
      seededLayer: layer.name,
      seededCells: layer.cells,
      innerResidual: residual,
      thickness: { mean, sd, cells: heightCells },
    },
    note: '',
  };
}

/** The valid cells' heights: mean, SD. */
export function thicknessOf(result: VolumeMeasuredResult): { mean: number; sd: number; cells: number } {
  const heights = result.cells.filter((c) => c.valid && c.height !== null).map((c) => c.height!);
  const mean = heights.reduce((a, b) => a + b, 0) / Math.max(1, heights.length);
  const sd = heights.length > 1 ? Math.sqrt(heights.reduce((a, b) => a + (b - mean) ** 2, 0) / (heights.length - 1)) : NaN;
  return { mean: heights.length ? mean : NaN, sd, cells: heights.length };
}
