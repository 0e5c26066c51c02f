import { spawnSync } from 'node:child_process';
import { cpSync, existsSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { readCsvTable } from '../../src/core/sweep';

// The CLI from its sources (same main() as bin/tissue-sheet.mjs).
const bin = join(__dirname, 'fromSource.mjs');
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-shard-'));
const cli = (args: string[], env: Record<string, string> = {}) =>
  spawnSync(process.execPath, [bin, ...args], { encoding: 'utf8', env: { ...process.env, ...env } });

// Tiny, on the exact engine: 2 Voronoi k x 4 ratios x 2 realizations = 16 runs in 4 seeded-surface groups.
const spec = {
  base: { surface: { kind: 'tube', radius: 40, length: 300 }, resolution: 128, cells: 24, engine: 'exact', sheet: { protocol: 'lab', validityMaxRatio: 4 } },
  vary: { 'lloyd.maxIterations': [0, 2], 'sheet.surfaceRatio': [1, 2, 3, 4] },
  realizations: 2,
  seed: 5,
};
const specPath = join(dir, 'spec.json');
writeFileSync(specPath, JSON.stringify(spec));
const writeConfig = () => {
  const path = join(dir, 'config.json');
  writeFileSync(
    path,
    JSON.stringify({ surface: { kind: 'plane', width: 50, height: 50 }, resolution: 32, cells: 6, engine: 'exact', lloyd: { maxIterations: 1 } }),
  );
  return path;
};
const FILES = ['runs.csv', 'aggregate.csv', 'aggregate.json', 'flintstones.csv'];
const read = (d: string, f: string) => readFileSync(join(d, f), 'utf8');

describe('sweep --shard and merge', () => {
  it('shards partition the runs, and merging them (one given twice) writes the unsharded sweep', () => {
    const whole = join(dir, 'whole');
    expect(cli(['sweep', specPath, '--out', whole]).status).toBe(0);
    const shards = [1, 2, 3].map((i) => join(dir, `shard${i}`));
    const keys: string[] = [];
    shards.forEach((out, i) => {
      // shard 2 through the SLURM array variables (task ids 10..12)
      const run =
        i === 1
          ? cli(['sweep', specPath, '--out', out, '--shard', 'slurm'], { SLURM_ARRAY_TASK_ID: '11', SLURM_ARRAY_TASK_MIN: '10', SLURM_ARRAY_TASK_COUNT: '3' })
          : cli(['sweep', specPath, '--out', out, `--shard=${i + 1}/3`]);
      expect(run.status, run.stderr).toBe(0);
      expect(JSON.parse(read(out, 'sweep.json')).shard).toEqual({ index: i + 1, count: 3, of: 16 });
      keys.push(...readCsvTable(read(out, 'runs.csv')).rows.map((r) => r.key));
    });
    const all = readCsvTable(read(whole, 'runs.csv')).rows.map((r) => r.key);
    expect(new Set(keys).size).toBe(keys.length);
    expect([...keys].sort()).toEqual([...all].sort());

    const merged = join(dir, 'merged');
    const merge = cli(['merge', shards[2], shards[0], shards[1], shards[0], '--out', merged]);
    expect(merge.status, merge.stderr).toBe(0);
    expect(merge.stderr).toMatch(/merge: 16 runs from 4 directories \(\d+ repeated/);
    for (const f of FILES) expect(read(merged, f), f).toBe(read(whole, f));
    const flintstones = JSON.parse(read(merged, 'aggregate.json')).flintstones;
    expect(flintstones.map((f: { voronoi: number }) => f.voronoi)).toEqual([1, 3]);
    expect(JSON.parse(read(merged, 'sweep.json')).merged).toMatchObject({ rows: 16, missing: 0 });

    // A missing shard is reported; sweeping the merged directory computes just its runs.
    const partial = join(dir, 'partial');
    const some = cli(['merge', shards[0], shards[2], '--out', partial]);
    expect(some.status).toBe(0);
    expect(some.stderr).toMatch(/warning: \d+ of 16 runs are in none of the directories/);
    const rest = cli(['sweep', specPath, '--out', partial]);
    expect(rest.status, rest.stderr).toBe(0);
    expect(rest.stderr).toMatch(/runs computed, \d+ resumed/);
    // resumed runs are appended: the same rows, in another order; the aggregates are the same
    const lines = (d: string) => read(d, 'runs.csv').split('\r\n').sort();
    expect(lines(partial)).toEqual(lines(whole));
    for (const f of FILES.slice(1)) expect(read(partial, f), f).toBe(read(whole, f));
  }, 120_000);

  it('refuses shards of another spec or version, non-sweep directories and bad --shard values (exit 2, one line)', () => {
    const one = join(dir, 'one');
    expect(cli(['sweep', specPath, '--out', one, '--shard', '1/8']).status).toBe(0);
    const other = join(dir, 'other.json');
    writeFileSync(other, JSON.stringify({ ...spec, seed: 6 }));
    const otherOut = join(dir, 'otherOut');
    expect(cli(['sweep', other, '--out', otherOut, '--shard', '2/8']).status).toBe(0);
    const older = join(dir, 'older');
    cpSync(one, older, { recursive: true });
    const record = JSON.parse(read(older, 'sweep.json'));
    writeFileSync(join(older, 'sweep.json'), JSON.stringify({ ...record, software: { ...record.software, version: '0.0.1-old' } }, null, 2));
    const plain = join(dir, 'plain');
    cpSync(join(dir, 'spec.json'), join(dir, 'plain.json'));
    for (const [args, pattern] of [
      [['merge', one, otherOut, '--out', join(dir, 'm1')], /otherOut\/sweep\.json: another spec than .*one\/sweep\.json/],
      [['merge', one, older, '--out', join(dir, 'm2')], /older\/sweep\.json: written by tissue-sheet 0\.0\.1-old/],
      [['merge', one, plain, '--out', join(dir, 'm3')], /plain: no such directory/],
      [['merge', one, dir, '--out', join(dir, 'm4')], /has no sweep\.json/],
      [['merge', one, '--out', one], /is also an input/],
      [['merge', '--out', join(dir, 'm5')], /missing sweep directories/],
      [['sweep', specPath, '--out', join(dir, 's1'), '--shard', '0/4'], /--shard: I must be 1 to 4/],
      [['sweep', specPath, '--out', join(dir, 's2'), '--shard', 'half'], /--shard: "half" is not I\/N/],
      [['sweep', specPath, '--out', join(dir, 's3'), '--shard', 'slurm'], /SLURM_ARRAY_TASK_ID is not set/],
    ] as const) {
      const run = cli([...args], { SLURM_ARRAY_TASK_ID: '' });
      expect(run.status, `${args.join(' ')}: ${run.stderr}`).toBe(2);
      expect(run.stderr).toMatch(pattern);
      expect(run.stderr.trim().split('\n')).toHaveLength(1);
      expect(run.stderr).not.toMatch(/\n\s+at /);
    }
    for (const m of ['m1', 'm2', 'm3', 'm4']) expect(existsSync(join(dir, m))).toBe(false);
  }, 120_000);

  it('resumes a directory only with the sweep that wrote it: the same base config, version and shard', () => {
    const first = join(dir, 'first');
    expect(cli(['sweep', specPath, '--out', first, '--shard', '1/8']).status).toBe(0);
    const rows = read(first, 'runs.csv');
    const copy = (name: string) => {
      const to = join(dir, name);
      cpSync(first, to, { recursive: true });
      return to;
    };
    const specWith = (name: string, base: object) => {
      const path = join(dir, name);
      writeFileSync(path, JSON.stringify({ ...spec, base: { ...spec.base, ...base } }));
      return path;
    };
    const older = copy('older-version');
    const record = JSON.parse(read(older, 'sweep.json'));
    writeFileSync(join(older, 'sweep.json'), JSON.stringify({ ...record, software: { ...record.software, version: '0.0.1-old' } }, null, 2));
    const cases: [string[], RegExp, string][] = [
      // Rows name their grid point by the varied values only: a row of cells 24 passed for one of cells 25.
      [
        ['sweep', specWith('cells25.json', { cells: 25 }), '--out', copy('cells'), '--shard', '1/8'],
        /holds a sweep of another base config \(base\.cells: 24 there, 25 here\); its \d+ rows would be mixed/,
        'cells',
      ],
      [['sweep', specPath, '--out', copy('shard2'), '--shard', '2/8'], /holds shard 1\/8, and this is shard 2\/8/, 'shard2'],
      [['sweep', specPath, '--out', older, '--shard', '1/8'], /holds a sweep written by tissue-sheet 0\.0\.1-old/, 'older-version'],
      // merge writes runs.csv anew: the rows a sweep already holds there would be lost.
      [
        ['merge', first, '--out', copy('merge-into')],
        /holds a sweep with \d+ rows in runs\.csv, which merge would replace; merge into a new directory/,
        'merge-into',
      ],
      // A sweep's record is not a result to replace.
      [
        ['run', writeConfig(), '--out', join(copy('run-into'), 'sweep.json')],
        /sweep\.json: is a file of the sweep in .*run-into; give another path/,
        'run-into',
      ],
    ];
    for (const [args, pattern, name] of cases) {
      const run = cli(args);
      expect(run.status, `${args.join(' ')}: ${run.stderr}`).toBe(2);
      expect(run.stderr).toMatch(pattern);
      expect(run.stderr.trim().split('\n')).toHaveLength(1);
      expect(read(join(dir, name), 'runs.csv')).toBe(rows);
    }
    // A row of another configuration under a key of this spec (runs.csv edited or swapped by
    // hand): its base columns differ, so it is set aside and computed again.
    const edited = copy('edited');
    const table = readCsvTable(read(edited, 'runs.csv'));
    const cellsAt = table.header.indexOf('cells');
    expect(cellsAt).toBeGreaterThan(0);
    const lines = read(edited, 'runs.csv').split('\r\n');
    const fields = lines[1].split(',');
    expect(fields[cellsAt]).toBe('24');
    fields[cellsAt] = '25';
    lines[1] = fields.join(',');
    writeFileSync(join(edited, 'runs.csv'), lines.join('\r\n'));
    const foreign = cli(['sweep', specPath, '--out', edited, '--shard', '1/8']);
    expect(foreign.status, foreign.stderr).toBe(0);
    expect(foreign.stderr).toMatch(
      /runs\.csv:2: cells is "25" but run .* of this spec has 24 \(a row of another configuration\); dropped, the run is computed again/,
    );
    expect(foreign.stderr).toMatch(/1 runs computed, \d+ resumed/);
    // The same config with a default written out is the same sweep: resumed, nothing computed.
    const same = cli(['sweep', specWith('explicit.json', { minSpacing: 0 }), '--out', copy('explicit'), '--shard', '1/8']);
    expect(same.status, same.stderr).toBe(0);
    expect(same.stderr).toMatch(/0 runs computed, \d+ resumed/);
    // With --force, merge replaces the rows it was told to.
    expect(cli(['merge', first, '--out', join(dir, 'merge-into'), '--force']).status).toBe(0);
    // One version across two commits: merged, and said.
    const [a, b] = ['commit-a', 'commit-b'].map((name, k) => {
      const to = copy(name);
      const r = JSON.parse(read(to, 'sweep.json'));
      writeFileSync(join(to, 'sweep.json'), JSON.stringify({ ...r, software: { ...r.software, commit: `${k}`.repeat(40) } }, null, 2));
      return to;
    });
    const mixed = cli(['merge', a, b, '--out', join(dir, 'merged-commits')]);
    expect(mixed.status, mixed.stderr).toBe(0);
    expect(mixed.stderr).toMatch(/warning: the directories were written by 2 commits of tissue-sheet .* \(0000000000, 1111111111\)/);
  }, 120_000);
});
