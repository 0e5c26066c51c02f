/**
 * Aggregation of tidy sweep rows per grid point.
 *
 * Rows are grouped by the values of the varied fields (their CSV text), in order of first
 * appearance. For every other column except `key`, `realization` and `seed` whose non-empty
 * cells all parse as numbers (Number(cell), "NaN" included), the statistics per group are:
 * n = number of finite values, mean = their mean, sd = sample standard deviation (n - 1
 * denominator) of the finite values; mean is NaN when n = 0 and sd is NaN when n < 2.
 * Non-numeric columns are left out.
 * - CSV: the varied fields, `runs` (rows in the group), then `<column>.mean` and `<column>.sd`
 *   for each numeric column.
 * - JSON: `[{ point, runs, stats: { column: { mean, sd, n } } }]` with NaN written as null.
 */
import { formatCsv } from './csv';

export const RESERVED_COLUMNS = ['key', 'realization', 'seed'] as const;

export interface ColumnStats {
  mean: number;
  sd: number;
  n: number;
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

const isNumeric = (cell: string): boolean => cell.trim() !== '' && !Number.isNaN(Number(cell)) || cell.trim() === 'NaN';

/** Mean, sample SD and count of the finite values. */
export function meanSd(values: readonly number[]): ColumnStats {
  const finite = values.filter(Number.isFinite);
  const n = finite.length;
  if (n === 0) return { mean: NaN, sd: NaN, n };
  const mean = finite.reduce((a, b) => a + b, 0) / n;
  const sd = n < 2 ? NaN : Math.sqrt(finite.reduce((a, b) => a + (b - mean) ** 2, 0) / (n - 1));
  return { mean, sd, n };
}

export function aggregateRows(rows: readonly Record<string, string>[], fields: readonly string[], columns?: readonly string[]): Aggregate {
  const skip = new Set<string>([...RESERVED_COLUMNS, ...fields]);
  const candidates = columns ?? [...new Set(rows.flatMap((r) => Object.keys(r)))].filter((c) => !skip.has(c));
  const numeric = candidates.filter((c) => {
    let any = false;
    for (const r of rows) {
      const cell = r[c];
      if (cell === undefined || cell === '') continue;
      if (!isNumeric(cell)) return false;
      any = true;
    }
    return any;
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
      stats[c] = meanSd(g.map((r) => (r[c] === undefined || r[c] === '' ? NaN : Number(r[c]))));
    }
    points.push({ point, runs: g.length, stats });
  }
  return { fields: [...fields], columns: numeric, points };
}

export function aggregateToCsv(agg: Aggregate): string {
  const header = [...agg.fields, 'runs', ...agg.columns.flatMap((c) => [`${c}.mean`, `${c}.sd`])];
  const rows = agg.points.map((p) => [
    ...agg.fields.map((f) => p.point[f]),
    p.runs,
    ...agg.columns.flatMap((c) => [p.stats[c].mean, p.stats[c].sd]),
  ]);
  return formatCsv(header, rows);
}

/** JSON-ready form (NaN -> null). */
export function aggregateToJson(agg: Aggregate): unknown {
  const clean = (x: number): number | null => (Number.isFinite(x) ? x : null);
  return agg.points.map((p) => ({
    point: p.point,
    runs: p.runs,
    stats: Object.fromEntries(Object.entries(p.stats).map(([c, s]) => [c, { mean: clean(s.mean), sd: clean(s.sd), n: s.n }])),
  }));
}
