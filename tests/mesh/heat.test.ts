import { describe, expect, it } from 'vitest';
import { icosphere, mulberry32 } from '../../src/core/mesh/generate';
import { cotanLaplacian, geodesicVoronoi, HeatGeodesics, lumpedMass } from '../../src/core/mesh/heat';
import { csrAddDiagonal, SparseCholesky, type CsrMatrix } from '../../src/core/mesh/sparse';
import { meanEdgeLength } from '../../src/core/mesh/types';
import { loadShipped, surfaceArea } from './helpers';

/** y = A x, from the CSR layout's definition. */
function csrMultiply(A: CsrMatrix, x: ArrayLike<number>): Float64Array {
  const y = new Float64Array(A.n);
  for (let i = 0; i < A.n; i++) {
    for (let p = A.rowPtr[i]; p < A.rowPtr[i + 1]; p++) y[i] += A.values[p] * x[A.colIdx[p]];
  }
  return y;
}

const dot = (p: Float32Array, a: number, b: number) => p[3 * a] * p[3 * b] + p[3 * a + 1] * p[3 * b + 1] + p[3 * a + 2] * p[3 * b + 2];
const greatCircle = (p: Float32Array, a: number, b: number) => Math.acos(Math.min(1, Math.max(-1, dot(p, a, b))));

describe('cotangent Laplacian and mass matrix', () => {
  const mesh = icosphere(8);
  const L = cotanLaplacian(mesh);
  const M = lumpedMass(mesh);
  it('rows sum to 0, symmetric, mass sums to the surface area', () => {
    const ones = new Float64Array(L.n).fill(1);
    for (const r of csrMultiply(L, ones)) expect(Math.abs(r)).toBeLessThan(1e-12);
    const dense = new Map<string, number>();
    for (let i = 0; i < L.n; i++) for (let p = L.rowPtr[i]; p < L.rowPtr[i + 1]; p++) dense.set(`${i},${L.colIdx[p]}`, L.values[p]);
    for (const [k, v] of dense) {
      const [i, j] = k.split(',');
      expect(dense.get(`${j},${i}`)).toBeCloseTo(v, 14);
    }
    expect(M.reduce((s, x) => s + x, 0)).toBeCloseTo(surfaceArea(mesh), 10);
  });
  it('Dirichlet energy of a linear function x equals ∫|∇x|² ≈ (2/3) of the area on a unit sphere', () => {
    // ∫_S |∇_S x|² = ∫ (1 - x²) = 4π - 4π/3 = 8π/3.
    const x = Float64Array.from({ length: L.n }, (_, i) => mesh.positions[3 * i]);
    const Lx = csrMultiply(L, x);
    const energy = x.reduce((s, xi, i) => s + xi * Lx[i], 0);
    expect(energy / ((8 * Math.PI) / 3)).toBeCloseTo(1, 2);
  });
  it('sparse Cholesky solves (L + M) x = b to round-off, with far less fill than dense', () => {
    const A = csrAddDiagonal(L, M);
    const chol = new SparseCholesky(A);
    const rnd = mulberry32(3);
    const b = Float64Array.from({ length: A.n }, () => rnd() - 0.5);
    const x = chol.solve(b);
    const r = csrMultiply(A, x);
    let err = 0;
    for (let i = 0; i < A.n; i++) err = Math.max(err, Math.abs(r[i] - b[i]));
    expect(err).toBeLessThan(1e-10);
    expect(chol.nnz).toBeLessThan((A.n * A.n) / 20);
  });
});

describe('heat method geodesics', () => {
  it('on a fine unit sphere, distance from a pole matches the great-circle distance (mean relative error < 3 %)', () => {
    const mesh = icosphere(20); // 4002 vertices
    let src = 0;
    const p = mesh.positions;
    for (let i = 0; i < p.length / 3; i++) if (p[3 * i + 2] > p[3 * src + 2]) src = i;
    const d = new HeatGeodesics(mesh).distance([src]);
    const h = meanEdgeLength(mesh);
    let rel = 0,
      count = 0,
      maxAbs = 0;
    for (let i = 0; i < d.length; i++) {
      const g = greatCircle(p, src, i);
      maxAbs = Math.max(maxAbs, Math.abs(d[i] - g));
      if (g < 3 * h) continue; // relative error is meaningless right at the source
      rel += Math.abs(d[i] - g) / g;
      count++;
    }
    expect(d[src]).toBe(0);
    expect(rel / count).toBeLessThan(0.03);
    expect(maxAbs).toBeLessThan(0.1); // ~3 % of π, also at the antipode
  });

  it('two sources give the minimum of the two single-source fields (approximately)', () => {
    const mesh = icosphere(10);
    const solver = new HeatGeodesics(mesh);
    const a = solver.distance([0]),
      b = solver.distance([100]);
    const ab = solver.distance([0, 100]);
    let err = 0;
    for (let i = 0; i < ab.length; i++) err += Math.abs(ab[i] - Math.min(a[i], b[i]));
    // Near the bisector the multi-source field is smoother than the exact minimum (a known
    // trait of the heat method), so the bound is looser than the single-source accuracy; using
    // only one of the sources would give ~0.5.
    expect(err / ab.length).toBeLessThan(0.05);
  });

  it('geodesic Voronoi on a sphere agrees with the great-circle Voronoi except near cell borders', () => {
    const mesh = icosphere(12);
    const p = mesh.positions;
    const nv = p.length / 3;
    const rnd = mulberry32(9);
    const sites = [...new Set(Array.from({ length: 10 }, () => Math.floor(rnd() * nv)))];
    const { labels, distance } = geodesicVoronoi(mesh, sites);
    sites.forEach((s, k) => expect(labels[s]).toBe(k)); // each site is in its own cell
    let agree = 0;
    for (let i = 0; i < nv; i++) {
      let best = 0;
      for (let k = 1; k < sites.length; k++) if (greatCircle(p, sites[k], i) < greatCircle(p, sites[best], i)) best = k;
      if (labels[i] === best) agree++;
      expect(distance[i]).toBeGreaterThanOrEqual(-1e-9);
    }
    expect(agree / nv).toBeGreaterThan(0.95);
  });

  // Its speed is a measurement: bench/cpuReferences.ts.
  it('14-site geodesic Voronoi on the shipped ~9,000-vertex mesh gives every site a cell', () => {
    const mesh = loadShipped('level-set-blob.ply');
    const nv = mesh.positions.length / 3;
    expect(nv).toBeGreaterThan(8000);
    const solver = new HeatGeodesics(mesh);
    const sites = Array.from({ length: 14 }, (_, k) => Math.floor(((k + 0.5) * nv) / 14));
    const { labels } = geodesicVoronoi(mesh, sites, solver);
    expect(new Set(labels).size).toBe(14);
  });
});
