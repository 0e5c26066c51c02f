/**
 * The sweep's Flintstones fits made on its threads (src/core/sweep/fitOutcomes.ts): a fit is taken from
 * there only for exactly the points the aggregate fits, the fits a thread makes are those the
 * main thread makes (bit for bit), and the aggregate is the same whichever made them.
 */
import { afterAll, describe, expect, it } from 'vitest';
import { anchoredB, flintstonesLaw, type FlintstonesFit, type FlintstonesPoint } from '../../src/core/analysis/flintstones';
import { Random } from '../../src/core/random';
import { expandSweep, flintstonesProblems, sweepFitter, sweepFlintstones } from '../../src/core/sweep';
import { cachedFitter, fitOutcome, fitOutcomes, pointsKey, type FitOutcome } from '../../src/core/sweep/fitOutcomes';
import { SweepWorkers } from '../../src/cli/sweepWorkers';

const RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10];

/** Runs and rows of a tube sweep whose n3D follows the law plus noise; Voronoi 1 gets too few ratios with values. */
function sweep() {
  const base = { surface: { kind: 'tube', radius: 81.49, length: 4096 }, cells: 200, sheet: { protocol: 'lab' } };
  const runs = expandSweep({ base, vary: { 'lloyd.maxIterations': [0, 2, 5], 'sheet.surfaceRatio': RATIOS }, realizations: 4, seed: 9 });
  const fields = ['lloyd.maxIterations', 'sheet.surfaceRatio'];
  const random = new Random(5);
  const law = { nMax: 7.8, c: 2.2, d: -1.3, b: anchoredB(7.8, 2.2, -1.3, 6) };
  const rows = runs.map((run) => {
    const s = run.point['sheet.surfaceRatio'] as number;
    const voronoi = (run.point['lloyd.maxIterations'] as number) + 1;
    const n = voronoi === 1 && s > 1.5 ? '' : String(flintstonesLaw(s, law) + 0.1 * (random.next() - 0.5));
    const row: Record<string, string> = { key: run.key, realization: String(run.realization), seed: String(run.seed), 'exact.meanNeighbours3D': n };
    for (const f of fields) row[f] = String(run.point[f]);
    return row;
  });
  return { runs, rows, fields };
}

describe('Flintstones fits made elsewhere', () => {
  it('are the points the aggregate fits, in its order, for the groups it fits', () => {
    const { runs, rows, fields } = sweep();
    const fitted: FlintstonesPoint[][] = [];
    const fits = sweepFlintstones(rows, runs, fields, (points) => (fitted.push([...points]), sweepFitter(points)));
    expect(flintstonesProblems(rows, runs, fields)).toEqual(fitted);
    // Voronoi 1 has 3 ratios with values: no fit, and no problem.
    expect(fits.map((f) => [f.voronoi, f.parameters !== null])).toEqual([
      [1, false],
      [3, true],
      [6, true],
    ]);
    expect(fitted.length).toBe(2);
  });

  it('are taken only for the same points, errors as thrown', () => {
    const { runs, rows, fields } = sweep();
    const [points] = flintstonesProblems(rows, runs, fields);
    const marker = { marker: true } as unknown as FlintstonesFit;
    const outcomes = new Map<string, FitOutcome>([[pointsKey(points), { fit: marker }]]);
    expect(cachedFitter(outcomes)(points)).toBe(marker);
    // One value one ulp away, or the points in another order: fitted here.
    const moved = points.map((p, k) => (k === 7 ? { ...p, n: p.n + Math.abs(p.n) * Number.EPSILON } : p));
    expect(moved[7].n).not.toBe(points[7].n);
    expect(cachedFitter(outcomes)(moved)).toEqual(sweepFitter(moved));
    const reversed = [...points].reverse();
    expect(cachedFitter(outcomes)(reversed)).toEqual(sweepFitter(reversed));
    const failing = new Map<string, FitOutcome>([[pointsKey(points), { error: 'fitFlintstones: no admissible starting point' }]]);
    expect(() => cachedFitter(failing)(points)).toThrow(/^fitFlintstones: no admissible starting point$/);
    // fitOutcome keeps a fit's error message.
    const flat = [1, 2, 3, 4, 5].map((s) => ({ s, n: 6 - s }));
    const outcome = fitOutcome(flat);
    let thrown = '';
    try {
      sweepFitter(flat);
    } catch (error) {
      thrown = (error as Error).message;
    }
    expect(outcome).toEqual(thrown ? { error: thrown } : { fit: sweepFitter(flat) });
  });

  describe('on sweep threads', () => {
    const pool = new SweepWorkers(2, { renderer: 'test', maxTextureSize: 4096, floatBlend: false, softwareRenderer: true }, new Map());
    afterAll(() => pool.close());

    it('taken one at a time by every thread (fitMany) equal the main thread fits bit for bit, and the aggregate is the same', async () => {
      const { runs, rows, fields } = sweep();
      const problems = flintstonesProblems(rows, runs, fields);
      // More problems than threads, some of them the same points, one that cannot be fitted.
      const flat = [1, 2, 3, 4, 5].map((s) => ({ s, n: 6 - s }));
      const many = [...problems, flat, ...problems.map((points) => points.map((p) => ({ ...p, n: p.n + 0.02 }))), ...problems];
      const outcomes = await pool.fitMany(many);
      expect(outcomes.length).toBe(many.length);
      many.forEach((points, k) => {
        const here = fitOutcome(points);
        expect(outcomes[k]).toEqual(here);
        if ('fit' in here) expect(Float64Array.from((outcomes[k] as { fit: FlintstonesFit }).fit.covariance)).toEqual(Float64Array.from(here.fit.covariance));
      });
      const byPoints = fitOutcomes(many, outcomes);
      expect(JSON.stringify(sweepFlintstones(rows, runs, fields, cachedFitter(byPoints)))).toBe(JSON.stringify(sweepFlintstones(rows, runs, fields)));
      expect(await pool.fitMany([])).toEqual([]);
    });
  });
});
