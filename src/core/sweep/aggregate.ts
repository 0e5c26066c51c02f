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
 * - CSV (`aggregateToCsv`): the varied fields, `runs` (rows in the group), then per column only
 *   the statistics that mean something for it (`csvStatistics`): the run-level metrics of a
 *   method (% scutoids, scutoids, valid cells, mean transitions, won, lost, 3D neighbours) get
 *   mean, sd, the 95 % confidence interval of the mean (mean ± t(0.975, n − 1)·sd/√n, not
 *   clamped) and n; a surface's mean sides gets mean and sd; a polygon fraction its mean (the
 *   distribution over realizations); every other column (iterations, the CVT energy, excluded
 *   cells = cells − valid cells) is left to runs.csv. A header cell is `<column>.<statistic>`
 *   with the column's unit last (`exact.percentScutoids.mean_pct`, units.ts); NaN statistics
 *   are written as empty cells.
 * - JSON: `[{ point, runs, stats: { column: { mean, sd, se, n, missing, ci95 } } }]`, NaN as null.
 */
import { tQuantile975 } from '../analysis/realizations';
import { formatCsv } from './csv';
import { internKeys, recordOf } from './records';
import { cellNumber, columnPosition, typedCellsOf } from './typedCells';
import { columnUnit, fileColumn } from './units';

const RESERVED_COLUMNS = ['key', 'realization', 'seed'] as const;

export interface ColumnStats {
  mean: number;
  sd: number;
  se: number;
  n: number;
  missing: number;
}

interface AggregatePoint {
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
export function meanSd(values: ArrayLike<number>, length = values.length): ColumnStats {
  // Sums from 0 in the values' order (as a reduce over the finite values), without their copy.
  let n = 0;
  let sum = 0;
  for (let k = 0; k < length; k++) {
    const v = values[k];
    if (!Number.isFinite(v)) continue;
    sum += v;
    n++;
  }
  const missing = length - n;
  if (n === 0) return { mean: NaN, sd: NaN, se: NaN, n, missing };
  const mean = sum / n;
  let squares = 0;
  if (n >= 2) {
    for (let k = 0; k < length; k++) {
      const v = values[k];
      if (Number.isFinite(v)) squares += (v - mean) ** 2;
    }
  }
  const sd = n < 2 ? NaN : Math.sqrt(squares / (n - 1));
  return { mean, sd, se: sd / Math.sqrt(n), n, missing };
}

/** Each column's position in `header` (-1 when absent), once per header and column list. */
const positionsByHeader = new WeakMap<readonly string[], { columns: readonly string[]; at: Int32Array }>();
function columnPositions(header: readonly string[], columns: readonly string[]): Int32Array {
  const kept = positionsByHeader.get(header);
  if (kept?.columns === columns) return kept.at;
  const at = Int32Array.from(columns, (column) => columnPosition(header, column));
  positionsByHeader.set(header, { columns, at });
  return at;
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
  // One group's values of one column at a time, in row order (the statistics' sums follow it).
  let largest = 0;
  for (const g of groups.values()) largest = Math.max(largest, g.length);
  const statsKeys = internKeys(numeric);
  const values = new Float64Array(largest);
  for (const g of groups.values()) {
    const point: Record<string, string> = {};
    for (const f of fields) point[f] = g[0][f] ?? '';
    const columnStats: ColumnStats[] = new Array<ColumnStats>(numeric.length);
    // A row the sweep made keeps its numbers (typedCells.ts): the same values as its text parsed.
    const typed = g.map(typedCellsOf);
    const positions = typed.map((cells) => (cells ? columnPositions(cells.header, numeric) : null));
    // The usual group: every row typed, under one header (the loop below without its tests).
    const shared = positions[0] !== null && positions.every((at) => at === positions[0]) ? positions[0] : null;
    if (shared) {
      statsByRows(
        typed.map((cells) => cells!.numbers),
        shared,
        columnStats,
      );
    } else {
      for (let c = 0; c < numeric.length; c++) {
        const column = numeric[c];
        for (let i = 0; i < g.length; i++) {
          const at = positions[i];
          values[i] = at ? (at[c] < 0 ? NaN : typed[i]!.numbers[at[c]]) : cellNumber(g[i][column]);
        }
        columnStats[c] = meanSd(values, g.length);
      }
    }
    // One record per point of a few hundred columns (records.ts: one hidden class for them all).
    points.push({ point, runs: g.length, stats: recordOf(statsKeys, columnStats) });
  }
  return { fields: [...fields], columns: numeric, points };
}

/**
 * meanSd of every column at once, the rows read one after another (each row's numbers in one
 * array, read in order: a column at a time jumped between the rows' arrays). Per column the same
 * sums in the same order as meanSd's, so the same bits: the finite values from 0 in row order,
 * then the squares about their mean in row order. `at[c]` is column c's position in a row (-1:
 * absent, a NaN).
 */
function statsByRows(rows: readonly Float64Array[], at: Int32Array, out: ColumnStats[]): void {
  const m = at.length;
  const sums = new Float64Array(m);
  const counts = new Int32Array(m);
  for (const row of rows) {
    for (let c = 0; c < m; c++) {
      const v = at[c] < 0 ? NaN : row[at[c]];
      if (!Number.isFinite(v)) continue;
      sums[c] += v;
      counts[c]++;
    }
  }
  const means = new Float64Array(m);
  for (let c = 0; c < m; c++) means[c] = sums[c] / counts[c];
  const squares = new Float64Array(m);
  for (const row of rows) {
    for (let c = 0; c < m; c++) {
      const v = at[c] < 0 ? NaN : row[at[c]];
      if (Number.isFinite(v)) squares[c] += (v - means[c]) ** 2;
    }
  }
  for (let c = 0; c < m; c++) {
    const n = counts[c];
    const missing = rows.length - n;
    if (n === 0) {
      out[c] = { mean: NaN, sd: NaN, se: NaN, n, missing };
      continue;
    }
    const sd = n < 2 ? NaN : Math.sqrt(squares[c] / (n - 1));
    out[c] = { mean: means[c], sd, se: sd / Math.sqrt(n), n, missing };
  }
}

const orEmpty = (x: number): number | string => (Number.isFinite(x) ? x : '');

/** The 95 % confidence interval of the mean (t distribution, not clamped); NaN when n < 2. */
function ci95(stats: ColumnStats): [number, number] {
  if (stats.n < 2 || !Number.isFinite(stats.se)) return [NaN, NaN];
  const half = tQuantile975(stats.n - 1) * stats.se;
  return [stats.mean - half, stats.mean + half];
}

type CsvStatistic = 'mean' | 'sd' | 'ci95low' | 'ci95high' | 'n';

/** The statistics aggregate.csv writes for a column (see the module comment); none: not written. */
function csvStatistics(column: string): readonly CsvStatistic[] {
  const metric = /^(?:labels|exact)\.([^.]+)$/.exec(column)?.[1];
  if (metric !== undefined) {
    return ['percentScutoids', 'scutoids', 'validCells', 'meanTransitions', 'meanWon', 'meanLost', 'meanNeighbours3D'].includes(metric)
      ? ['mean', 'sd', 'ci95low', 'ci95high', 'n']
      : [];
  }
  if (/^(?:labels|exact)\.[^.]+\.meanSides$/.test(column)) return ['mean', 'sd'];
  if (/^(?:labels|exact)\.[^.]+\.polygons\.[^.]+$/.test(column)) return ['mean'];
  // A column of another kind (a caller's own numbers): all of them.
  return /^(?:iterations|finalEnergy)$|^(?:labels|exact)\./.test(column) ? [] : ['mean', 'sd', 'ci95low', 'ci95high', 'n'];
}

/** The summary columns worth aggregating (numeric, with a statistic in csvStatistics). */
export function aggregateColumns(summary: readonly string[], text: ReadonlySet<string>): string[] {
  return summary.filter((c) => !text.has(c) && csvStatistics(c).length > 0);
}

/** `<column>.<statistic>`, with the column's unit last (n has none). */
function statisticColumn(column: string, statistic: CsvStatistic): string {
  const unit = statistic === 'n' ? null : columnUnit(column);
  return unit === null ? `${column}.${statistic}` : `${column}.${statistic}_${unit}`;
}

function statisticValue(stats: ColumnStats, statistic: CsvStatistic): number | string {
  if (statistic === 'n') return stats.n;
  if (statistic === 'mean') return orEmpty(stats.mean);
  if (statistic === 'sd') return orEmpty(stats.sd);
  return orEmpty(ci95(stats)[statistic === 'ci95low' ? 0 : 1]);
}

export function aggregateToCsv(agg: Aggregate): string {
  const written = agg.columns.map((c) => ({ column: c, statistics: csvStatistics(c) })).filter((w) => w.statistics.length > 0);
  const header = [...agg.fields.map(fileColumn), 'runs', ...written.flatMap(({ column, statistics }) => statistics.map((s) => statisticColumn(column, s)))];
  const rows = agg.points.map((p) => {
    const row: unknown[] = agg.fields.map((f) => p.point[f]);
    row.push(p.runs);
    for (const { column, statistics } of written) for (const s of statistics) row.push(statisticValue(p.stats[column], s));
    return row;
  });
  return formatCsv(header, rows);
}

const clean = (x: number): number | null => (Number.isFinite(x) ? x : null);

/** JSON-ready form (NaN -> null). */
export function aggregateToJson(agg: Aggregate): unknown {
  return agg.points.map((p) => {
    // The point's own keys (for...in order), in records of one hidden class per key list.
    const keys: string[] = [];
    for (const c in p.stats) keys.push(c);
    const columns = internKeys(keys);
    const stats = columns.map((c) => {
      const s = p.stats[c];
      const [low, high] = ci95(s);
      return { mean: clean(s.mean), sd: clean(s.sd), se: clean(s.se), n: s.n, missing: s.missing, ci95: [clean(low), clean(high)] };
    });
    return { point: p.point, runs: p.runs, stats: recordOf(columns, stats) };
  });
}
