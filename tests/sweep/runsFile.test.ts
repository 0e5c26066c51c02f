import { describe, expect, it } from 'vitest';
import {
  aggregateRows,
  aggregateToCsv,
  baseColumns,
  csvField,
  expandSweep,
  formatCsvRow,
  parseCsv,
  planResume,
  readCsvTable,
  ResumeError,
  runSweep,
  type SweepRun,
} from '../../src/core/sweep';

describe('CSV cells that would open as formulas (OWASP)', () => {
  it('get a leading apostrophe when text, never when numbers, and read back as written', () => {
    for (const text of ['=HYPERLINK("http://x")', '+1+2', '-2+3', '@SUM(A1)', '\tcmd', '\rcmd', "'=already"]) {
      const cell = csvField(text);
      expect(cell.replace(/^"/, '')).toMatch(/^'/);
      expect(parseCsv(formatCsvRow([text])).records[0][0]).toBe(text);
    }
    for (const value of [-3, -1.5e-7, -Infinity, 3]) expect(csvField(value)).toBe(String(value));
    for (const text of ['-3', '+4', '-1.5e-7', 'plain', 'a=b']) expect(csvField(text)).toBe(text);
  });
});

const runs = expandSweep({ base: { seed: 1 }, vary: { s: [1, 2], label: ['=x', 'c'] }, realizations: 2 });
const fields = ['s', 'label'];
const header = [...baseColumns(fields), 'pct', 'method', 'extra'];
const filled = (run: SweepRun) => new Set(run.point.s === 1 ? ['pct', 'method'] : ['pct', 'method', 'extra']);
const spec = { header, fields, runs, filledColumns: filled, textColumns: new Set(['method']) };
const runner = async (config: Record<string, unknown>) => ({ pct: (config.s as number) * 10, method: '@lab', ...(config.s === 2 ? { extra: 7 } : {}) });

async function completeFile(): Promise<string> {
  let file = '';
  await runSweep({
    runs,
    fields,
    runner,
    summaryColumns: header.slice(baseColumns(fields).length),
    append: (t) => {
      file += t;
    },
  });
  return file;
}

describe('resuming from a runs file', () => {
  it('keeps every row of an intact file and rewrites nothing', async () => {
    const file = await completeFile();
    const plan = planResume(file, spec);
    expect(plan.rejected).toEqual([]);
    expect(plan.rows).toHaveLength(8);
    expect(plan.rewrite).toBe(false);
    expect(plan.rows[0].label).toBe('=x'); // neutralised on disk, restored on reading
    expect(file).toContain("'=x");
  });

  it('drops duplicated, truncated, malformed, hand-edited and foreign rows, reporting each by line', async () => {
    const lines = (await completeFile()).split('\r\n');
    const [head, ...rows] = lines.slice(0, -1);
    const edit = (row: string, column: string, value: string) => {
      const cells = parseCsv(row + '\r\n').records[0];
      cells[header.indexOf(column)] = value;
      return formatCsvRow(cells).slice(0, -2);
    };
    const corrupted =
      [
        head,
        rows[0],
        rows[0], // line 3: duplicate
        edit(rows[1], 'pct', 'abc'), // line 4: not a number
        rows[2] + ',1', // line 5: one field too many
        edit(rows[3], 'seed', '12345'), // line 6: wrong seed
        edit(rows[4], 'key', 's=9&label="c"#r0'), // line 7: not a run of this spec
        edit(rows[5], 'extra', ''), // line 8: an expected column emptied
        edit(rows[0].replace('#r0', '#r1'), 'extra', '5'), // line 9: a column this run does not fill
      ].join('\r\n') +
      '\r\n' +
      rows[6].slice(0, 10); // line 10: cut off
    const plan = planResume(corrupted, spec);
    expect(plan.rejected.map((r) => [r.line, r.reason.split(' ')[0]])).toEqual([
      [3, 'duplicate'],
      [4, 'pct:'],
      [5, '9'],
      [6, 'seed'],
      [7, 'key'],
      [8, 'extra'],
      [9, 'realization'],
      [10, 'incomplete'],
    ]);
    expect(plan.rows.map((r) => r.key)).toEqual([runs[0].key]);
    expect(plan.rewrite).toBe(true);
    // resuming from the cleaned text computes exactly the other runs, once each
    const seen: string[] = [];
    let file = plan.cleanText;
    const res = await runSweep({
      runs,
      fields,
      existingCsv: plan.cleanText,
      summaryColumns: header.slice(5),
      runner: async (c, run) => {
        seen.push(run.key);
        return runner(c);
      },
      append: (t) => {
        file += t;
      },
    });
    expect(res.skipped).toBe(1);
    expect(seen.sort()).toEqual(
      runs
        .slice(1)
        .map((r) => r.key)
        .sort(),
    );
    expect(planResume(file, spec).rejected).toEqual([]);
    expect(readCsvTable(file).rows).toHaveLength(8);
  });

  it('refuses a file written with another header, naming the column', async () => {
    const file = (await completeFile()).replace('pct', 'percent');
    expect(() => planResume(file, spec, 'out/runs.csv')).toThrow(ResumeError);
    expect(() => planResume(file, spec, 'out/runs.csv')).toThrow(
      /^out\/runs\.csv: written for another spec or version \(column 6 is "percent", this spec writes "pct"\)/,
    );
  });
});

describe('aggregate', () => {
  const rows = [
    { key: 'a#r0', s: '1', realization: '0', seed: '1', pct: '10', only2: '' },
    { key: 'a#r1', s: '1', realization: '1', seed: '2', pct: 'oops', only2: '' },
    { key: 'a#r2', s: '1', realization: '2', seed: '3', pct: '30', only2: '' },
    { key: 'b#r0', s: '2', realization: '0', seed: '1', pct: '50', only2: '4' },
  ];
  it('keeps a column with one bad value, counting it as missing', () => {
    const agg = aggregateRows(rows, ['s']);
    expect(agg.columns).toContain('pct');
    expect(agg.points[0].stats.pct).toMatchObject({ mean: 20, n: 2, missing: 1 });
  });
  it('writes n = 0 with empty statistics, never a NaN mean presented as data', () => {
    const agg = aggregateRows(rows, ['s'], ['pct', 'only2']);
    expect(agg.points[0].stats.only2.n).toBe(0);
    const csv = readCsvTable(aggregateToCsv(agg));
    const stats = ['mean', 'sd', 'ci95low', 'ci95high', 'n'];
    expect(csv.header).toEqual(['s', 'runs', ...stats.map((s) => `pct.${s}`), ...stats.map((s) => `only2.${s}`)]);
    expect(csv.rows[0]['only2.mean']).toBe('');
    expect(csv.rows[0]['only2.n']).toBe('0');
    expect(csv.rows[0]['only2.ci95low']).toBe('');
    expect(csv.rows[1]['only2.mean']).toBe('4');
    expect(csv.rows[1]['pct.sd']).toBe('');
    expect(Number(csv.rows[0]['pct.sd'])).toBeCloseTo(Math.sqrt(200));
  });
});
