import { describe, expect, it } from 'vitest';
import { exactVoronoi } from '../../src/core/exact';
import { wrapDelta, type Grid } from '../../src/core/grid';
import { moveSitesToCentroids } from '../../src/core/lloydUpdate';
import { placeSites } from '../../src/core/sites';
import { useHeadlessContext } from './context';
import { GpuEngine, SUMS_STRIDE } from '../../src/gpu/engine';
import { gridLayout } from '../../src/gpu/layout';
import { GpuLloydRun, gridSites } from '../../src/gpu/lloyd';

const context = useHeadlessContext();

const plane: Grid = { width: 256, height: 200, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
const tube: Grid = { width: 128, height: 320, texelX: 1.01, texelY: 1, periodicX: true, periodicY: false };

describe('one Lloyd step against exact Voronoi centroids (d3-delaunay)', () => {
  for (const [name, grid, count] of [
    ['plane', plane, 120],
    ['tube (tripled sites)', tube, 80],
  ] as const) {
    it(`${name}: mean centroid error <= 0.25 texel`, () => {
      const sites = placeSites(grid, count, 11, 2);
      const exact = exactVoronoi(grid, sites);
      const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath: 'auto' });
      try {
        engine.setSites(sites);
        engine.floodLabels();
        const moved = sites.slice();
        moveSitesToCentroids(
          grid,
          moved,
          engine.computeSums(),
          count,
          1,
          {
            energy: 0,
            maxDisplacement: 0,
            maxDisplacementTexels: 0,
            emptyCells: 0,
          },
          SUMS_STRIDE,
        );
        let total = 0;
        for (let i = 0; i < count; i++) {
          const dx = wrapDelta(moved[2 * i] - exact.centroids[2 * i], grid.width, grid.periodicX);
          const dy = wrapDelta(moved[2 * i + 1] - exact.centroids[2 * i + 1], grid.height, grid.periodicY);
          total += Math.hypot(dx, dy);
        }
        expect(total / count).toBeLessThanOrEqual(0.25);
      } finally {
        engine.dispose();
      }
    });
  }
});

describe('Lloyd loop', () => {
  const options = { maxIterations: 15, tolerance: 0, overRelaxation: 1, warmStart: true };

  it('never increases the CVT energy under plain Lloyd', () => {
    const sites = placeSites(tube, 150, 3, 1.5);
    const engine = new GpuEngine(context, gridLayout(tube), 150, { variant: 'jfa+2', centroidPath: 'auto' });
    try {
      const run = new GpuLloydRun(engine, gridSites(tube, sites), options);
      while (!run.done) run.step();
      const energies = [...run.iterations.map((r) => r.energy), run.finish().energy];
      for (let k = 1; k < energies.length; k++) expect(energies[k]).toBeLessThanOrEqual(energies[k - 1] * (1 + 1e-6));
      expect(energies.at(-1)!).toBeLessThan(energies[0] * 0.9);
    } finally {
      engine.dispose();
    }
  });

  it('gives bit-identical sites for the same seed', () => {
    const results = [0, 1].map(() => {
      const sites = placeSites(plane, 90, 21, 1.5);
      const engine = new GpuEngine(context, gridLayout(plane), 90, { variant: 'jfa+2', centroidPath: 'auto' });
      const run = new GpuLloydRun(engine, gridSites(plane, sites), { ...options, maxIterations: 5 });
      while (!run.done) run.step();
      engine.dispose();
      return { sites: Array.from(run.sites), energies: run.iterations.map((r) => r.energy) };
    });
    expect(results[1]).toEqual(results[0]);
  });

  it('over-relaxation reaches a lower energy than plain Lloyd in the same iterations', () => {
    const energyAfter = (omega: number) => {
      const sites = placeSites(plane, 100, 8, 1.5);
      const engine = new GpuEngine(context, gridLayout(plane), 100, { variant: 'jfa+2', centroidPath: 'auto' });
      const run = new GpuLloydRun(engine, gridSites(plane, sites), { maxIterations: 20, tolerance: 0, overRelaxation: omega, warmStart: true });
      while (!run.done) run.step();
      const energy = run.finish().energy;
      engine.dispose();
      return energy;
    };
    expect(energyAfter(1.6)).toBeLessThan(energyAfter(1));
  });
});
