/**
 * A large result's per-cell records made when first read, from its side file's columns
 * (cellTables.ts), instead of all at once (issue 27): 300,000 records of a 100,000-cell result
 * (about 2.5 million objects with their neighbour lists) held the page's main thread for a long
 * task of allocation and then of garbage collection, while a page reads a handful of them (the
 * rows in view, the picked cell). A list is an array (Array.isArray, JSON.stringify, map, for..of
 * see every record, each made once and kept) behind a Proxy. Not structured-cloneable: send
 * the columns to a worker, not the records.
 */
import { analysisCellRecordsRange, cellRecordsRange, type AnalysisCellTable, type ResultCellTables } from './cellTables';
import type { SheetResult } from './result';

const INDEX = /^(?:0|[1-9]\d*)$/;

/** An array of `count` records, record i made by `make(i)` when first read. */
export function lazyRecords<T>(count: number, make: (i: number) => T): T[] {
  const made: (T | undefined)[] = new Array<T | undefined>(count);
  const index = (key: string | symbol) => (typeof key === 'string' && INDEX.test(key) ? Number(key) : -1);
  const at = (target: (T | undefined)[], i: number) => (target[i] ??= make(i));
  return new Proxy(made, {
    get(target, key, receiver) {
      const i = index(key);
      return i >= 0 && i < count ? at(target, i) : Reflect.get(target, key, receiver);
    },
    has(target, key) {
      const i = index(key);
      return (i >= 0 && i < count) || Reflect.has(target, key);
    },
    getOwnPropertyDescriptor(target, key) {
      const i = index(key);
      if (i >= 0 && i < count) return { value: at(target, i), writable: true, enumerable: true, configurable: true };
      return Reflect.getOwnPropertyDescriptor(target, key);
    },
    ownKeys(target) {
      return [...Array.from({ length: count }, (_, i) => String(i)), ...Reflect.ownKeys(target).filter((key) => index(key) < 0)];
    },
  }) as T[];
}

const analysisTables = new WeakMap<object, AnalysisCellTable>();
// Keyed by the result's lazy cell list, which a copy of the result (a new headline) keeps.
const resultTables = new WeakMap<object, ResultCellTables>();

/** The columns behind a result whose cell lists are lazy (withLazyCellRecords), or null. */
export function resultColumns(result: SheetResult): ResultCellTables | null {
  return (result.cells && resultTables.get(result.cells)) ?? null;
}

/** The columns behind an analysis's lazy cell records (withLazyCellRecords), or null. */
export function analysisColumns(cells: object | null | undefined): AnalysisCellTable | null {
  return (cells && analysisTables.get(cells)) ?? null;
}

/** withCellRecords (cellTables.ts) of `result` (its cell lists null or absent) with lazy lists. */
export function withLazyCellRecords(result: SheetResult, tables: ResultCellTables): SheetResult {
  const cells = (table: ResultCellTables['cells']) => lazyRecords(table.count, (i) => cellRecordsRange(table, i, i + 1)[0]);
  const lazy: SheetResult = {
    ...result,
    cells: cells(tables.cells),
    surfaces: result.surfaces.map((s, k) => ({ ...s, cells: cells(tables.surfaces[k]) })),
    analyses: result.analyses.map((a, k) => {
      const table = tables.analyses[k];
      const list = lazyRecords(table.count, (i) => analysisCellRecordsRange(table, i, i + 1)[0]);
      analysisTables.set(list, table);
      return { ...a, cells: list };
    }),
  };
  resultTables.set(lazy.cells, tables);
  return lazy;
}
