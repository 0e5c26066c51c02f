/**
 * labelAdjacency's contact lengths against the exact Voronoi diagram of the same sites
 * (src/core/exact.ts), on nearest-site labels from the brute-force oracle: the staircase
 * (sum of texel edges) is about 4/π too long; `lengths` must not be. Per resolution, the mean
 * label/exact ratio per contact and the per-cell agreement of neighbour sets after the lab's
 * minimum contact length is applied to both.
 */
import { describe, expect, it } from 'vitest';
import { labMinBoundaryLength } from '../../src/core/analysis/adjacency';
import { exactVoronoi } from '../../src/core/exact';
import type { Grid } from '../../src/core/grid';
import { labelAdjacency } from '../../src/core/labels';
import { createRandom } from '../../src/core/random';
import { contactAgreement } from '../oracles/contactAgreement';
import { bruteForceLabels } from '../oracles/labels';

/** Random sites in µm at least `spacing` apart (dart throwing), in a lengthX x lengthY box. */
function sitesUm(count: number, lengthX: number, lengthY: number, spacing: number, seed: number): Float64Array {
  const random = createRandom(seed);
  const out = new Float64Array(2 * count);
  let placed = 0;
  while (placed < count) {
    const x = random.next() * lengthX,
      y = random.next() * lengthY;
    let ok = true;
    for (let k = 0; k < placed && ok; k++) {
      let dx = Math.abs(out[2 * k] - x);
      dx = Math.min(dx, lengthX - dx); // periodic in x (harmless on the plane: only stricter)
      if (Math.hypot(dx, out[2 * k + 1] - y) < spacing) ok = false;
    }
    if (!ok) continue;
    out[2 * placed] = x;
    out[2 * placed + 1] = y;
    placed++;
  }
  return out;
}

const lengthX = 240,
  lengthY = 360,
  count = 150;
const spacing = 0.5 * Math.sqrt((lengthX * lengthY) / count);

function measure(periodicX: boolean, width: number, seed: number) {
  const height = Math.round((width * lengthY) / lengthX);
  const grid: Grid = { width, height, texelX: lengthX / width, texelY: lengthY / height, periodicX, periodicY: false };
  const um = sitesUm(count, lengthX, lengthY, spacing, seed);
  const sites = new Float32Array(2 * count);
  for (let k = 0; k < count; k++) {
    sites[2 * k] = um[2 * k] / grid.texelX;
    sites[2 * k + 1] = um[2 * k + 1] / grid.texelY;
  }
  const exact = exactVoronoi(grid, sites).adjacency as { offsets: Int32Array; neighbours: Int32Array; lengths: Float64Array };
  const nearest = bruteForceLabels(grid, sites);
  const staircaseLabels = labelAdjacency(grid, nearest, count, 'staircase');
  const labels = { ...labelAdjacency(grid, nearest, count), staircaseLengths: staircaseLabels.lengths };
  expect(staircaseLabels.neighbours).toEqual(labels.neighbours);
  const minLength = labMinBoundaryLength(lengthX * lengthY, count);
  const texel = Math.max(grid.texelX, grid.texelY);
  const unbiased = contactAgreement(labels, exact, count, texel, minLength);
  const staircase = contactAgreement({ ...labels, lengths: labels.staircaseLengths }, exact, count, texel, minLength);
  return { grid, labels, unbiased, staircase, minLength };
}

describe('labelAdjacency contact lengths against the exact Voronoi diagram', () => {
  for (const periodicX of [false, true]) {
    it(`${periodicX ? 'tube' : 'plane'}: unbiased at every resolution, and neighbour sets agree at least as often as with the staircase`, () => {
      const rows: string[] = [];
      for (const width of [60, 120, 240, 480]) {
        const runs = [1, 2].map((seed) => measure(periodicX, width, seed + (periodicX ? 10 : 0)));
        const mean = (f: (r: (typeof runs)[number]) => number) => runs.reduce((s, r) => s + f(r), 0) / runs.length;
        const ratio = mean((r) => r.unbiased.meanRatio),
          total = mean((r) => r.unbiased.totalRatio);
        const oldRatio = mean((r) => r.staircase.meanRatio);
        const agree = mean((r) => r.unbiased.cellAgreement),
          oldAgree = mean((r) => r.staircase.cellAgreement);
        const { grid, minLength } = runs[0];
        rows.push(
          `${width}x${grid.height} texel ${grid.texelX.toFixed(2)} µm (threshold ${minLength.toFixed(2)} µm): ratio ${ratio.toFixed(3)} (Σ ${total.toFixed(3)}; staircase ${oldRatio.toFixed(3)}), cells agreeing ${(100 * agree).toFixed(1)} % (staircase ${(100 * oldAgree).toFixed(1)} %)`,
        );
        expect(Math.abs(ratio - 1), `mean ratio at ${width}`).toBeLessThan(0.03);
        expect(Math.abs(total - 1), `total ratio at ${width}`).toBeLessThan(0.03);
        expect(oldRatio, 'the staircase is biased (the comparison can tell)').toBeGreaterThan(1.15);
        expect(agree, `agreement at ${width}`).toBeGreaterThanOrEqual(oldAgree);
        for (const r of runs) {
          // Only the lengths changed: same pairs, and never longer than the staircase, never
          // shorter than 1/sqrt(2) of it.
          for (let k = 0; k < r.labels.lengths.length; k++) {
            expect(r.labels.lengths[k]).toBeLessThanOrEqual(r.labels.staircaseLengths[k] + 1e-12);
            expect(r.labels.lengths[k]).toBeGreaterThanOrEqual(r.labels.staircaseLengths[k] / Math.SQRT2 - 1e-12);
          }
        }
      }
      console.log(`${periodicX ? 'tube' : 'plane'}, ${count} cells, ${lengthX} x ${lengthY} µm:\n  ${rows.join('\n  ')}`);
    });
  }

  it('measures a straight boundary at any angle to within one texel edge per end', () => {
    const grid: Grid = { width: 200, height: 150, texelX: 0.5, texelY: 0.8, periodicX: false, periodicY: false };
    for (const angle of [0, 0.2, 0.5, Math.PI / 4, 1.1, 1.5]) {
      // Two sites mirrored about a line through the centre: their bisector is that line.
      const cx = 100,
        cy = 75,
        d = 10;
      const nx = Math.cos(angle),
        ny = Math.sin(angle); // unit normal of the boundary in µm
      const sites = Float32Array.from([(cx * 0.5 - d * nx) / 0.5, (cy * 0.8 - d * ny) / 0.8, (cx * 0.5 + d * nx) / 0.5, (cy * 0.8 + d * ny) / 0.8]);
      const labels = labelAdjacency(grid, bruteForceLabels(grid, sites), 2);
      const exact = exactVoronoi(grid, sites).cells[0].lengths[0];
      expect(Math.abs(labels.lengths[0] - exact), `angle ${angle}`).toBeLessThanOrEqual(2 * 0.8 + 1e-9);
    }
  });
});
