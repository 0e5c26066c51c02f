import { describe, expect, it } from 'vitest';
import { anchoredB, flintstonesLaw } from '../../src/core/analysis/flintstones';
import { Random } from '../../src/core/random';
import { expandSweep, sweepFlintstones } from '../../src/core/sweep';
import { flintstonesInTurns } from '../../src/view/pageSweep';

/**
 * The page's Flintstones fits, one per turn of the event loop (no long task on the main thread):
 * the same fits, bit for bit, as sweepFlintstones makes at once, and the event loop turns between
 * them (a timer set before the fits fires before they end).
 */
describe('flintstonesInTurns', () => {
  const ratios = [1, 1.25, 1.5, 2, 3, 4, 6, 10];
  const base = { surface: { kind: 'tube', radius: 81.49, length: 4096 }, cells: 200, sheet: { protocol: 'lab' } };
  const runs = expandSweep({ base, vary: { 'lloyd.maxIterations': [0, 3, 6], 'sheet.surfaceRatio': ratios }, realizations: 3, seed: 4 });
  const fields = ['lloyd.maxIterations', 'sheet.surfaceRatio'];
  const random = new Random(8);
  const rows = runs.map((run) => {
    const s = run.point['sheet.surfaceRatio'] as number;
    const k = run.point['lloyd.maxIterations'] as number;
    const law = { nMax: 7 + k / 10, c: 2.5, d: -1.2, b: anchoredB(7 + k / 10, 2.5, -1.2, 6) };
    const row: Record<string, string> = { key: run.key, realization: String(run.realization), seed: String(run.seed) };
    for (const f of fields) row[f] = String(run.point[f]);
    row['exact.meanNeighbours3D'] = String(flintstonesLaw(s, law) + 0.2 * (random.next() - 0.5));
    return row;
  });

  it('gives sweepFlintstones’ fits, between turns of the event loop', async () => {
    let turned = false;
    setTimeout(() => (turned = true), 0);
    const inTurns = await flintstonesInTurns(rows, runs, fields);
    expect(turned).toBe(true);
    const atOnce = sweepFlintstones(rows, runs, fields);
    expect(inTurns.length).toBe(3);
    expect(inTurns.every((fit) => fit.parameters !== null)).toBe(true);
    expect(JSON.stringify(inTurns)).toBe(JSON.stringify(atOnce));
  });
});
