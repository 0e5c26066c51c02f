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
  orderForReuse,
  parseShard,
  shardRuns,
  sortRowsByRuns,
  sweepFlintstones,
  flintstonesToCsv,
  SweepSpecError,
  type SweepRun,
  type SweepSpec,
} from '../../src/core/sweep';
import { anchoredB, flintstonesLaw } from '../../src/core/analysis/flintstones';
import { Random } from '../../src/core/random';

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
  it('copies the base as structuredClone would: arrays, nulls, nested objects, own "__proto__" keys; runs share nothing', () => {
    const base = JSON.parse(
      '{"seed": 1, "a": {"list": [1, [2, {"x": null}]], "__proto__": {"polluted": true}}, "b": {"c": "text"}, "d": [{"e": 1}]}',
    ) as Record<string, unknown>;
    const expanded = expandSweep({ base, vary: { 'b.c': ['one', 'two'] }, realizations: 2 });
    for (const run of expanded) {
      const expected = structuredClone(base) as Record<string, unknown> & { b: Record<string, unknown> };
      expected.b.c = run.point['b.c'];
      expected.seed = run.seed;
      expect(run.config).toEqual(expected);
      expect(Object.keys(run.config.a as object)).toEqual(['list', '__proto__']);
      expect(({} as { polluted?: boolean }).polluted).toBeUndefined();
    }
    const [first, second] = expanded;
    (first.config.d as { e: number }[])[0].e = 99;
    ((first.config.a as { list: unknown[] }).list[1] as unknown[])[0] = 99;
    expect((second.config.d as { e: number }[])[0].e).toBe(1);
    expect(((second.config.a as { list: unknown[] }).list[1] as unknown[])[0]).toBe(2);
    expect((base.d as { e: number }[])[0].e).toBe(1);
    expect(() => expandSweep({ base: { seed: 1, f: () => 1 }, vary: { x: [1] } })).toThrow(/could not be cloned/);
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
    expect(parseCsv('a,b\nc,d\n').records).toEqual([
      ['a', 'b'],
      ['c', 'd'],
    ]);
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
      a: 1,
      'b.c.0': 2,
      'b.c.1': 3,
      'b.d': 'x',
      'e.0': 4,
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
    expect(csv.header).toEqual(['s', 'runs', 'pct.mean', 'pct.sd', 'pct.ci95low', 'pct.ci95high', 'pct.n']);
    expect(csv.rows[0]['pct.mean']).toBe('15');
    // 95 % CI of the mean by its definition: mean ± t(0.975, n − 1)·sd/√n; t(0.975, 1) = 12.7062 (tables).
    expect(Number(csv.rows[0]['pct.ci95low'])).toBeCloseTo(15 - 12.7062 * 5, 2);
    expect(Number(csv.rows[0]['pct.ci95high'])).toBeCloseTo(15 + 12.7062 * 5, 2);
    expect(csv.rows[1]['pct.ci95low']).toBe('');
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
    const res = await runSweep({
      runs,
      fields,
      runner,
      append: (t) => {
        file += t;
      },
      onProgress: (p) => progress.push(`${p.phase}:${p.finished}/${p.total}`),
    });
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
    await expect(
      runSweep({
        runs,
        fields,
        runner: failing,
        append: (t) => {
          file += t;
        },
      }),
    ).rejects.toThrow('interrupted');
    expect(readCsvTable(file).rows.length).toBe(5);
    // a write cut off mid-row
    file += 'garbage-partial,1';
    const state = remainingRuns(runs, readCsvTable(file).rows);
    expect(state.remaining.length).toBe(7);
    await expect(runSweep({ runs, fields, runner, existingCsv: file, append: () => {} })).rejects.toThrow(/incomplete/);
    const seen: string[] = [];
    const res = await runSweep({
      runs,
      fields,
      existingCsv: file,
      runner: async (c, run) => {
        seen.push(run.key);
        return runner(c);
      },
      truncate: (n) => {
        file = file.slice(0, n);
      },
      append: (t) => {
        file += t;
      },
    });
    expect(res.skipped).toBe(5);
    expect(seen).toEqual(state.remaining.map((r) => r.key));
    const table = readCsvTable(file);
    expect(table.truncated).toBe(false);
    expect(table.malformed).toBe(0);
    expect(table.rows.map((r) => r.key).sort()).toEqual(runs.map((r) => r.key).sort());
    expect(res.rows.length).toBe(12);
    // nothing left: a rerun runs nothing
    const again = await runSweep({
      runs,
      fields,
      existingCsv: file,
      runner: async () => {
        throw new Error('no');
      },
      append: () => {},
    });
    expect(again.completed).toBe(0);
  });

  it('skips failures when asked, runs concurrently, and refuses a changed spec', async () => {
    let file = '';
    const res = await runSweep({
      runs,
      fields,
      concurrency: 3,
      onError: 'skip',
      runner: async (c) => {
        await new Promise((r) => setTimeout(r, 1));
        if (c.s === 2) throw new Error('bad');
        return runner(c);
      },
      append: (t) => {
        file += t;
      },
    });
    expect(res.failed.length).toBe(4);
    expect(readCsvTable(file).rows.length).toBe(8);
    const other = expandSweep({ base: { seed: 2, s: 1 }, vary: { s: [1, 2, 3], label: ['a,b', 'c'] }, realizations: 2 });
    await expect(runSweep({ runs: other, fields, runner, existingCsv: file, append: () => {} })).rejects.toThrow(/seed/);
  });
});

describe('shards', () => {
  const grid: SweepSpec = {
    base: { seed: 1 },
    vary: { 'lloyd.maxIterations': [0, 1, 2], 'sheet.surfaceRatio': [1, 2, 3, 4] },
    realizations: 5,
    seedMode: 'per-realization',
  };
  const runs = expandSweep(grid);
  // Runs sharing a seeded surface: same config but for sheet.*, same seed.
  const group = (run: SweepRun) => JSON.stringify([run.point['lloyd.maxIterations'], run.seed]);

  it('every run is in exactly one shard, groups whole, shards balanced within one group', () => {
    for (const count of [1, 2, 3, 4, 7, 15, 16, 100]) {
      const shards = Array.from({ length: count }, (_, i) => shardRuns(runs, { index: i + 1, count }, group));
      const keys = shards.flatMap((s) => s.map((r) => r.key));
      expect(new Set(keys).size, `N=${count}`).toBe(keys.length);
      expect([...keys].sort()).toEqual(runs.map((r) => r.key).sort());
      const home = new Map<string, number>();
      shards.forEach((s, i) =>
        s.forEach((r) => {
          expect(home.get(group(r)) ?? i).toBe(i);
          home.set(group(r), i);
        }),
      );
      const groupsPer = shards.map((s) => new Set(s.map(group)).size);
      expect(Math.max(...groupsPer) - Math.min(...groupsPer)).toBeLessThanOrEqual(1);
    }
  });

  it('keeps the runs of a group consecutive, and deals every Voronoi k to every shard', () => {
    const shards = [1, 2, 3, 4].map((index) => shardRuns(runs, { index, count: 4 }, group));
    for (const shard of shards) {
      const seen: string[] = [];
      for (const run of shard) if (seen[seen.length - 1] !== group(run)) seen.push(group(run));
      expect(new Set(seen).size).toBe(seen.length); // no group resumes after another
      expect(new Set(shard.map((r) => r.point['lloyd.maxIterations']))).toEqual(new Set([0, 1, 2]));
    }
  });

  it('with one run per group, shard I of N is every N-th run of the reuse order', () => {
    const ordered = orderForReuse(runs, (r) => r.key);
    expect(ordered.map((r) => r.key)).toEqual(runs.map((r) => r.key));
    const third = shardRuns(runs, { index: 3, count: 5 }, (r) => r.key);
    expect(third.map((r) => r.key)).toEqual(runs.filter((_, k) => k % 5 === 2).map((r) => r.key));
  });

  it('parses I/N and SLURM array variables, refusing the rest with one line naming --shard', () => {
    expect(parseShard('2/4')).toEqual({ index: 2, count: 4 });
    expect(parseShard('slurm', { SLURM_ARRAY_TASK_ID: '7', SLURM_ARRAY_TASK_MIN: '5', SLURM_ARRAY_TASK_COUNT: '4' })).toEqual({ index: 3, count: 4 });
    expect(parseShard('slurm', { SLURM_ARRAY_TASK_ID: '0', SLURM_ARRAY_TASK_MIN: '0', SLURM_ARRAY_TASK_COUNT: '1' })).toEqual({ index: 1, count: 1 });
    for (const [text, env, pattern] of [
      ['0/4', {}, /I must be 1 to 4/],
      ['5/4', {}, /I must be 1 to 4/],
      ['1/0', {}, /N must be/],
      ['a/b', {}, /not I\/N/],
      ['2', {}, /not I\/N/],
      ['slurm', {}, /SLURM_ARRAY_TASK_ID is not set/],
      ['slurm', { SLURM_ARRAY_TASK_ID: '9', SLURM_ARRAY_TASK_MIN: '1', SLURM_ARRAY_TASK_COUNT: '4' }, /not one of 4 consecutive tasks/],
      ['slurm', { SLURM_ARRAY_TASK_ID: 'x', SLURM_ARRAY_TASK_MIN: '1', SLURM_ARRAY_TASK_COUNT: '4' }, /SLURM_ARRAY_TASK_ID="x"/],
    ] as const) {
      let error: unknown;
      try {
        parseShard(text, env);
      } catch (e) {
        error = e;
      }
      expect(error, text).toBeInstanceOf(SweepSpecError);
      expect((error as Error).message).toMatch(/^--shard/);
      expect((error as Error).message).toMatch(pattern);
      expect((error as Error).message).not.toMatch(/\n/);
    }
  });

  it('sortRowsByRuns puts rows in run order whatever order they came in', () => {
    const ordered = orderForReuse(runs, group);
    const rows = [...ordered].reverse().map((r) => ({ key: r.key }));
    expect(sortRowsByRuns(rows, ordered).map((r) => r.key)).toEqual(ordered.map((r) => r.key));
  });
});

describe('Flintstones law in the sweep aggregate', () => {
  const RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10];
  const truths: Record<number, { nMax: number; c: number; d: number }> = { 0: { nMax: 8, c: 2.5, d: -1.2 }, 4: { nMax: 7.5, c: 2, d: -1.5 } };
  const tube = { surface: { kind: 'tube', radius: 81.49, length: 4096 }, cells: 200, minSpacing: 5, sheet: { protocol: 'lab' } };

  /** A sweep's runs and rows whose n3D follows the law with the given truth per Voronoi k, plus noise. */
  function syntheticSweep(ratios: number[], noise: number, metric = 'exact.meanNeighbours3D', extra: Record<string, unknown[]> = {}) {
    const runs = expandSweep({ base: tube, vary: { ...extra, 'lloyd.maxIterations': [0, 4], 'sheet.surfaceRatio': ratios }, realizations: 6, seed: 3 });
    const fields = Object.keys({ ...extra, 'lloyd.maxIterations': 0, 'sheet.surfaceRatio': 0 });
    const random = new Random(11);
    const rows = runs.map((run) => {
      const truth = truths[run.point['lloyd.maxIterations'] as number];
      const p = { ...truth, b: anchoredB(truth.nMax, truth.c, truth.d, 6) };
      const u = Math.max(random.next(), 1e-12);
      const n = flintstonesLaw(run.point['sheet.surfaceRatio'] as number, p) + noise * Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * random.next());
      const row: Record<string, string> = { key: run.key, realization: String(run.realization), seed: String(run.seed), [metric]: String(n) };
      for (const f of fields) row[f] = String(run.point[f]);
      return row;
    });
    return { runs, rows, fields };
  }

  it('recovers the parameters of each Voronoi k within 3 standard errors from a synthetic sweep', () => {
    const { runs, rows, fields } = syntheticSweep(RATIOS, 0.05);
    const fits = sweepFlintstones(rows, runs, fields);
    expect(fits.map((f) => f.voronoi)).toEqual([1, 5]);
    for (const fit of fits) {
      const truth = truths[fit.voronoi - 1];
      expect(fit.metric).toBe('exact.meanNeighbours3D');
      expect(fit.points).toBe(RATIOS.length * 6);
      expect(fit.ratios).toBe(RATIOS.length);
      expect(fit.illConditioned, fit.note).toBe(false);
      expect(fit.rSquared!).toBeGreaterThan(0.9);
      for (const name of ['nMax', 'c', 'd'] as const) {
        const se = fit.standardErrors![name]!;
        expect(se).toBeGreaterThan(0);
        expect(Math.abs(fit.parameters![name] - truth[name]), `Voronoi ${fit.voronoi} ${name}`).toBeLessThan(3 * se + 1e-9);
      }
      // the anchor holds: n3D(1) = 6
      expect(flintstonesLaw(1, fit.parameters!)).toBeCloseTo(6, 9);
    }
  });

  it('fits each combination of the other varied fields apart, and uses labels where there is no exact value', () => {
    const { runs, rows, fields } = syntheticSweep(RATIOS, 0.05, 'labels.meanNeighbours3D', { cells: [100, 200] });
    const fits = sweepFlintstones(rows, runs, fields);
    expect(fits.map((f) => [f.group.cells, f.voronoi])).toEqual([
      ['100', 1],
      ['100', 5],
      ['200', 1],
      ['200', 5],
    ]);
    for (const fit of fits) expect(fit.metric).toBe('labels.meanNeighbours3D');
    const csv = readCsvTable(flintstonesToCsv(fits, fields));
    expect(csv.header.slice(0, 3)).toEqual(['cells', 'voronoi', 'metric']);
    expect(csv.rows.map((r) => r.illConditioned)).toEqual(['false', 'false', 'false', 'false']);
    expect(Number(csv.rows[1]['nMax'])).toBeCloseTo(fits[1].parameters!.nMax, 12);
  });

  it('flags a fit the data cannot pin down, and makes none from too few ratios', () => {
    const narrow = syntheticSweep([1, 1.25, 1.5, 1.75], 0.3);
    const fits = sweepFlintstones(narrow.rows, narrow.runs, narrow.fields);
    expect(fits.length).toBe(2);
    for (const fit of fits) {
      expect(fit.illConditioned).toBe(true);
      expect(fit.note).toMatch(/standard error|converge/);
    }
    const few = syntheticSweep([1, 2, 4], 0.05);
    for (const fit of sweepFlintstones(few.rows, few.runs, few.fields)) {
      expect(fit.parameters).toBeNull();
      expect(fit.note).toMatch(/3 distinct surface ratios/);
    }
  });
});
