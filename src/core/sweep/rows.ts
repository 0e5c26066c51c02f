/**
 * One run's row of runs.csv: its cells in the header's order (typed: numbers stay numbers), the
 * same row as the text a reader gets back, and its CSV line; the flat summary a sweep thread
 * hands over (a key list and values). runSweep (runner.ts) makes a row this way as each run
 * finishes.
 */
import { csvField, flattenSummary } from './csv';
import type { ConfigObject, SweepRun } from './expand';
import { valueText } from './expand';
import { recordOf } from './records';
import { keepTypedCells } from './typedCells';

/**
 * The cells of one run's row in `header` order, typed (numbers stay numbers, so the CSV writer
 * never treats them as text), and the same row as the text a reader gets back. A summary
 * column missing from the header is an error: the header is fixed before the first run and
 * must cover every column (see columns.ts), and a dropped column would be a silent lie.
 */
export function runCells<C extends ConfigObject>(
  run: SweepRun<C>,
  fields: readonly string[],
  summary: unknown,
  header: readonly string[],
  values?: Readonly<Record<string, unknown>>,
): { cells: unknown[]; row: Record<string, string>; line: string } {
  const base = new Map<string, unknown>([
    ['key', run.key],
    ['realization', run.realization],
    ['seed', run.seed],
  ]);
  for (const f of fields) base.set(f, valueText(run.point[f]));
  if (values) for (const [k, v] of Object.entries(values)) base.set(k, v);
  const known = headerSet(header);
  let cells: unknown[];
  if (isFlatList(summary)) {
    // Values by position: where each header column's value is, once per key list and header;
    // then the base's values in their columns (a base column's value wins, as below).
    const at = listPositions(summary.keys, header, known, base, run.key);
    const values = summary.values;
    cells = new Array<unknown>(header.length);
    for (let k = 0; k < header.length; k++) cells[k] = at[k] >= 0 ? values[at[k]] : undefined;
    const where = headerPositions(header);
    for (const [column, value] of base) for (const k of where.get(column) ?? []) cells[k] = value;
  } else {
    const flat = flattenSummary(summary);
    for (const c in flat) {
      if (!known.has(c) && !base.has(c)) throw new Error(`run ${run.key}: its summary has a column "${c}" that the sweep's header lacks`);
    }
    cells = header.map((h) => (base.has(h) ? base.get(h) : Object.prototype.hasOwnProperty.call(flat, h) ? flat[h] : undefined));
  }
  // The record's text from the same conversions (a number's text is its CSV field as it is:
  // String(n) never needs quotes), so each number is turned into text once.
  const texts: string[] = new Array<string>(header.length);
  const parts: string[] = new Array<string>(header.length);
  for (let k = 0; k < header.length; k++) {
    const v = cells[k];
    const text =
      typeof v === 'number'
        ? numberText(v)
        : v === null || v === undefined
          ? ''
          : typeof v === 'string'
            ? v
            : typeof v === 'object'
              ? JSON.stringify(v)
              : String(v);
    texts[k] = text;
    parts[k] = typeof v === 'number' || typeof v === 'bigint' || typeof v === 'boolean' || text === '' ? text : csvField(v);
  }
  // A record of one hidden class per header (records.ts): the sweep keeps every row to its end.
  const row = recordOf(header, texts);
  keepTypedCells(row, header, cells);
  // One flat string now (a join), not a chain of hundreds of concatenations flattened when the
  // row is written: rows are made as runs finish, written in a burst after the last one.
  return { cells, row, line: `${parts.join(',')}\r\n` };
}

/**
 * String(n), from a bounded cache: a sweep's numbers repeat (polygon fractions are counts over
 * a few valid-cell counts, 10,000 distinct values among 340,000 in the published sweep), and
 * the shortest round-trip text of a double costs several times a lookup. 0 and -0 share an
 * entry, as they share their text ("0").
 */
const numberTexts = new Map<number, string>();
function numberText(n: number): string {
  let text = numberTexts.get(n);
  if (text === undefined) {
    text = String(n);
    if (numberTexts.size >= 1 << 16) numberTexts.clear();
    numberTexts.set(n, text);
  }
  return text;
}

/** Each header's positions of every column name (all of them, should a name repeat), once per header. */
const headerPositionsKept = new WeakMap<readonly string[], Map<string, number[]>>();
function headerPositions(header: readonly string[]): Map<string, number[]> {
  let where = headerPositionsKept.get(header);
  if (!where) {
    where = new Map();
    header.forEach((h, k) => {
      const list = where!.get(h);
      if (list) list.push(k);
      else where!.set(h, [k]);
    });
    headerPositionsKept.set(header, where);
  }
  return where;
}

/** Each header's column names as a set, made once per header (runCells runs once per run). */
const headerSets = new WeakMap<readonly string[], Set<string>>();
function headerSet(header: readonly string[]): Set<string> {
  let set = headerSets.get(header);
  if (!set) headerSets.set(header, (set = new Set(header)));
  return set;
}

/**
 * A flat summary as its column names and values side by side (a sweep thread's message), so no
 * object of hundreds of keys is built per run; the names are one array per shape of summary.
 */
export interface FlatList {
  readonly keys: readonly string[];
  readonly values: readonly unknown[];
}

const FLAT_LIST: unique symbol = Symbol('flat sweep summary as a key list');

/** Marks `keys` (unique column names) and `values` as one flat summary for runCells. */
export function flatList(keys: readonly string[], values: readonly unknown[]): FlatList {
  return Object.defineProperty({ keys, values }, FLAT_LIST, { value: true, enumerable: false });
}

function isFlatList(summary: unknown): summary is FlatList {
  return typeof summary === 'object' && summary !== null && (summary as { [FLAT_LIST]?: boolean })[FLAT_LIST] === true;
}

/** Per key list, per header: the position in the list of each header column's value (-1: none). */
const listPositionsKept = new WeakMap<readonly string[], WeakMap<readonly string[], Int32Array>>();

/**
 * Where each of `header`'s columns is in `keys`, checking (as for a record) that every key is a
 * header column or a base column; the check depends on the base's columns only through the
 * fields and run values, the same for every run of a sweep, but is repeated where a key is missing.
 */
function listPositions(keys: readonly string[], header: readonly string[], known: Set<string>, base: Map<string, unknown>, runKey: string): Int32Array {
  let byHeader = listPositionsKept.get(keys);
  const kept = byHeader?.get(header);
  if (kept) return kept;
  const index = new Map(keys.map((k, n) => [k, n]));
  for (const c of keys) {
    if (!known.has(c) && !base.has(c)) throw new Error(`run ${runKey}: its summary has a column "${c}" that the sweep's header lacks`);
  }
  const at = Int32Array.from(header, (h) => index.get(h) ?? -1);
  // Kept only where every key is a header column: the check then holds for any base.
  if (keys.every((c) => known.has(c))) {
    if (!byHeader) listPositionsKept.set(keys, (byHeader = new WeakMap()));
    byHeader.set(header, at);
  }
  return at;
}
