import { describe, expect, it } from 'vitest';
import { exactVoronoi } from '../../src/core/exact';
import { rasterizeCells } from '../../src/core/exactEngine';
import type { Grid } from '../../src/core/grid';
import { mulberry32 } from '../../src/core/mesh/generate';
import { exactLabelImage } from '../../src/view/exactLabels';

/** Random sites (texel units) on `grid`. */
function sites(grid: Grid, n: number, seed: number): Float64Array {
  const random = mulberry32(seed);
  return Float64Array.from({ length: 2 * n }, (_, k) => (k % 2 === 0 ? grid.width : grid.height) * random());
}

describe('exactLabelImage (the views of an opened result)', () => {
  for (const [name, grid] of [
    ['a tube (periodic around, anisotropic texels)', { width: 96, height: 160, texelX: 1.7, texelY: 2.5, periodicX: true, periodicY: false }],
    ['a plane', { width: 120, height: 80, texelX: 1, texelY: 1, periodicX: false, periodicY: false }],
    ['a torus-like periodic plane', { width: 64, height: 64, texelX: 0.5, texelY: 0.5, periodicX: true, periodicY: true }],
  ] as [string, Grid][]) {
    it(`${name}: the label image of core/exact.ts's exact cells, texel for texel`, () => {
      for (const seed of [1, 2, 3]) {
        const points = sites(grid, 150, seed);
        const expected = rasterizeCells(grid, exactVoronoi(grid, points));
        const labels = exactLabelImage(grid, points);
        let differing = 0;
        for (let t = 0; t < labels.length; t++) if (labels[t] !== expected[t]) differing++;
        // Texel centres on a cell edge (up to rounding) may go either way.
        expect(differing).toBeLessThanOrEqual(2);
        expect(labels.every((id) => id >= 0 && id < 150)).toBe(true);
      }
    });
  }
});
