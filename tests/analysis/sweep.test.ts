import { describe, expect, it } from 'vitest';
import {
  aggregateRows,
  aggregateToCsv,
  aggregateToJson,
  csvField,
  expandSweep,
  flattenSummary,
  formatCsvRow,
  getPath,
  meanSd,
  parseCsv,
  readCsvTable,
  remainingRuns,
  runSweep,
  variedFields,
  type SweepSpec,
} from '../../src/core/sweep';

const spec: SweepSpec = {
  base: { seed: 42, geometry: { kind: 'tube', ratio: 1 }, lloyd: { iterations: 0 }, sites: 200 },
  vary: { 'geometry.ratio': [1, 2, 4], 'lloyd.iterations': [0, 3] },
  realizations: 4,
};

describe('expandSweep', () => {
  const runs = expandSweep(spec);
  it('is the Cartesian product times realizations, first field slowest', () => {
    expect(runs.length).toBe(3 * 2 * 4);
    expect(runs.map((r) => r.point['geometry.ratio']).slice(0, 9)).toEqual([1, 1, 1, 1, 1, 1, 1, 1, 2]);
    expect(runs.map((r) => r.realization).slice(0, 5)).toEqual([0, 1, 2, 3, 0]);
    expect(runs[5].key).toBe('geometry.ratio=1&lloyd.iterations=3#r1');
    expect(new Set(runs.map((r) => r.key)).size).toBe(runs.length);
  });
  it('sets the varied values and the seed in a deep copy of the base', () => {
    const r = runs[9];
    expect(getPath(r.config, 'geometry.ratio')).toBe(2);
    expect(getPath(r.config, 'geometry.kind')).toBe('tube');
    expect(r.config.seed).toBe(r.seed);
    expect((spec.base.geometry as { ratio: number }).ratio).toBe(1);
    expect(r.config.geometry).not.toBe(runs[10].config.geometry);
  });
  it('gives distinct deterministic uint32 seeds per run, stable across calls', () => {
    const seeds = runs.map((r) => r.seed);
    expect(new Set(seeds).size).toBe(runs.length);
    for (const s of seeds) expect(Number.isInteger(s) && s >= 0 && s < 2 ** 32).toBe(true);
    expect(expandSweep(spec).map((r) => r.seed)).toEqual(seeds);
    expect(expandSweep({ ...spec, seed: 43 }).map((r) => r.seed)).not.toEqual(seeds);
    // adding a value does not change the keys and seeds of existing runs
    const more = expandSweep({ ...spec, vary: { ...spec.vary, 'geometry.ratio': [1, 2, 4, 10] } });
    const byKey = new Map(more.map((r) => [r.key, r.seed]));
    for (const r of runs) expect(byKey.get(r.key)).toBe(r.seed);
  });
  it('shares seeds across grid points in per-realization mode', () => {
    const crn = expandSweep({ ...spec, seedMode: 'per-realization' });
    const r0 = crn.filter((r) => r.realization === 0).map((r) => r.seed);
    expect(new Set(r0).size).toBe(1);
    expect(new Set(crn.map((r) => r.seed)).size).toBe(4);
  });
  it('handles no varied fields, and rejects bad specs', () => {
    const single = expandSweep({ base: { a: 1 }, realizations: 2 });
    expect(single.map((r) => r.key)).toEqual(['#r0', '#r1']);
    expect(variedFields({ base: {} })).toEqual([]);
    expect(() => expandSweep({ base: {}, vary: { seed: [1, 2] } })).toThrow();
    expect(() => expandSweep({ base: {}, vary: { a: [] } })).toThrow();
    expect(() => expandSweep({ base: {}, realizations: 0 })).toThrow();
    expect(() => expandSweep({ base: { a: 3 }, vary: { 'a.b': [1] } })).toThrow();
  });
});

describe('CSV', () => {
  it('quotes per RFC 4180 and round-trips', () => {
    expect(csvField('plain')).toBe('plain');
    expect(csvField('a,b')).toBe('"a,b"');
    expect(csvField('say "hi"')).toBe('"say ""hi"""');
    expect(csvField('two\nlines')).toBe('"two\nlines"');
    expect(csvField(' pad')).toBe('" pad"');
    expect(csvField(null)).toBe('');
    expect(csvField(1.5)).toBe('1.5');
    expect(csvField({ a: [1, 2] })).toBe('"{""a"":[1,2]}"');
    const fields = ['x', 'a,b', 'q"q', 'l1\r\nl2', '', 'NaN'];
    const text = formatCsvRow(fields) + formatCsvRow(['1', '2', '3', '4', '5', '6']);
    expect(text.endsWith('\r\n')).toBe(true);
    const parsed = parseCsv(text);
    expect(parsed.records).toEqual([fields, ['1', '2', '3', '4', '5', '6']]);
    expect(parsed.truncated).toBe(false);
    expect(parseCsv('a,b\nc,d\n').records).toEqual([['a', 'b'], ['c', 'd']]);
  });
  it('reports a truncated last record and drops malformed ones', () => {
    const text = 'k,v\r\na,1\r\nb,2,3\r\nc,0.12';
    const t = readCsvTable(text);
    expect(t.rows).toEqual([{ k: 'a', v: '1' }]);
    expect(t.malformed).toBe(1);
    expect(t.truncated).toBe(true);
    expect(text.slice(0, t.validLength)).toBe('k,v\r\na,1\r\nb,2,3\r\n');
  });
  it('flattens nested summaries into dotted columns', () => {
    expect(flattenSummary({ a: 1, b: { c: [2, 3], d: 'x' }, e: Float64Array.from([4]) })).toEqual({
      a: 1, 'b.c.0': 2, 'b.c.1': 3, 'b.d': 'x', 'e.0': 4,
    });
  });
});

describe('aggregation', () => {
  it('computes mean and sample SD per grid point', () => {
    expect(meanSd([1, 2, 3, 4])).toEqual({ mean: 2.5, sd: Math.sqrt(5 / 3), se: Math.sqrt(5 / 3) / 2, n: 4, missing: 0 });
    expect(meanSd([5, NaN]).n).toBe(1);
    expect(Number.isNaN(meanSd([5]).sd)).toBe(true);
    const rows = [
      { key: 'a#r0', s: '1', realization: '0', seed: '9', pct: '10', label: 'x' },
      { key: 'a#r1', s: '1', realization: '1', seed: '8', pct: '20', label: 'y' },
      { key: 'b#r0', s: '2', realization: '0', seed: '7', pct: '50', label: 'z' },
      { key: 'b#r1', s: '2', realization: '1', seed: '6', pct: 'NaN', label: 'w' },
    ];
    const agg = aggregateRows(rows, ['s']);
    expect(agg.columns).toEqual(['pct']);
    expect(agg.points.map((p) => p.point.s)).toEqual(['1', '2']);
    expect(agg.points[0].stats.pct.mean).toBe(15);
    expect(agg.points[0].stats.pct.sd).toBeCloseTo(Math.SQRT2 * 5);
    expect(agg.points[1].stats.pct).toEqual({ mean: 50, sd: NaN, se: NaN, n: 1, missing: 1 });
    const csv = readCsvTable(aggregateToCsv(agg));
    expect(csv.header).toEqual(['s', 'runs', 'pct.mean', 'pct.sd', 'pct.se', 'pct.n']);
    expect(csv.rows[0]['pct.mean']).toBe('15');
    const json = aggregateToJson(agg) as { stats: { pct: { sd: number | null } } }[];
    expect(json[1].stats.pct.sd).toBeNull();
    expect(JSON.parse(JSON.stringify(json))).toEqual(json);
  });
});

describe('runSweep', () => {
  const runs = expandSweep({ base: { seed: 1, s: 1 }, vary: { s: [1, 2, 3], label: ['a,b', 'c'] }, realizations: 2 });
  const fields = ['s', 'label'];
  const runner = async (config: Record<string, unknown>) => ({ pct: (config.s as number) * 10, nested: { seedMod: (config.seed as number) % 7 } });

  it('writes a header and one row per run, appended as runs complete', async () => {
    let file = '';
    const progress: string[] = [];
    const res = await runSweep({ runs, fields, runner, append: (t) => { file += t; }, onProgress: (p) => progress.push(`${p.phase}:${p.finished}/${p.total}`) });
    expect(res.completed).toBe(12);
    const table = readCsvTable(file);
    expect(table.header).toEqual(['key', 's', 'label', 'realization', 'seed', 'pct', 'nested.seedMod']);
    expect(table.rows.length).toBe(12);
    expect(table.rows[0].label).toBe('a,b');
    expect(table.rows.map((r) => r.key)).toEqual(runs.map((r) => r.key));
    expect(table.rows[11].pct).toBe('30');
    expect(progress[0]).toBe('start:0/12');
    expect(progress[progress.length - 1]).toBe('done:12/12');
    const agg = aggregateRows(table.rows, fields);
    expect(agg.points.length).toBe(6);
    expect(agg.points[0].stats.pct).toEqual({ mean: 10, sd: 0, se: 0, n: 2, missing: 0 });
  });

  it('resumes an interrupted sweep, running only what remains', async () => {
    let file = '';
    let calls = 0;
    const failing = async (config: Record<string, unknown>) => {
      if (++calls === 6) throw new Error('interrupted');
      return runner(config);
    };
    await expect(runSweep({ runs, fields, runner: failing, append: (t) => { file += t; } })).rejects.toThrow('interrupted');
    expect(readCsvTable(file).rows.length).toBe(5);
    // a write cut off mid-row
    file += 'garbage-partial,1';
    const state = remainingRuns(runs, readCsvTable(file).rows);
    expect(state.remaining.length).toBe(7);
    await expect(runSweep({ runs, fields, runner, existingCsv: file, append: () => {} })).rejects.toThrow(/incomplete/);
    const seen: string[] = [];
    const res = await runSweep({
      runs, fields, existingCsv: file,
      runner: async (c, run) => { seen.push(run.key); return runner(c); },
      truncate: (n) => { file = file.slice(0, n); },
      append: (t) => { file += t; },
    });
    expect(res.skipped).toBe(5);
    expect(seen).toEqual(state.remaining.map((r) => r.key));
    const table = readCsvTable(file);
    expect(table.truncated).toBe(false);
    expect(table.malformed).toBe(0);
    expect(table.rows.map((r) => r.key).sort()).toEqual(runs.map((r) => r.key).sort());
    expect(res.rows.length).toBe(12);
    // nothing left: a rerun runs nothing
    const again = await runSweep({ runs, fields, existingCsv: file, runner: async () => { throw new Error('no'); }, append: () => {} });
    expect(again.completed).toBe(0);
  });

  it('skips failures when asked, runs concurrently, and refuses a changed spec', async () => {
    let file = '';
    const res = await runSweep({
      runs, fields, concurrency: 3, onError: 'skip',
      runner: async (c) => { await new Promise((r) => setTimeout(r, 1)); if (c.s === 2) throw new Error('bad'); return runner(c); },
      append: (t) => { file += t; },
    });
    expect(res.failed.length).toBe(4);
    expect(readCsvTable(file).rows.length).toBe(8);
    const other = expandSweep({ base: { seed: 2, s: 1 }, vary: { s: [1, 2, 3], label: ['a,b', 'c'] }, realizations: 2 });
    await expect(runSweep({ runs: other, fields, runner, existingCsv: file, append: () => {} })).rejects.toThrow(/seed/);
  });
});
