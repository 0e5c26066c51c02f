/**
 * Geodesic distance on a triangle mesh by the heat method (Crane, Weischedel, Wardetzky,
 * "Geodesics in Heat", ACM TOG 2013), and the geodesic Voronoi diagram built from it.
 *
 * Why the heat method: a Voronoi diagram of s sites on a mesh needs s distance fields; the
 * heat method reduces each to two sparse solves with matrices that do not depend on the
 * source, so both are factored once (SparseCholesky) and every site then costs two pairs of
 * triangular solves plus O(F) work. The result's optional geodesic comparison
 * (src/run/closedRecord.ts) sets the GPU cube-map Voronoi against it.
 *
 * Steps (per source set):
 *  1. heat flow  (M + t L) u = δ_sources, t = h² (h = mean edge length, Crane's choice);
 *  2. X = -∇u / |∇u| per face;
 *  3. integrated divergence of X at each vertex;
 *  4. Poisson  L φ = -div X  (L is singular: we factor L + εM and remove the mean of the
 *     right-hand side; the constant that remains is removed by step 5);
 *  5. shift φ so the sources are at 0.
 * L is the positive semi-definite cotangent Laplacian: L_ij = -(cot α_ij + cot β_ij)/2,
 * L_ii = -Σ_j L_ij; M is the lumped (barycentric) mass: a third of the incident triangle areas.
 */
import { csrAddDiagonal, csrFromTriplets, SparseCholesky, type CsrMatrix } from './sparse';
import { crossOfDifferences, dotOfDifferences, meanEdgeLength, triangleArea, triangleCross, type TriangleMesh } from './types';

/** Cotangent of the angle at vertex o of triangle (o, a, b). */
function cotAt(p: Float32Array, o: number, a: number, b: number): number {
  const c = crossOfDifferences(p, o, a, o, b, cotCross);
  return dotOfDifferences(p, o, a, o, b) / Math.max(Math.sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]), 1e-300);
}

const cotCross = new Float64Array(3);

/**
 * Cotangent Laplacian (positive semi-definite, CSR). With `clampNegative`, negative edge weights
 * (obtuse opposite angles) are set to 0: that keeps the matrix an M-matrix, which the Tutte
 * embedding in the spherical parameterization needs to be guaranteed flip-free.
 */
export function cotanLaplacian(mesh: TriangleMesh, clampNegative = false): CsrMatrix {
  const p = mesh.positions,
    t = mesh.indices;
  const nv = p.length / 3;
  const weights = new Map<number, number>();
  for (let f = 0; f < t.length; f += 3) {
    for (let k = 0; k < 3; k++) {
      const o = t[f + k],
        a = t[f + ((k + 1) % 3)],
        b = t[f + ((k + 2) % 3)];
      const key = Math.min(a, b) * nv + Math.max(a, b);
      weights.set(key, (weights.get(key) ?? 0) + 0.5 * cotAt(p, o, a, b));
    }
  }
  const rows: number[] = [],
    cols: number[] = [],
    vals: number[] = [];
  const diag = new Float64Array(nv);
  for (const [key, w0] of weights) {
    const w = clampNegative ? Math.max(w0, 0) : w0;
    const a = Math.floor(key / nv),
      b = key - a * nv;
    rows.push(a, b);
    cols.push(b, a);
    vals.push(-w, -w);
    diag[a] += w;
    diag[b] += w;
  }
  for (let i = 0; i < nv; i++) {
    rows.push(i);
    cols.push(i);
    vals.push(diag[i]);
  }
  return csrFromTriplets(nv, rows, cols, vals);
}

/** Lumped mass: one third of the area of the triangles around each vertex. */
export function lumpedMass(mesh: TriangleMesh): Float64Array {
  const p = mesh.positions,
    t = mesh.indices;
  const m = new Float64Array(p.length / 3);
  for (let f = 0; f < t.length / 3; f++) {
    const area = triangleArea(p, t, f);
    for (let k = 0; k < 3; k++) m[t[3 * f + k]] += area / 3;
  }
  return m;
}

export interface HeatOptions {
  /** t = timeFactor × h² (default 1, Crane et al.'s recommendation). */
  timeFactor?: number;
}

/**
 * Prepared heat-method solver for one mesh: factor once, then `distance()` per source set.
 * Construction cost is two sparse Cholesky factorizations; each query is 4 triangular solves.
 */
export class HeatGeodesics {
  readonly mesh: TriangleMesh;
  readonly time: number;
  readonly mass: Float64Array;
  private readonly heat: SparseCholesky;
  private readonly poisson: SparseCholesky;
  /** Per face, per corner: cot of the angle at that corner (for the divergence). */
  private readonly cots: Float64Array;
  /** Per face: 1 / (2 area) and the unit normal. */
  private readonly faceData: Float64Array;

  constructor(mesh: TriangleMesh, options: HeatOptions = {}) {
    this.mesh = mesh;
    const h = meanEdgeLength(mesh);
    this.time = (options.timeFactor ?? 1) * h * h;
    const L = cotanLaplacian(mesh);
    const M = lumpedMass(mesh);
    this.mass = M;
    const A = csrAddDiagonal({ ...L, values: L.values.map((v) => v * this.time) }, M);
    this.heat = new SparseCholesky(A);
    // L is singular (constants); a tiny mass shift makes it definite without changing φ
    // beyond a constant (removed by the shift to the sources).
    let trace = 0,
      msum = 0;
    for (let i = 0; i < M.length; i++) msum += M[i];
    for (let i = 0; i < L.n; i++) for (let p = L.rowPtr[i]; p < L.rowPtr[i + 1]; p++) if (L.colIdx[p] === i) trace += L.values[p];
    const eps = (1e-10 * trace) / msum;
    this.poisson = new SparseCholesky(csrAddDiagonal(L, M, eps), this.heat.perm);

    const p = mesh.positions,
      t = mesh.indices;
    const nf = t.length / 3;
    this.cots = new Float64Array(3 * nf);
    this.faceData = new Float64Array(4 * nf);
    const cross = new Float64Array(3);
    for (let f = 0; f < nf; f++) {
      const [a, b, c] = [t[3 * f], t[3 * f + 1], t[3 * f + 2]];
      this.cots[3 * f] = cotAt(p, a, b, c);
      this.cots[3 * f + 1] = cotAt(p, b, c, a);
      this.cots[3 * f + 2] = cotAt(p, c, a, b);
      const [nx, ny, nz] = triangleCross(p, t, f, cross);
      const twiceArea = Math.hypot(nx, ny, nz) || 1e-300;
      this.faceData.set([1 / twiceArea, nx / twiceArea, ny / twiceArea, nz / twiceArea], 4 * f);
    }
  }

  /** Nonzeros of the two Cholesky factors (for reports). */
  get factorNonzeros(): number {
    return this.heat.nnz + this.poisson.nnz;
  }

  /** Approximate geodesic distance from every vertex to the nearest of `sources` (vertex ids). */
  distance(sources: ArrayLike<number>): Float64Array {
    const nv = this.mesh.positions.length / 3;
    if (sources.length === 0) throw new Error('HeatGeodesics.distance: no source vertices');
    const delta = new Float64Array(nv);
    for (let k = 0; k < sources.length; k++) {
      const s = sources[k];
      if (!(s >= 0 && s < nv)) throw new Error(`HeatGeodesics.distance: source ${s} is not a vertex id (0..${nv - 1})`);
      delta[s] = 1;
    }
    const u = this.heat.solve(delta);
    const p = this.mesh.positions,
      t = this.mesh.indices;
    const nf = t.length / 3;
    const div = new Float64Array(nv);
    const ids = [0, 0, 0];
    for (let f = 0; f < nf; f++) {
      ids[0] = t[3 * f];
      ids[1] = t[3 * f + 1];
      ids[2] = t[3 * f + 2];
      const inv2A = this.faceData[4 * f];
      const nx = this.faceData[4 * f + 1],
        ny = this.faceData[4 * f + 2],
        nz = this.faceData[4 * f + 3];
      // ∇u = 1/(2A) Σ_i u_i (N × e_i), e_i = edge opposite i, counter-clockwise.
      let gx = 0,
        gy = 0,
        gz = 0;
      for (let k = 0; k < 3; k++) {
        const i = ids[k],
          j = ids[(k + 1) % 3],
          l = ids[(k + 2) % 3];
        const ex = p[3 * l] - p[3 * j],
          ey = p[3 * l + 1] - p[3 * j + 1],
          ez = p[3 * l + 2] - p[3 * j + 2];
        const ui = u[i];
        gx += ui * (ny * ez - nz * ey);
        gy += ui * (nz * ex - nx * ez);
        gz += ui * (nx * ey - ny * ex);
      }
      gx *= inv2A;
      gy *= inv2A;
      gz *= inv2A;
      const gl = Math.hypot(gx, gy, gz);
      if (gl === 0) continue;
      const Xx = -gx / gl,
        Xy = -gy / gl,
        Xz = -gz / gl;
      // Integrated divergence: at vertex i, ½ Σ cot θ_1 (e_1 · X) + cot θ_2 (e_2 · X).
      for (let k = 0; k < 3; k++) {
        const i = ids[k],
          j = ids[(k + 1) % 3],
          l = ids[(k + 2) % 3];
        const cotL = this.cots[3 * f + ((k + 2) % 3)]; // angle at l, opposite edge i-j
        const cotJ = this.cots[3 * f + ((k + 1) % 3)]; // angle at j, opposite edge i-l
        const e1 = (p[3 * j] - p[3 * i]) * Xx + (p[3 * j + 1] - p[3 * i + 1]) * Xy + (p[3 * j + 2] - p[3 * i + 2]) * Xz;
        const e2 = (p[3 * l] - p[3 * i]) * Xx + (p[3 * l + 1] - p[3 * i + 1]) * Xy + (p[3 * l + 2] - p[3 * i + 2]) * Xz;
        div[i] += 0.5 * (cotL * e1 + cotJ * e2);
      }
    }
    // Solve L φ = -div; remove the (round-off) constant component of the right-hand side first.
    let mean = 0;
    for (let i = 0; i < nv; i++) mean += div[i];
    mean /= nv;
    for (let i = 0; i < nv; i++) div[i] = -(div[i] - mean);
    const phi = this.poisson.solve(div);
    let shift = 0;
    for (let k = 0; k < sources.length; k++) shift += phi[sources[k]];
    shift /= sources.length;
    for (let i = 0; i < nv; i++) phi[i] -= shift;
    return phi;
  }
}

export interface GeodesicVoronoi {
  /** Per vertex: index (into siteVertexIds) of the nearest site. */
  labels: Int32Array;
  /** Per vertex: geodesic distance to that site. */
  distance: Float64Array;
}

/**
 * Geodesic Voronoi diagram on the mesh vertices: one heat-method distance field per site (on
 * one prepared solver, or the one passed in), each vertex labelled with its nearest site.
 */
export function geodesicVoronoi(mesh: TriangleMesh, siteVertexIds: ArrayLike<number>, solver = new HeatGeodesics(mesh)): GeodesicVoronoi {
  const nv = mesh.positions.length / 3;
  const labels = new Int32Array(nv).fill(-1);
  const distance = new Float64Array(nv).fill(Infinity);
  for (let s = 0; s < siteVertexIds.length; s++) {
    const d = solver.distance([siteVertexIds[s]]);
    for (let i = 0; i < nv; i++) {
      if (d[i] < distance[i]) {
        distance[i] = d[i];
        labels[i] = s;
      }
    }
  }
  return { labels, distance };
}
