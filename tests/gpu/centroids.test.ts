import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { bruteForceLabels, reduceCentroids } from '../oracles/labels';
import { placeSites } from '../../src/core/sites';
import { useHeadlessContext } from './context';
import { GpuEngine } from '../../src/gpu/engine';
import { gridLayout } from '../../src/gpu/layout';

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
  // The blend path (the default on a GPU) needs EXT_float_blend: headless-gl has none (it runs
  // in e2e/centroidPaths.spec.ts on Chromium), a machine whose GL driver has it runs it here.
  for (const centroidPath of ['blend', 'gather', 'readback'] as const)
    for (const [name, grid, count] of cases) {
      for (const weighted of [false, true]) {
        it.skipIf(centroidPath === 'blend' && !context.capabilities.floatBlend)(
          `${centroidPath}, ${name}, ${weighted ? 'Gaussian density' : 'uniform density'}: centroids within 1e-3 texel`,
          () => {
            const sites = placeSites(grid, count, 5, 2);
            const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath });
            try {
              const weights = weighted ? gaussianWeights(grid) : null;
              if (weights) engine.setGeometry(weights);
              engine.setSites(sites);
              engine.floodLabels();
              const gpu = engine.computeSums();
              const cpu = reduceCentroids(grid, engine.readLabels(), sites, weights);
              let worst = 0;
              for (let i = 0; i < count; i++) {
                expect(gpu[5 * i + 3]).toBeGreaterThan(0);
                const dx = gpu[5 * i] / gpu[5 * i + 3] - cpu[4 * i] / cpu[4 * i + 2];
                const dy = gpu[5 * i + 1] / gpu[5 * i + 3] - cpu[4 * i + 1] / cpu[4 * i + 2];
                worst = Math.max(worst, Math.hypot(dx, dy));
                // The cell's energy (w * d² summed) agrees to float32 summation accuracy.
                expect(Math.abs(gpu[5 * i + 4] - cpu[4 * i + 3])).toBeLessThanOrEqual(1e-4 * cpu[4 * i + 3] + 1e-6);
              }
              expect(worst).toBeLessThanOrEqual(1e-3);
            } finally {
              engine.dispose();
            }
          },
        );
      }
    }

  it('readback reads a grid in several bands: labels match brute force, sums match the CPU and gather', () => {
    // 1100 x 1000 texels: two readback bands of 953 and 47 rows (bands hold 2^20 texels).
    const grid: Grid = { width: 1100, height: 1000, texelX: 1, texelY: 1.5, periodicX: true, periodicY: false };
    const count = 400;
    const sites = placeSites(grid, count, 9, 4);
    const weights = gaussianWeights(grid);
    const sums: Float64Array[] = [];
    for (const centroidPath of ['readback', 'gather'] as const) {
      const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath });
      try {
        engine.setGeometry(weights);
        engine.setSites(sites);
        engine.floodLabels();
        sums.push(engine.computeSums().slice());
        if (centroidPath === 'readback') {
          const labels = engine.readLabels();
          const reference = bruteForceLabels(grid, sites);
          let wrong = 0;
          for (let i = 0; i < reference.length; i++) if (labels[i] !== reference[i]) wrong++;
          expect(wrong / reference.length).toBeLessThanOrEqual(1e-4);
          // Band by band on the engine's packed ids = all rows at once on the ids read back.
          const cpu = reduceCentroids(grid, labels, sites, weights);
          for (let k = 0; k < 4 * count; k++) {
            const gpu = sums[0][5 * (k >> 2) + [0, 1, 3, 4][k & 3]];
            expect(Math.abs(gpu - cpu[k])).toBeLessThanOrEqual(1e-6 * Math.abs(cpu[k]) + 1e-3);
          }
        }
      } finally {
        engine.dispose();
      }
    }
    // Gather sums in float32 on the GPU: over cells of up to ~8,000 weighted texels whose
    // random first sites lie ~20 texels off their centroids, that costs up to ~3e-3 texel.
    const [readback, gather] = sums;
    for (let i = 0; i < count; i++) {
      expect(readback[5 * i + 3]).toBeGreaterThan(0);
      const dx = readback[5 * i] / readback[5 * i + 3] - gather[5 * i] / gather[5 * i + 3];
      const dy = readback[5 * i + 1] / readback[5 * i + 3] - gather[5 * i + 1] / gather[5 * i + 3];
      expect(Math.hypot(dx, dy)).toBeLessThanOrEqual(5e-3);
      expect(Math.abs(readback[5 * i + 4] - gather[5 * i + 4])).toBeLessThanOrEqual(1e-4 * gather[5 * i + 4]);
    }
  });

  it('gather: a thin sliver owning texels past its window but none on its ring is summed whole', () => {
    // Site 0's cell is a band 0.7 texel wide at 0.35 rad between sites 1 and 2, closed by sites
    // 3 and 4 18 texels along it (every site in a texel of its own): 12 texels at Chebyshev
    // distances 0-3 and 5-8 from the site's texel, none at 4. Once the cell's area is known (the
    // second sum, as in a converged loop) its window has radius 4: the band crosses that ring
    // between texel centres. Found by bench/gpuCheck.ts (a 512², 10,000-site plane lost such a texel).
    const grid: Grid = { width: 64, height: 64, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const theta = 0.35;
    const [cx, cy] = [32.1, 32.3];
    const [ux, uy] = [Math.cos(theta), Math.sin(theta)];
    const [nx, ny] = [-uy, ux];
    const sites = Float32Array.from([
      cx,
      cy,
      cx + 0.5 * nx,
      cy + 0.5 * ny,
      cx - 0.5 * nx,
      cy - 0.5 * ny,
      cx + 18 * ux,
      cy + 18 * uy,
      cx - 18 * ux,
      cy - 18 * uy,
    ]);
    const engine = new GpuEngine(context, gridLayout(grid), 5, { variant: 'jfa+2', centroidPath: 'gather' });
    try {
      engine.setSites(sites);
      engine.floodLabels();
      engine.computeSums();
      const gpu = engine.computeSums();
      const labels = engine.readLabels();
      // The case holds on the GPU's own labels: texels past radius 4, none on it.
      const distances: number[] = [];
      labels.forEach((label, k) => label === 0 && distances.push(Math.max(Math.abs((k % 64) - 32), Math.abs(Math.floor(k / 64) - 32))));
      expect(distances.some((d) => d > 4)).toBe(true);
      expect(distances).not.toContain(4);
      expect(engine.gatherStats!.lastRetries).toBeGreaterThan(0);
      const cpu = reduceCentroids(grid, labels, sites, null);
      for (let i = 0; i < 5; i++) {
        expect(gpu[5 * i + 3]).toBe(cpu[4 * i + 2]);
        expect(Math.abs(gpu[5 * i] - cpu[4 * i])).toBeLessThanOrEqual(1e-3 * cpu[4 * i + 2]);
        expect(Math.abs(gpu[5 * i + 1] - cpu[4 * i + 1])).toBeLessThanOrEqual(1e-3 * cpu[4 * i + 2]);
      }
    } finally {
      engine.dispose();
    }
  });

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
    const last = 5 * (count - 1);
    const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath: 'gather' });
    try {
      engine.setSites(sites);
      engine.floodLabels();
      const gpu = engine.computeSums();
      const cpu = reduceCentroids(grid, engine.readLabels(), sites, null);
      expect(engine.gatherStats!.lastRetries).toBeGreaterThan(0);
      expect(gpu[last + 3]).toBe(cpu[4 * (count - 1) + 2]);
      expect(gpu[last] / gpu[last + 3]).toBeCloseTo(cpu[4 * (count - 1)] / cpu[4 * (count - 1) + 2], 3);
      // The retry summed only the overflowing cells and passed every other cell's sums on.
      for (let i = 0; i < count; i++) {
        expect(gpu[5 * i + 3]).toBe(cpu[4 * i + 2]);
        expect(Math.abs(gpu[5 * i] - cpu[4 * i])).toBeLessThanOrEqual(1e-3 * cpu[4 * i + 2]);
        expect(Math.abs(gpu[5 * i + 1] - cpu[4 * i + 1])).toBeLessThanOrEqual(1e-3 * cpu[4 * i + 2]);
      }
    } finally {
      engine.dispose();
    }
  });
});
