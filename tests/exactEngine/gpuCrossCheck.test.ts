import { describe, expect, it } from 'vitest';
import { wrapDelta, type Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { neighbourSet } from '../../src/core/analysis/adjacency';
import { ExactLloydRun } from '../../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../../src/core/exactEngine/exactSurface';
import { useHeadlessContext } from '../gpu/context';
import { GpuEngine } from '../../src/gpu/engine';
import { gridLayout } from '../../src/gpu/layout';
import { GpuLloydRun, gridSites } from '../../src/gpu/lloyd';

const context = useHeadlessContext();

// The lab's tube (512 x 4096 texels, 200 cells about 100 texels across) and a plane with cells
// of the same size. Exact neighbour sets hinge on the shortest contacts, so the texel error of
// the GPU centroids must be small against a cell: the published resolution is the fair case.
const tube: Grid = { width: 512, height: 4096, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
const plane: Grid = { width: 1024, height: 1024, texelX: 1, texelY: 1, periodicX: false, periodicY: false };

describe('GPU and exact engines from the same initial sites', () => {
  for (const [name, grid, count] of [
    ['tube', tube, 200],
    ['plane', plane, 100],
  ] as const) {
    it(`${name}: after 5 iterations, sites within 0.5 texel RMS and identical neighbour sets on >= 99 % of cells`, () => {
      const options = { maxIterations: 5, tolerance: 0, overRelaxation: 1, warmStart: true };
      const initial = placeSites(grid, count, 17, 5);
      const gpuSites = initial.slice();
      const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath: 'auto' });
      try {
        const gpu = new GpuLloydRun(engine, gridSites(grid, gpuSites), options);
        while (!gpu.done) gpu.step();
      } finally {
        engine.dispose();
      }
      const exactSites = initial.slice();
      const exact = new ExactLloydRun(grid, exactSites, options);
      while (!exact.done) exact.step();
      expect(exact.iterations.map((r) => Object.keys(r).sort())).toEqual(
        exact.iterations.map(() => ['centroidMs', 'diagramMs', 'energy', 'iteration', 'jumpFloodPasses', 'maxDisplacement']),
      );

      let squared = 0;
      for (let i = 0; i < count; i++) {
        const dx = wrapDelta(gpuSites[2 * i] - exactSites[2 * i], grid.width, grid.periodicX);
        const dy = wrapDelta(gpuSites[2 * i + 1] - exactSites[2 * i + 1], grid.height, grid.periodicY);
        squared += dx * dx + dy * dy;
      }
      const rms = Math.sqrt(squared / count);
      expect(rms).toBeLessThan(0.5);

      const a = exactSurface(grid, gpuSites);
      const b = exactSurface(grid, exactSites);
      let same = 0;
      for (let i = 0; i < count; i++) if (neighbourSet(a, i).join() === neighbourSet(b, i).join()) same++;
      console.log(`${name}: sites ${rms.toFixed(3)} texel RMS apart, neighbour sets identical on ${same} of ${count} cells`);
      expect(same / count).toBeGreaterThanOrEqual(0.99);
    });
  }
});
