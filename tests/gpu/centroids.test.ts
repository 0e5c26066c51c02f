import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { reduceCentroids } from '../../src/core/labels';
import { placeSites } from '../../src/core/sites';
import { CcvtEngine } from '../../src/gpu/engine';
import { useHeadlessContext } from './context';

const context = useHeadlessContext();

function gaussianWeights(grid: Grid): Float32Array {
  const weights = new Float32Array(grid.width * grid.height);
  for (let y = 0; y < grid.height; y++) {
    for (let x = 0; x < grid.width; x++) {
      const r2 = ((x - grid.width / 3) ** 2 + (y - grid.height / 2) ** 2) / (grid.width * grid.width * 0.02);
      weights[y * grid.width + x] = 1 + 9 * Math.exp(-r2);
    }
  }
  return weights;
}

describe('centroid pass against a CPU reduction of the same labels', () => {
  const cases: Array<[string, Grid, number]> = [
    ['plane', { width: 200, height: 150, texelX: 1, texelY: 1, periodicX: false, periodicY: false }, 120],
    ['tube', { width: 96, height: 300, texelX: 1.05, texelY: 1, periodicX: true, periodicY: false }, 40],
    ['periodic plane, one cell', { width: 64, height: 64, texelX: 1, texelY: 1, periodicX: true, periodicY: true }, 1],
  ];
  for (const [name, grid, count] of cases) {
    for (const weighted of [false, true]) {
      it(`${name}, ${weighted ? 'Gaussian density' : 'uniform density'}: centroids within 1e-3 texel`, () => {
        const sites = placeSites(grid, count, 5, 2);
        const engine = new CcvtEngine(context, grid, count, { variant: 'jfa+2', centroidPath: 'gather' });
        try {
          const weights = weighted ? gaussianWeights(grid) : null;
          if (weights) engine.setWeights(weights);
          engine.setSites(sites);
          engine.floodLabels();
          const gpu = engine.computeSums();
          const cpu = reduceCentroids(grid, engine.readLabels(), sites, weights);
          let worst = 0;
          for (let i = 0; i < count; i++) {
            expect(gpu[4 * i + 2]).toBeGreaterThan(0);
            const dx = gpu[4 * i] / gpu[4 * i + 2] - cpu[4 * i] / cpu[4 * i + 2];
            const dy = gpu[4 * i + 1] / gpu[4 * i + 2] - cpu[4 * i + 1] / cpu[4 * i + 2];
            worst = Math.max(worst, Math.hypot(dx, dy));
            // The cell's energy (w * d² summed) agrees to float32 summation accuracy.
            expect(Math.abs(gpu[4 * i + 3] - cpu[4 * i + 3])).toBeLessThanOrEqual(1e-4 * cpu[4 * i + 3] + 1e-6);
          }
          expect(worst).toBeLessThanOrEqual(1e-3);
        } finally {
          engine.dispose();
        }
      });
    }
  }

  it('grows the gather window instead of returning a truncated centroid', () => {
    const grid: Grid = { width: 256, height: 64, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    // 40 sites crowded at one end: the last cell reaches ~230 texels, far past the first
    // window, which is sized for cells of average area.
    const count = 40;
    const sites = new Float32Array(2 * count);
    for (let i = 0; i < count - 1; i++) {
      sites[2 * i] = 2.5 + 3 * (i % 6);
      sites[2 * i + 1] = 4.5 + 9 * Math.floor(i / 6);
    }
    sites[2 * (count - 1)] = 25.5;
    sites[2 * (count - 1) + 1] = 30.5;
    const last = 4 * (count - 1);
    const engine = new CcvtEngine(context, grid, count, { variant: 'jfa+2', centroidPath: 'gather' });
    try {
      
      engine.setSites(sites);
      engine.floodLabels();
      const gpu = engine.computeSums();
      const cpu = reduceCentroids(grid, engine.readLabels(), sites, null);
      expect(engine.gatherStats!.lastRetries).toBeGreaterThan(0);
      expect(gpu[last + 2]).toBe(cpu[last + 2]);
      expect(gpu[last] / gpu[last + 2]).toBeCloseTo(cpu[last] / cpu[last + 2], 3);
      // The retry summed only the overflowing cells and passed every other cell's sums on.
      for (let i = 0; i < count; i++) {
        expect(gpu[4 * i + 2]).toBe(cpu[4 * i + 2]);
        expect(Math.abs(gpu[4 * i] - cpu[4 * i])).toBeLessThanOrEqual(1e-3 * cpu[4 * i + 2]);
        expect(Math.abs(gpu[4 * i + 1] - cpu[4 * i + 1])).toBeLessThanOrEqual(1e-3 * cpu[4 * i + 2]);
      }
    } finally {
      engine.dispose();
    }
  });
});
