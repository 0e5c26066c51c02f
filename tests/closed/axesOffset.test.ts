import { describe, expect, it } from 'vitest';
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { SheetRunner } from '../../src/run/runSheet';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();
const run = (input: ConfigInput) => new SheetRunner(context).run(validateConfig({ resolution: 64, cells: 120, seed: 4, ...input }));

describe('sheet.offset "axes": the lab\'s spheroid model', () => {
  it('the apical sites lie on the ellipsoid (a + t, b + t, c + t) and are the closest points to the basal sites', async () => {
    const [a, b, c, t] = [60, 35, 30, 12];
    const { result } = await run({
      surface: { kind: 'ellipsoid', a, b, c },
      lloyd: { maxIterations: 0 },
      minSpacing: 3,
      sheet: { thickness: t, offset: 'axes', layers: 1 },
    });
    const apical = result.surfaces[result.surfaces.length - 1];
    expect(apical.name).toBe('apical');
    const [A, B, C] = [a + t, b + t, c + t];
    result.cells.forEach((basal, id) => {
      const p = apical.cells[id].position;
      expect((p[0] / A) ** 2 + (p[1] / B) ** 2 + (p[2] / C) ** 2).toBeCloseTo(1, 9);
      // Closest point: the offset from the basal site is along the outer ellipsoid's normal there.
      const d = p.map((v, k) => basal.position[k] - v);
      const normal = [p[0] / A ** 2, p[1] / B ** 2, p[2] / C ** 2];
      const dn = Math.hypot(...d),
        nn = Math.hypot(...normal);
      const cosine = (d[0] * normal[0] + d[1] * normal[1] + d[2] * normal[2]) / (dn * nn);
      expect(Math.abs(cosine)).toBeGreaterThan(1 - 1e-9);
    });
    // Both methods ran on the same stack, and the exact one is recorded with its contact threshold.
    expect(result.analyses.map((x) => x.method)).toEqual(['labels', 'exact']);
    expect(result.analyses[1].minContactLength).toBeGreaterThan(0);
    expect(result.config.sheet.offset).toBe('axes');
  });

  it('on a sphere "axes" is the concentric sphere: no neighbour changes, exactly as "normal"', async () => {
    for (const offset of ['axes', 'normal'] as const) {
      const { result } = await run({ surface: { kind: 'sphere', radius: 40 }, lloyd: { maxIterations: 2 }, sheet: { thickness: 10, offset } });
      for (const analysis of result.analyses) expect(analysis.summary.percentScutoids).toBe(0);
    }
  });

  it('is refused where it does not apply, naming the field', async () => {
    await expect(run({ surface: { kind: 'mesh', src: 'organoid.ply', scale: 50 }, sheet: { thickness: 5, offset: 'axes' } })).rejects.toMatchObject({
      field: 'sheet.offset',
    });
    await expect(run({ surface: { kind: 'plane', width: 100, height: 100 }, sheet: { thickness: 5, offset: 'axes' } })).rejects.toMatchObject({
      field: 'sheet.offset',
    });
    await expect(
      run({ surface: { kind: 'ellipsoid', a: 60, b: 35, c: 30 }, sheet: { thickness: 30, direction: 'inward', offset: 'axes' } }),
    ).rejects.toMatchObject({ field: 'sheet.thickness' });
  });
});
