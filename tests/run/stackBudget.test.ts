import { describe, expect, it } from 'vitest';
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { estimateRun } from '../../src/core/config/limits';
import { surfaceColumnNames } from '../../src/core/sweep';
import { runSheet } from '../../src/run';
import { useHeadlessContext } from '../gpu/context';

/**
 * The run budget, the sweep's columns and the pipeline read one description of the stack
 * (sheetOffsets): the budget counts every surface the pipeline builds, layer steps included
 * (issue 25: a sphere with thickness 10 and layerStep 1 was budgeted as 2 surfaces, built as 11).
 */
const context = useHeadlessContext();

const cases: [string, ConfigInput, number][] = [
  [
    'a sphere, thickness 10, layerStep 1 µm',
    { surface: { kind: 'sphere', radius: 30 }, resolution: 16, cells: 20, lloyd: { maxIterations: 0 }, sheet: { thickness: 10, layerStep: 1 } },
    11,
  ],
  [
    'an ellipsoid inward, thickness 3, layerStep 1.25 µm',
    {
      surface: { kind: 'ellipsoid', a: 30, b: 24, c: 20 },
      resolution: 16,
      cells: 20,
      lloyd: { maxIterations: 0 },
      sheet: { thickness: 3, layerStep: 1.25, direction: 'inward' },
    },
    4,
  ],
  [
    'a sphere with 3 layers',
    { surface: { kind: 'sphere', radius: 30 }, resolution: 16, cells: 20, lloyd: { maxIterations: 0 }, sheet: { thickness: 6, layers: 3 } },
    5,
  ],
  [
    'a tube, s = 2, layerStep 0.25',
    { surface: { kind: 'tube', radius: 20, length: 120 }, resolution: 64, cells: 20, lloyd: { maxIterations: 0 }, sheet: { surfaceRatio: 2, layerStep: 0.25 } },
    5,
  ],
  [
    'a tube, thickness 7 inward, layerStep 0.1',
    {
      surface: { kind: 'tube', radius: 20, length: 120 },
      resolution: 64,
      cells: 20,
      lloyd: { maxIterations: 0 },
      sheet: { thickness: 7, direction: 'inward', layerStep: 0.1 },
    },
    7,
  ],
  [
    'a plane, thickness 5, layerStep 2 µm',
    { surface: { kind: 'plane', width: 100, height: 100 }, resolution: 64, cells: 20, lloyd: { maxIterations: 0 }, sheet: { thickness: 5, layerStep: 2 } },
    4,
  ],
];

describe('the budget counts the surfaces the pipeline builds', () => {
  for (const [name, input, surfaces] of cases) {
    it(name, async () => {
      const config = validateConfig(input);
      const estimate = estimateRun(config);
      expect(estimate.surfaces).toBe(surfaces);
      expect(surfaceColumnNames(config)).toHaveLength(surfaces);
      const { result } = await runSheet(config, context);
      expect(1 + result.surfaces.length).toBe(surfaces);
      // and every surface's texels are in the work: iterations x seeded + one flood per surface
      const texels = estimate.grids.map((g) => g.width * g.height);
      expect(estimate.grids).toHaveLength(surfaces);
      expect(estimate.work).toBe(texels[0] * config.lloyd.maxIterations + texels.reduce((a, b) => a + b, 0));
      expect(result.surfaces.map((s) => s.grid.width * s.grid.height)).toEqual(
        config.surface.kind === 'plane' || config.surface.kind === 'tube' ? texels.slice(1) : result.surfaces.map(() => texels[0]),
      );
    });
  }
});
