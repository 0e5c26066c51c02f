import { describe, expect, it } from 'vitest';
import { aggregateRows, aggregateToCsv, aggregateToJson, flatList, meanSd, runCells, runSweep, type SweepRun } from '../../src/core/sweep';
import { Random } from '../../src/core/random';

/** The statistics as the reduce-based meanSd computed them before (the oracle for the loops). */
function meanSdReduce(values: readonly number[]) {
  const finite = values.filter(Number.isFinite);
  const n = finite.length;
  const missing = values.length - n;
  if (n === 0) return { mean: NaN, sd: NaN, se: NaN, n, missing };
  const mean = finite.reduce((a, b) => a + b, 0) / n;
  const sd = n < 2 ? NaN : Math.sqrt(finite.reduce((a, b) => a + (b - mean) ** 2, 0) / (n - 1));
  return { mean, sd, se: sd / Math.sqrt(n), n, missing };
}

/** Every number as its 8 bytes in hex, so -0, NaN and the last bit count. */
const bits = (x: unknown) =>
  JSON.stringify(x, (_k, v) =>
    typeof v === 'number' ? `#${Array.from(new Uint8Array(Float64Array.of(v).buffer), (b) => b.toString(16).padStart(2, '0')).join('')}` : v,
  );

describe('sweep rows keep their typed cells for the aggregate', () => {
  it('meanSd gives the bits of the reduce over the finite values', () => {
    const random = new Random(7);
    const specials = [NaN, Infinity, -Infinity, -0, 0, 1e300, -1e-300];
    for (let trial = 0; trial < 300; trial++) {
      const n = Math.floor(random.next() * 25);
      const values = Array.from({ length: n }, () =>
        random.next() < 0.1 ? specials[Math.floor(random.next() * specials.length)] : (random.next() - 0.5) * 10 ** Math.floor(random.next() * 12 - 6),
      );
      expect(bits(meanSd(values))).toBe(bits(meanSdReduce(values)));
    }
  });

  it('aggregates rows made by runCells exactly as the same rows read back as text', () => {
    const random = new Random(11);
    // A repeated column (a row's text is its last cell's) and values of every kind.
    const header = ['key', 'k', 'realization', 'seed', 'a', 'b', 'c', 'd', 'text', 'b'];
    const odd = [NaN, Infinity, -0, null, undefined, '', '12', ' 7 ', 'x', true, 1e21, 5e-324, 12n, [3], { x: 1 }];
    const rows: Record<string, string>[] = [];
    for (let p = 0; p < 4; p++) {
      for (let r = 0; r < 6; r++) {
        const summary: Record<string, unknown> = {};
        for (const c of ['a', 'b', 'c', 'd']) summary[c] = random.next() < 0.2 ? odd[Math.floor(random.next() * odd.length)] : random.next() * 100 - 50;
        summary.text = 'label';
        const run = { key: `p${p}#r${r}`, point: { k: p }, realization: r, seed: r, config: {}, pointKey: `k=${p}` } as unknown as SweepRun;
        // A runner's record (flattened by runCells) or a thread's key list; array and object
        // values are cells only in a key list (a record's would be flattened into other columns).
        const nested = Object.values(summary).some((v) => typeof v === 'object' && v !== null);
        const flat = r % 2 === 0 && !nested ? summary : flatList(Object.keys(summary), Object.values(summary));
        rows.push(runCells(run, ['k'], flat, header).row);
      }
    }
    // The same rows as a reader of runs.csv gets them: text only, no typed cells.
    const parsed = rows.map((row) => ({ ...row }));
    // A resumed sweep's groups: rows read from the file beside rows made now.
    const mixed = rows.map((row, k) => (k % 3 === 1 ? { ...row } : row));
    for (const columns of [['a', 'b', 'c', 'd'], ['a', 'b', 'c', 'd', 'text', 'absent'], undefined]) {
      const typed = aggregateRows(rows, ['k'], columns);
      const text = aggregateRows(parsed, ['k'], columns);
      expect(bits(typed)).toBe(bits(text));
      expect(bits(aggregateRows(mixed, ['k'], columns))).toBe(bits(text));
      expect(aggregateToCsv(typed)).toBe(aggregateToCsv(text));
      expect(JSON.stringify(aggregateToJson(typed))).toBe(JSON.stringify(aggregateToJson(text)));
    }
  });

  it('runSweep formats rows as runs finish, in any order, into the file a one-at-a-time sweep writes', async () => {
    const runs = Array.from({ length: 12 }, (_, k) => ({
      key: `k${k}`,
      point: { x: k % 3 },
      realization: Math.floor(k / 3),
      seed: k,
      config: { x: k % 3 },
      pointKey: `x=${k % 3}`,
    })) as unknown as SweepRun[];
    const summaryOf = (run: SweepRun) => ({ value: Number(run.seed) * 1.5, half: Number(run.seed) / 3, name: `r${run.seed}` });
    const write = async (reversed: boolean, summaryColumns?: string[]) => {
      let file = '';
      const result = await runSweep({
        runs,
        fields: ['x'],
        summaryColumns,
        append: (text) => void (file += text),
        runner: async (_config, run) => summaryOf(run),
        // Every run of a task reported in reverse order: rows wait for the runs before them.
        tasks: {
          key: () => 'one',
          run: async (task, done) => {
            for (const run of reversed ? [...task].reverse() : task) done(run, summaryOf(run));
          },
        },
      });
      return { file, rows: result.rows };
    };
    const plain = await write(false);
    for (const columns of [undefined, ['value', 'half', 'name']]) {
      const out = await write(true, columns);
      expect(out.file).toBe(plain.file);
      expect(out.rows).toEqual(plain.rows);
    }
  });
});
