import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { validateConfig } from '../../src/core/config';
import {
  expandSweep,
  flattenSummary,
  geometryValues,
  readCsvTable,
  readRunsCsv,
  runCells,
  runSweep,
  validateSweepSpec,
  variedFields,
  type SweepRun,
} from '../../src/core/sweep';
import { SweepThreadLost, SweepWorkers } from '../../src/cli/sweepWorkers';
import { createHeadlessContext } from '../../src/node/headless';
import { SheetRunner, sweepSummary } from '../../src/run/index';

// The CLI from its sources (same main() as bin/tissue-sheet.mjs); its worker threads load the
// sources through tsx too.
const bin = join(__dirname, 'fromSource.mjs');
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-workers-'));
const cli = (args: string[]) => spawnSync(process.execPath, [bin, ...args], { encoding: 'utf8' });

// Small, on the exact engine: 3 Voronoi k x 4 ratios x 3 realizations = 36 runs in 9 seeded-surface groups.
const spec = {
  base: { surface: { kind: 'tube', radius: 40, length: 300 }, resolution: 128, cells: 24, engine: 'exact', sheet: { protocol: 'lab', validityMaxRatio: 4 } },
  vary: { 'lloyd.maxIterations': [0, 1, 3], 'sheet.surfaceRatio': [1, 1.5, 2, 4] },
  realizations: 3,
  seed: 11,
};
const specPath = join(dir, 'spec.json');
writeFileSync(specPath, JSON.stringify(spec));
const FILES = ['runs.csv', 'aggregate.csv', 'aggregate.json', 'flintstones.csv'];
const read = (d: string, f: string) => readFileSync(join(d, f), 'utf8');

describe('sweep --workers N', () => {
  it('writes the same files byte for byte with the main thread alone, beside 1 and beside 2 threads, and resumes with another N', () => {
    // --workers N: the main thread and N - 1 worker threads, all computing runs.
    const one = join(dir, 'one');
    const a = cli(['sweep', specPath, '--out', one, '--workers', '1']);
    expect(a.status, a.stderr).toBe(0);
    for (const n of [2, 3]) {
      const other = join(dir, `n${n}`);
      const b = cli(['sweep', specPath, '--out', other, `--workers=${n}`]);
      expect(b.status, b.stderr).toBe(0);
      expect(b.stderr).toMatch(/sweep: 36 runs computed, 0 resumed/);
      for (const f of FILES) expect(read(other, f), `${f}, --workers ${n}`).toBe(read(one, f));
    }
    expect(readCsvTable(read(one, 'runs.csv')).rows).toHaveLength(36);

    // Cut runs.csv after 10 rows (and mid-row): resuming with 2 threads computes the rest, and the
    // aggregates are those of the uninterrupted sweep.
    const cut = join(dir, 'cut');
    const c = cli(['sweep', specPath, '--out', cut, '--workers', '2']);
    expect(c.status, c.stderr).toBe(0);
    const text = read(cut, 'runs.csv');
    const lines = text.split('\r\n');
    writeFileSync(join(cut, 'runs.csv'), lines.slice(0, 11).join('\r\n') + '\r\n' + lines[11].slice(0, 7));
    const d = cli(['sweep', specPath, '--out', cut, '--workers', '2']);
    expect(d.status, d.stderr).toBe(0);
    expect(d.stderr).toMatch(/sweep: 26 runs computed, 10 resumed/);
    for (const f of FILES.slice(1)) expect(read(cut, f), f).toBe(read(one, f));
    expect(read(cut, 'runs.csv')).toBe(text);
  }, 180_000);

  it('every row is its run computed alone, GPU runs (main thread) and exact runs (threads) mixed', async () => {
    // adjacency "labels" takes the GPU engine (main thread), "exact" the exact engine (threads).
    const mixed = {
      base: { surface: { kind: 'tube', radius: 30, length: 200 }, resolution: 64, cells: 20, engine: 'auto' },
      vary: { 'sheet.adjacency': ['labels', 'exact'], 'lloyd.maxIterations': [0, 2], 'sheet.surfaceRatio': [1, 2] },
      realizations: 2,
      seed: 4,
    };
    const mixedPath = join(dir, 'mixed.json');
    writeFileSync(mixedPath, JSON.stringify(mixed));
    const out = join(dir, 'mixed');
    const r = cli(['sweep', mixedPath, '--out', out, '--workers', '2']);
    expect(r.status, r.stderr).toBe(0);
    const table = readRunsCsv(read(out, 'runs.csv'));
    const runs = expandSweep(validateSweepSpec(mixed));
    const fields = variedFields(validateSweepSpec(mixed));
    const byKey = new Map(table.rows.map((row) => [row.key, row]));
    const context = createHeadlessContext();
    try {
      const engines = new Set<string>();
      for (const run of runs) {
        const { result } = await new SheetRunner(context).run(validateConfig(run.config), { views: false });
        engines.add(result.engine.name);
        // The row: the run's base geometry (units.ts) and its summary, computed alone.
        const summary = { ...geometryValues(validateConfig(run.config), fields), ...sweepSummary(result) };
        expect(byKey.get(run.key), run.key).toEqual(runCells(run, fields, summary, table.header).row);
      }
      expect([...engines].sort()).toEqual(['exact', 'gpu']);
    } finally {
      context.dispose();
    }
  }, 180_000);

  it('refuses a bad --workers value', () => {
    for (const v of ['0', 'many']) {
      const r = cli(['sweep', specPath, '--out', join(dir, 'bad'), '--workers', v]);
      expect(r.status, v).toBe(2);
      expect(r.stderr).toMatch(/--workers: must be an integer from 1 to 1024/);
    }
  });
});

describe('runSweep with tasks finishing in any order', () => {
  const runs = expandSweep({ base: { seed: 1, s: 1 }, vary: { k: [0, 1, 2], s: [1, 2, 3, 4] }, realizations: 3 }) as SweepRun<
    Record<string, unknown> & { seed: number }
  >[];
  const fields = ['k', 's'];
  const summary = (run: SweepRun) => ({ value: Number(run.config.k) * 100 + Number(run.config.s) * 10 + run.realization });

  async function sweep(concurrency: number, shuffle: (n: number) => number): Promise<string> {
    let file = '';
    let appends = 0;
    let announced = 0;
    await runSweep({
      runs,
      fields,
      append: (text) => {
        // One row per append (the header with the first), as the page's reader expects.
        expect(readCsvTable(text).rows.length + (appends === 0 ? 0 : 1)).toBe(1);
        appends++;
        file += text;
      },
      runner: async (_config, run) => summary(run),
      concurrency,
      // Every run's 'done' comes once its row is in the file, however long the row waited for
      // the runs before it (the page shows the row of each 'done').
      onProgress: (p) => {
        if (p.phase === 'done')
          expect(
            readCsvTable(file).rows.map((r) => r.key),
            p.run.key,
          ).toContain(p.run.key);
        if (p.phase === 'done') announced++;
      },
      tasks: {
        key: (run) => `${run.config.k}#${run.realization}`,
        before: (a, b) => a.realization - b.realization,
        // Each task reports its runs in a shuffled order, after shuffled delays.
        run: async (task, done) => {
          const order = task.map((run, k) => ({ run, at: shuffle(k) })).sort((x, y) => x.at - y.at);
          for (const { run, at } of order) {
            await new Promise((r) => setTimeout(r, at % 3));
            done(run, summary(run));
          }
        },
      },
    });
    expect(appends).toBe(runs.length);
    expect(announced).toBe(runs.length);
    return file;
  }

  it('writes rows in run order whatever the concurrency and the finishing order', async () => {
    let seed = 1;
    const random = () => (seed = (seed * 1103515245 + 12345) % 2147483648) % 97;
    const reference = await sweep(1, (k) => k);
    expect(readCsvTable(reference).rows.map((r) => r.key)).toEqual(runs.map((r) => r.key));
    for (const concurrency of [2, 3, 8]) expect(await sweep(concurrency, random), `concurrency ${concurrency}`).toBe(reference);
  });

  it('keeps the finished rows of a sweep stopped by a failure', async () => {
    let file = '';
    const run = runSweep({
      runs,
      fields,
      append: (text) => {
        file += text;
      },
      runner: async (_config, r) => summary(r),
      concurrency: 2,
      tasks: {
        key: (r) => String(r.realization),
        run: async (task, done) => {
          for (const r of task) {
            if (r.realization === 0 && r.config.k === 2) throw new Error('boom');
            done(r, summary(r));
          }
        },
      },
    });
    await expect(run).rejects.toThrow('boom');
    const keys = readCsvTable(file).rows.map((r) => r.key);
    // Realization 0 stopped at its first k = 2 run; the other tasks that ran are all there.
    expect(keys.filter((k) => k.endsWith('#r0'))).toHaveLength(8);
    expect(new Set(keys).size).toBe(keys.length);
  });
});

describe('SweepWorkers holding two tasks per thread', () => {
  // One thread, tasks sent faster than it computes them: the second waits in the thread's queue.
  const base = { surface: { kind: 'tube', radius: 30, length: 200 }, resolution: 64, cells: 20, engine: 'exact', sheet: { surfaceRatio: 2 } };
  const task = (seed: number) => [{ key: `r${seed}`, pointKey: 'p', config: { ...base, seed, lloyd: { maxIterations: 2 } } }];
  const capabilities = () => {
    const context = createHeadlessContext();
    const { capabilities } = context;
    context.dispose();
    return capabilities;
  };

  it('computes queued tasks as each alone, and takes a third once one ends', async () => {
    const pool = new SweepWorkers(1, capabilities());
    try {
      expect(pool.capacity).toBe(2);
      const got = new Map<string, unknown>();
      const done = (key: string, summary: unknown) => got.set(key, summary);
      await Promise.all([1, 2, 3].map((seed) => pool.run(task(seed), `chain${seed}`, done)));
      const context = createHeadlessContext();
      try {
        for (const seed of [1, 2, 3]) {
          const { result } = await new SheetRunner(context).run(validateConfig(task(seed)[0].config), { views: false });
          const alone = sweepSummary(result);
          const values = got.get(`r${seed}`) as { keys: string[]; values: unknown[] };
          expect(Object.fromEntries(values.keys.map((k, n) => [k, values.values[n]]))).toEqual(flattenSummary(alone));
        }
      } finally {
        context.dispose();
      }
    } finally {
      await pool.close();
    }
  }, 120_000);

  it('fails the task it computes and the one queued behind it on an abort', async () => {
    const pool = new SweepWorkers(1, capabilities());
    try {
      const long = (seed: number) => [
        { key: `r${seed}`, pointKey: 'p', config: { ...base, seed, cells: 200, resolution: 256, lloyd: { maxIterations: 200, tolerance: 0 } } },
      ];
      const first = pool.run(long(1), 'a', () => {});
      const second = pool.run(long(2), 'b', () => {});
      // Both sent (run() claims a thread first, a microtask), then the abort.
      await new Promise((resolve) => setImmediate(resolve));
      pool.abort();
      await expect(first).rejects.toMatchObject({ name: 'AbortError' });
      await expect(second).rejects.toMatchObject({ name: 'AbortError' });
    } finally {
      await pool.close();
    }
  }, 120_000);

  it('hands both tasks of a thread that exits back as SweepThreadLost, and refuses more', async () => {
    const pool = new SweepWorkers(1, capabilities());
    const first = pool.run(task(1), 'a', () => {});
    const second = pool.run(task(2), 'b', () => {});
    // The thread goes away under its tasks (as a crash would).
    await (pool as unknown as { slots: { worker: { terminate(): Promise<number> } }[] }).slots[0].worker.terminate();
    await expect(first).rejects.toBeInstanceOf(SweepThreadLost);
    await expect(second).rejects.toBeInstanceOf(SweepThreadLost);
    await expect(pool.run(task(3), 'c', () => {})).rejects.toThrow(/no sweep worker thread is left/);
    await pool.close();
  }, 60_000);
});
