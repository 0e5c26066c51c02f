import { describe, expect, it } from 'vitest';
import { ConfigError, validateConfig, type ClosedConfig, type ConfigInput } from '../../src/core/config';
import { placeClosedSites } from '../../src/core/closed/geometry';
import { ellipsoidProjector } from '../../src/core/closed/projector';
import { sampleSurface } from '../../src/core/cubemap/sample';
import { runSheet } from '../../src/run/runSheet';
import { useHeadlessContext } from '../gpu/context';
import { GpuEngine } from '../../src/gpu/engine';
import { cubeLayout } from '../../src/gpu/layout';
import { closedSites, GpuLloydRun } from '../../src/gpu/lloyd';

const context = useHeadlessContext();
const closed = (input: ConfigInput) => validateConfig(input) as ClosedConfig;

describe('plain constrained Lloyd on an ellipsoid', () => {
  it('never increases the CVT energy (omega = 1)', () => {
    const image = sampleSurface({ kind: 'ellipsoid', a: 80, b: 40, c: 40 }, 64);
    const projector = ellipsoidProjector(80, 40, 40);
    const sites = placeClosedSites(image, projector, 200, 3, 0);
    const engine = new GpuEngine(context, cubeLayout(64), 200, { variant: 'jfa+2', centroidPath: 'auto' });
    try {
      engine.setGeometry(image.area, image.position);
      const run = new GpuLloydRun(engine, closedSites(projector, sites, 0.5), { maxIterations: 25, tolerance: 0, overRelaxation: 1, warmStart: true });
      while (!run.done) run.step();
      const energies = [...run.iterations.map((r) => r.energy), run.finish().energy];
      for (let k = 1; k < energies.length; k++) expect(energies[k]).toBeLessThanOrEqual(energies[k - 1] * (1 + 1e-9));
      expect(energies.at(-1)!).toBeLessThan(energies[0] * 0.8);
      // Sites stay on the ellipsoid.
      for (let i = 0; i < 200; i++) {
        const [x, y, z] = [0, 1, 2].map((c) => sites.positions[3 * i + c]);
        expect((x / 80) ** 2 + (y / 40) ** 2 + (z / 40) ** 2).toBeCloseTo(1, 9);
      }
    } finally {
      engine.dispose();
    }
  });
});

describe('ellipsoid 2:1:1, 200 cells', () => {
  it('% scutoids is above 0 and rises with thickness', async () => {
    const base = { surface: { kind: 'ellipsoid', a: 100, b: 50, c: 50 }, resolution: 64, cells: 200, minSpacing: 8, lloyd: { maxIterations: 30 } } as const;
    const percents: number[] = [];
    for (const thickness of [8, 30, 90]) {
      const { result } = await runSheet(closed({ ...base, sheet: { thickness, adjacency: 'labels' } }), context);
      expect(result.analyses[0].summary.validCells).toBe(200);
      percents.push(result.analyses[0].summary.percentScutoids);
    }
    console.log(
      `ellipsoid 2:1:1 (a = 100 µm), cells ~17 µm across: % scutoids at thickness 8, 30, 90 µm outward: ${percents.map((p) => p.toFixed(1)).join(', ')}`,
    );
    expect(percents[0]).toBeGreaterThan(0);
    expect(percents[1]).toBeGreaterThan(percents[0]);
    expect(percents[2]).toBeGreaterThan(percents[1]);
  }, 20000);
});

describe('offsets beyond the smallest radius of curvature are refused', () => {
  const error = async (input: ConfigInput) => {
    try {
      await runSheet(closed(input), context);
    } catch (e) {
      return e as ConfigError;
    }
    return null;
  };
  it('sphere: inward at or beyond R', async () => {
    const e = await error({ surface: { kind: 'sphere', radius: 50 }, resolution: 32, cells: 20, sheet: { direction: 'inward', thickness: 50 } });
    expect(e).toBeInstanceOf(ConfigError);
    expect(e!.field).toBe('sheet.thickness');
    expect(e!.message).toBe(
      'sheet.thickness: 50 µm inward reaches the smallest radius of curvature of the sphere (50 µm), where the offset surface folds over itself; use less than 50 µm or direction "outward"',
    );
  });
  it('ellipsoid 2:1:1: inward beyond b²/a', async () => {
    const e = await error({ surface: { kind: 'ellipsoid', a: 100, b: 50, c: 50 }, resolution: 32, cells: 20, sheet: { direction: 'inward', thickness: 30 } });
    expect(e?.message).toContain('smallest radius of curvature of the ellipsoid (25 µm)');
    expect(
      await error({
        surface: { kind: 'ellipsoid', a: 100, b: 50, c: 50 },
        resolution: 32,
        cells: 20,
        lloyd: { maxIterations: 1 },
        sheet: { direction: 'inward', thickness: 20 },
      }),
    ).toBeNull();
  });
});
