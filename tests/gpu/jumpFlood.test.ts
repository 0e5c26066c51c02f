import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { coldSchedule } from '../../src/core/jumpSchedule';
import { bruteForceLabels } from '../oracles/labels';
import { placeSites } from '../../src/core/sites';
import { mislabeledFraction, useHeadlessContext } from './context';
import { GpuEngine } from '../../src/gpu/engine';
import { gridLayout } from '../../src/gpu/layout';
import { GpuLloydRun, gridSites } from '../../src/gpu/lloyd';

const context = useHeadlessContext();

const plane: Grid = { width: 192, height: 160, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
const torus: Grid = { width: 160, height: 192, texelX: 1, texelY: 1, periodicX: true, periodicY: true };
// A tube unrolled: x runs around (periodic), y along the axis; texels a little anisotropic.
const tube: Grid = { width: 128, height: 256, texelX: 0.98, texelY: 1, periodicX: true, periodicY: false };

// Sites closer than a texel fall into one texel and cannot both be splatted: keep them apart.
const minSpacingTexels = 1.5;

describe('jump flood against brute-force nearest site', () => {
  for (const [name, grid] of [
    ['plane', plane],
    ['periodic plane', torus],
    ['tube', tube],
  ] as const) {
    for (const count of [1, 2, 7, 60, 500, 2000]) {
      it(`${name}, ${count} sites: at most 1e-4 of texels mislabeled (jfa+2)`, () => {
        const sites = placeSites(grid, count, 1000 + count, minSpacingTexels * grid.texelX);
        const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath: 'auto' });
        try {
          engine.setSites(sites);
          engine.floodLabels();
          const error = mislabeledFraction(engine.readLabels(), bruteForceLabels(grid, sites));
          expect(error).toBeLessThanOrEqual(1e-4);
        } finally {
          engine.dispose();
        }
      });
    }
  }

  // Warm floods over whole Lloyd runs (12 iterations, sites moving tens of texels at first and
  // a fraction of a texel at the end), each iteration compared with brute force and with a cold
  // jfa+2 flood of the same sites.
  for (const [name, grid, count] of [
    ['tube', tube, 400],
    ['periodic plane', torus, 2000],
    ['plane', plane, 150],
  ] as const) {
    it(`${name}, ${count} sites: warm starts stay within the cold flood's error bound`, () => {
      const sites = placeSites(grid, count, 7, minSpacingTexels * grid.texelX);
      const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath: 'auto' });
      const cold = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath: 'auto' });
      try {
        const run = new GpuLloydRun(engine, gridSites(grid, sites), { maxIterations: 12, tolerance: 0, overRelaxation: 1, warmStart: true });
        let worstWarm = 0;
        let worstCold = 0;
        while (!run.done) {
          run.step();
          const reference = bruteForceLabels(grid, run.sites);
          worstWarm = Math.max(worstWarm, mislabeledFraction(engine.readLabels(), reference));
          cold.setSites(run.sites);
          cold.floodLabels();
          worstCold = Math.max(worstCold, mislabeledFraction(cold.readLabels(), reference));
        }
        expect(worstWarm).toBeLessThanOrEqual(1e-4);
        expect(worstWarm).toBeLessThanOrEqual(Math.max(worstCold, 2 / (grid.width * grid.height)));
        // Once sites move by a texel or two the warm flood runs two passes, a cold one 10 or more.
        const coldPasses = coldSchedule(grid.width, grid.height, 'jfa+2').length;
        expect(run.iterations.at(-1)!.jumpFloodPasses).toBeLessThanOrEqual(2);
        expect(coldPasses).toBeGreaterThanOrEqual(10);
      } finally {
        engine.dispose();
        cold.dispose();
      }
    });
  }

  it('plain JFA is measurably worse than jfa+2 on many sites (the variant matters)', () => {
    const grid = plane;
    const sites = placeSites(grid, 2000, 99, minSpacingTexels);
    const reference = bruteForceLabels(grid, sites);
    const errors: Record<string, number> = {};
    for (const variant of ['jfa', 'jfa+2', '1+jfa'] as const) {
      const engine = new GpuEngine(context, gridLayout(grid), 2000, { variant, centroidPath: 'auto' });
      engine.setSites(sites);
      engine.floodLabels();
      errors[variant] = mislabeledFraction(engine.readLabels(), reference);
      engine.dispose();
    }
    expect(errors['jfa+2']).toBeLessThanOrEqual(errors['jfa']);
    expect(errors['1+jfa']).toBeLessThanOrEqual(1e-3);
  });
});
