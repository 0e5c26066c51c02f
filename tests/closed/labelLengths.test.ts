/**
 * cubeLabelAdjacency's contact lengths against the restricted Voronoi diagram of the same sites
 * (src/core/closed/restrictedVoronoi.ts; exact on the sphere, tests/closed/restrictedSphere),
 * on nearest-site cube-map labels from the brute-force reference (cubeBruteForceLabels). The
 * staircase (`staircaseLengths`) is about 4/π too long; `lengths` must not be. Per resolution:
 * the mean label/exact ratio per contact and the per-cell agreement of neighbour sets after
 * the lab's minimum contact length is applied to both.
 */
import { describe, expect, it } from 'vitest';
import { labMinBoundaryLength } from '../../src/core/analysis/adjacency';
import { cubeLabelAdjacency } from '../../src/core/closed/geometry';
import { cubeBruteForceLabels } from '../oracles/cubeMap';
import { randomSequentialSites } from './randomSequentialSites';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import { sphereSurface, type EllipsoidGeometry } from '../../src/core/closed/restrictedSurface';
import { sampleSurface } from '../../src/core/cubemap/sample';
import { contactAgreement } from '../oracles/contactAgreement';

const count = 200;

function measure(surface: EllipsoidGeometry, n: number, seed: number) {
  const { a, b, c } = surface;
  const exactArea = restrictedVoronoi(surface, new Float64Array([a, 0, 0]), 1).surfaceArea;
  const diameter = Math.sqrt(exactArea / count);
  const sites = randomSequentialSites(surface, count, 0.5 * diameter, seed).positions;
  const exact = restrictedVoronoi(surface, sites, count).adjacency as { offsets: Int32Array; neighbours: Int32Array; lengths: Float64Array };
  const image = sampleSurface({ kind: 'ellipsoid', a, b, c }, n);
  const sample = { n, position: image.position, area: image.area, totalArea: image.totalArea };
  const nearest = cubeBruteForceLabels(image.position, sites, count);
  const staircase = cubeLabelAdjacency(sample, nearest, count, undefined, 'staircase');
  const labels = { ...cubeLabelAdjacency(sample, nearest, count), staircaseLengths: staircase.lengths };
  expect(staircase.neighbours).toEqual(labels.neighbours);
  const texel = Math.sqrt(exactArea / (6 * n * n));
  const minLength = labMinBoundaryLength(exactArea, count);
  return {
    labels,
    texel,
    minLength,
    unbiased: contactAgreement(labels, exact, count, texel, minLength),
    staircase: contactAgreement({ ...labels, lengths: labels.staircaseLengths }, exact, count, texel, minLength),
  };
}

const surfaces: [string, EllipsoidGeometry][] = [
  ['sphere R 50', sphereSurface(50)],
  ['ellipsoid 90:45:45', { kind: 'ellipsoid', a: 90, b: 45, c: 45 }],
];

describe('cubeLabelAdjacency contact lengths against the restricted Voronoi diagram', () => {
  for (const [name, surface] of surfaces) {
    it(`${name}, ${count} cells: unbiased at 32..256 texels per face edge`, () => {
      const rows: string[] = [];
      for (const n of [32, 64, 128, 256]) {
        const runs = (n <= 128 ? [1, 2] : [1]).map((seed) => measure(surface, n, seed));
        const mean = (f: (r: (typeof runs)[number]) => number) => runs.reduce((s, r) => s + f(r), 0) / runs.length;
        const ratio = mean((r) => r.unbiased.meanRatio),
          total = mean((r) => r.unbiased.totalRatio);
        const oldRatio = mean((r) => r.staircase.meanRatio);
        const agree = mean((r) => r.unbiased.cellAgreement),
          oldAgree = mean((r) => r.staircase.cellAgreement);
        rows.push(
          `n ${n}, texel ${runs[0].texel.toFixed(2)} µm (threshold ${runs[0].minLength.toFixed(2)} µm): ratio ${ratio.toFixed(3)} (Σ ${total.toFixed(3)}; staircase ${oldRatio.toFixed(3)}), cells agreeing ${(100 * agree).toFixed(1)} % (staircase ${(100 * oldAgree).toFixed(1)} %)`,
        );
        // Within 3 % from n 64 up (one texel edge at each end of a contact of >= 3 texels: 5 %
        // at n 32, where the staircase's ends weigh most).
        const tolerance = n >= 64 ? 0.03 : 0.05;
        expect(Math.abs(ratio - 1), `mean ratio at n ${n}`).toBeLessThan(tolerance);
        expect(Math.abs(total - 1), `total ratio at n ${n}`).toBeLessThan(tolerance);
        expect(oldRatio, 'the staircase is biased (the comparison can tell)').toBeGreaterThan(1.15);
        // Neighbour sets: never clearly worse than the staircase's; where a texel edge is at
        // most half the minimum contact length (defaultResolution's rule), >= 95 % of cells.
        expect(agree, `agreement at n ${n}`).toBeGreaterThanOrEqual(oldAgree - 0.01);
        if (runs[0].texel <= runs[0].minLength / 2) expect(agree, `agreement at n ${n}`).toBeGreaterThanOrEqual(0.95);
        for (const r of runs) {
          // Same pairs as the staircase, and a positive length for every one of them.
          expect(r.labels.lengths.length).toBe(r.labels.staircaseLengths.length);
          for (let k = 0; k < r.labels.lengths.length; k++) expect(r.labels.lengths[k]).toBeGreaterThan(0);
        }
      }
      console.log(`${name}, ${count} RSA cells:\n  ${rows.join('\n  ')}`);
    });
  }

  // Per face the length is the chord of the contact's piece there: a contact that crosses a
  // whole face (two cells) comes out at 2 sqrt(2) / π = 0.90 of a great circle, kept and long.
  it('keeps a contact that goes all round the surface: two cells on a sphere share the equator', () => {
    const R = 30,
      n = 48;
    const image = sampleSurface({ kind: 'sphere', radius: R }, n);
    const sites = Float64Array.from([0, 0, R, 0.3, 0.2, -R]); // near the poles
    const norm = (k: number) => Math.hypot(sites[3 * k], sites[3 * k + 1], sites[3 * k + 2]);
    for (const k of [0, 1]) for (let c = 0; c < 3; c++) sites[3 * k + c] *= R / norm(k);
    const exact = restrictedVoronoi(sphereSurface(R), sites, 2).adjacency.lengths![0];
    const sample = { n, position: image.position, area: image.area, totalArea: image.totalArea };
    const nearest = cubeBruteForceLabels(image.position, sites, 2);
    const labels = { ...cubeLabelAdjacency(sample, nearest, 2), staircaseLengths: cubeLabelAdjacency(sample, nearest, 2, undefined, 'staircase').lengths };
    console.log(`two cells: exact ${exact.toFixed(2)} µm, labels ${labels.lengths[0].toFixed(2)} µm, staircase ${labels.staircaseLengths[0].toFixed(2)} µm`);
    expect(labels.lengths[0] / exact).toBeGreaterThan(0.95 * ((2 * Math.SQRT2) / Math.PI));
    expect(labels.lengths[0] / exact).toBeLessThan(1.02);
  });
});
