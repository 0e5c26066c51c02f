/**
 * Aggregation of tidy sweep rows per grid point.
 *
 * Rows are grouped by the values of the varied fields (their CSV text), in order of first
 * appearance. The numeric columns are `columns` when given (the CLI passes every summary
 * column but the text ones), else every column except `key`, `realization`, `seed` and the
 * fields in which most non-empty cells parse as numbers: one stray value never drops a column.
 * Per group and column: n = number of finite values, mean = their mean, sd = sample standard
 * deviation (n - 1 denominator), se = sd / sqrt(n); `missing` = rows of the group whose cell is
 * empty, not a number, NaN or infinite. mean is NaN when n = 0 (written empty, with n = 0, so
 * "no data" is never presented as a value), sd and se NaN when n < 2.
 * - CSV: the varied fields, `runs` (rows in the group), then `<column>.mean`, `.sd`, `.se`, `.n`
 *   for each numeric column; NaN statistics are written as empty cells.
 * - JSON: `[{ point, runs, stats: { column: { mean, sd, se, n, missing } } }]`, NaN as null.
 */
import { formatCsv } from './csv';

export const RESERVED_COLUMNS = ['key', 'realization', 'seed'] as const;

export interface ColumnStats {
  mean: number;
  sd: number;
  se: number;
  n: number;
  missing: number;
}

export interface AggregatePoint {
  point: Record<string, string>;
  runs: number;
  stats: Record<string, ColumnStats>;
}

export interface Aggregate {
  fields: string[];
  columns: string[];
  points: AggregatePoint[];
}

const isNumeric = (cell: string): boolean => cell === 'NaN' || (cell.trim() !== '' && !Number.isNaN(Number(cell)));

/** Mean, sample SD, SE and count of the finite values; `missing` counts the others. */
export function meanSd(values: readonly number[]): ColumnStats {
  const finite = values.filter(Number.isFinite);
  const n = finite.length;
  const missing = values.length - n;
  if (n === 0) return { mean: NaN, sd: NaN, se: NaN, n, missing };
  const mean = finite.reduce((a, b) => a + b, 0) / n;
  const sd = n < 2 ? NaN : Math.sqrt(finite.reduce((a, b) => a + (b - mean) ** 2, 0) / (n - 1));
  return { mean, sd, se: sd / Math.sqrt(n), n, missing };
}

export function aggregateRows(rows: readonly Record<string, string>[], fields: readonly string[], columns?: readonly string[]): Aggregate {
  const skip = new Set<string>([...RESERVED_COLUMNS, ...fields]);
  const numeric =
    columns !== undefined
      ? [...columns]
      : [...new Set(rows.flatMap((r) => Object.keys(r)))].filter((c) => {
          if (skip.has(c)) return false;
          let yes = 0;
          let no = 0;
          for (const r of rows) {
            const cell = r[c];
            if (cell === undefined || cell === '') continue;
            if (isNumeric(cell)) yes++;
            else no++;
          }
          return yes > no;
        });
  const groups = new Map<string, Record<string, string>[]>();
  for (const r of rows) {
    const k = JSON.stringify(fields.map((f) => r[f] ?? ''));
    let g = groups.get(k);
    if (!g) groups.set(k, (g = []));
    g.push(r);
  }
  const points: AggregatePoint[] = [];
  for (const g of groups.values()) {
    const point: Record<string, string> = {};
    for (const f of fields) point[f] = g[0][f] ?? '';
    const stats: Record<string, ColumnStats> = {};
    for (const c of numeric) {
      stats[c] = meanSd(g.map((r) => (r[c] === undefined || r[c] === '' || !isNumeric(r[c]) ? NaN : Number(r[c]))));
    }
    points.push({ point, runs: g.length, stats });
  }
  return { fields: [...fields], columns: numeric, points };
}

const orEmpty = (x: number): number | string => (Number.isFinite(x) ? x : '');

export function aggregateToCsv(agg: Aggregate): string {
  const header = [...agg.fields, 'runs', ...agg.columns.flatMap((c) => [`${c}.mean`, `${c}.sd`, `${c}.se`, `${c}.n`])];
  const rows = agg.points.map((p) => [
    ...agg.fields.map((f) => p.point[f]),
    p.runs,
    ...agg.columns.flatMap((c) => [orEmpty(p.stats[c].mean), orEmpty(p.stats[c].sd), orEmpty(p.stats[c].se), p.stats[c].n]),
  ]);
  return formatCsv(header, rows);
}

/** JSON-ready form (NaN -> null). */
export function aggregateToJson(agg: Aggregate): unknown {
  const clean = (x: number): number | null => (Number.isFinite(x) ? x : null);
  return agg.points.map((p) => ({
    point: p.point,
    runs: p.runs,
    stats: Object.fromEntries(
      Object.entries(p.stats).map(([c, s]) => [c, { mean: clean(s.mean), sd: clean(s.sd), se: clean(s.se), n: s.n, missing: s.missing }]),
    ),
  }));
}
