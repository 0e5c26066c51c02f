import { describe, expect, it } from 'vitest';
import { csvField, flatList, runCells, type SweepRun } from '../../src/core/sweep';
import { Random } from '../../src/core/random';
import { recordOf } from '../../src/core/sweep/records';

/**
 * runCells' row from a thread's flat key list, from a record (a runner's summary, which
 * runCells flattens), and the text an independent formatting of the same cells gives (String of
 * a number, csvField of the rest), whatever the values repeat (its number texts are kept) or
 * which columns a run's base fills.
 */
describe('runCells', () => {
  it('the same cells, row and line from a key list and from a record, numbers as String(n)', () => {
    const random = new Random(11);
    const specials = [NaN, -0, 0, Infinity, -Infinity, 1 / 3, 0.1 + 0.2, 1e21, -1e-7];
    const keys = Array.from({ length: 40 }, (_, k) => `exact.layer${k}.meanSides`);
    // A header with a column of no value, a summary key that is also a base column (the base's
    // value wins), and a repeated column name.
    const header = ['key', 'k', 'realization', 'seed', 'tube', ...keys, 'missing', 'seed'];
    const summaryKeys = [...keys, 'seed'];
    for (let trial = 0; trial < 200; trial++) {
      const values: unknown[] = summaryKeys.map(() => {
        const u = random.next();
        if (u < 0.2) return specials[Math.floor(random.next() * specials.length)];
        if (u < 0.3) return random.next() < 0.5 ? 'text, "quoted"' : null;
        // Repeated values (fractions of a few counts) and fresh ones.
        return u < 0.7 ? Math.floor(random.next() * 7) / 6 : (random.next() - 0.5) * 10 ** Math.floor(random.next() * 10 - 4);
      });
      const run = {
        key: `k=${trial}#r0`,
        point: { k: trial },
        realization: trial % 3,
        seed: 1000 + trial,
        config: { seed: 1000 + trial },
        index: trial,
        pointKey: `k=${trial}`,
      } as unknown as SweepRun;
      const geometry = { tube: trial % 2 === 0 ? 'tube' : 'plane' };
      const fromList = runCells(run, ['k'], flatList(summaryKeys, values), header, geometry);
      const record = Object.fromEntries(summaryKeys.map((key, n) => [key, values[n]]));
      const fromRecord = runCells(run, ['k'], record, header, geometry);
      expect(fromList.cells).toEqual(fromRecord.cells);
      expect(fromList.row).toEqual(fromRecord.row);
      expect(fromList.line).toBe(fromRecord.line);
      const base: Record<string, unknown> = { key: run.key, k: String(trial), realization: run.realization, seed: run.seed, ...geometry };
      const expected = header.map((h) => (h in base ? base[h] : h === 'missing' ? undefined : values[summaryKeys.indexOf(h)]));
      expect(fromList.cells.length).toBe(header.length);
      fromList.cells.forEach((cell, k) => expect(Object.is(cell, expected[k]), header[k]).toBe(true));
      const text = (v: unknown) => (typeof v === 'number' ? String(v) : csvField(v));
      expect(fromList.line).toBe(`${expected.map(text).join(',')}\r\n`);
      header.forEach((h) => {
        const last = expected[header.lastIndexOf(h)];
        expect(fromList.row[h]).toBe(typeof last === 'number' ? String(last) : last === null || last === undefined ? '' : String(last));
      });
    }
  });

  it('rows are plain records of every column, whatever the names, with or without generated code', () => {
    // Names that could break generated code if they were not literals, and a repeated one.
    const odd = ['a"b', 'c\\d', "e'f", 'g\nh', 'line\u2028sep', '`${x}`', '}); throw 1; ({', 'constructor', 'toString', '0', '12', 'x.y.z'];
    const run = { key: 'p#r0', point: {}, realization: 0, seed: 7, config: {}, index: 0, pointKey: 'p' } as unknown as SweepRun;
    const make = () => {
      const header = ['key', 'realization', 'seed', ...odd, 'x.y.z'];
      const values = odd.map((_, n) => (n % 3 === 0 ? n / 7 : n % 3 === 1 ? `t${n}` : null));
      return { header, ...runCells(run, [], flatList(odd, values), header) };
    };
    const check = ({ header, row, cells }: ReturnType<typeof make>) => {
      // Built key by key, as the reference: same keys in the same order, same texts.
      const reference: Record<string, string> = {};
      header.forEach((h, k) => {
        const v = cells[k];
        reference[h] = typeof v === 'number' ? String(v) : v === null || v === undefined ? '' : String(v);
      });
      expect(Object.getPrototypeOf(row)).toBe(Object.prototype);
      expect(Object.keys(row)).toEqual(Object.keys(reference));
      expect(JSON.stringify(row)).toBe(JSON.stringify(reference));
      expect(Object.prototype.hasOwnProperty.call(row, 'constructor')).toBe(true);
    };
    check(make());
    // A page whose Content-Security-Policy forbids generated code: the rows are the same.
    const original = globalThis.Function;
    globalThis.Function = function refused() {
      throw new EvalError('Refused to evaluate a string as JavaScript (CSP)');
    } as unknown as FunctionConstructor;
    try {
      check(make());
    } finally {
      globalThis.Function = original;
    }
  });

  it('records of hundreds of keys (past what an object holds in itself) equal records built key by key, each its own', () => {
    const keys = Array.from({ length: 400 }, (_, k) => (k % 97 === 5 ? 'repeated' : `column.${k}`));
    const reference = (values: readonly unknown[]) => {
      const record: Record<string, unknown> = {};
      keys.forEach((key, k) => (record[key] = values[k]));
      return record;
    };
    const first = keys.map((_, k) => k * 0.5);
    const second = keys.map((_, k) => `v${k}`);
    const a = recordOf(keys, first);
    const b = recordOf(keys, second);
    for (const [record, values] of [
      [a, first],
      [b, second],
    ] as const) {
      expect(Object.getPrototypeOf(record)).toBe(Object.prototype);
      expect(Object.keys(record)).toEqual(Object.keys(reference(values)));
      expect(JSON.stringify(record)).toBe(JSON.stringify(reference(values)));
    }
    // The last of a repeated key's values, as assignments in order keep.
    expect(a.repeated).toBe(first[keys.lastIndexOf('repeated')]);
    // Records do not share their values (each is a copy of the template, not the template).
    a['column.1'] = -1;
    expect(b['column.1']).toBe('v1');
    expect(recordOf(keys, first)['column.1']).toBe(0.5);
  });
});
