/**
 * The result's per-cell data as columns (typed arrays) instead of one object per cell, and the
 * documented binary side file `tissue-sheet run` writes them to where a JSON result would be
 * huge (README, "Result JSON"; docs/benchmark.md, "A million cells"). Pure: no file system.
 *
 * Side file: the 8 bytes "TSCELLS1", 8 bytes zero, then every column's raw little-endian values,
 * each starting at a multiple of 8 bytes. The result JSON's `cellsFile` says where each column is:
 * `tables[]`, one per cell list of the JSON (`of`: "cells", "surfaces[k].cells",
 * "analyses[k].cells"), each with `count` and `columns`: {name: {type, offset, length}} (type
 * float64, int32 or uint8; offset in bytes from the start of the file; length in values). Two
 * columns with the same values may name the same bytes (written once).
 *
 * Columns of a surface's cells ("cells", "surfaces[k].cells"), cell i of n:
 * - position: float64 x 3n, (x, y, z) of cell i at 3i (µm); surface: float64 x 2n, (u, v) at 2i
 * - area: float64 x n (µm²); touchesBorder: uint8 x n (1 or 0)
 * - neighbourOffsets: int32 x (n + 1); cell i's neighbours are entries neighbourOffsets[i] to
 *   neighbourOffsets[i + 1] - 1 of neighbourIds (int32, ascending per cell) and
 *   neighbourLengths (float64, shared boundary length in µm)
 * Columns of an analysis's cells ("analyses[k].cells"): valid, scutoid (uint8 x n), won, lost,
 * transitions, neighbours3D (int32 x n), sides (int32 x S·n: surface s of cell i at s·n + i, S
 * surfaces in stack order). The ids are the indices.
 * Every value is the one the JSON would hold (float64 throughout: a result read back from the
 * side file equals the JSON one bit for bit). Tables are read-only: they may share arrays with
 * the adjacency the pipeline keeps for reuse.
 */
import type { SurfaceAdjacency } from '../core/analysis';
import type { CellStatistics } from '../core/analysis/scutoids';
import { cellStatisticsRecords, type AnalysisRecord, type CellStatisticsRecord } from '../core/analysis/record';
import type { CellRecord, SheetResult } from './result';
import { checkCellTables } from './cellsFileCheck';

/** The cells of one surface as columns (see the module comment). */
export interface CellTable {
  readonly count: number;
  readonly position: Float64Array;
  readonly surface: Float64Array;
  readonly area: Float64Array;
  readonly touchesBorder: Uint8Array;
  readonly neighbourOffsets: Int32Array;
  readonly neighbourIds: Int32Array;
  readonly neighbourLengths: Float64Array;
}

/** An analysis's per-cell statistics as columns (sides: surface-major, S x count). */
export interface AnalysisCellTable {
  readonly count: number;
  readonly valid: Uint8Array;
  readonly scutoid: Uint8Array;
  readonly won: Int32Array;
  readonly lost: Int32Array;
  readonly transitions: Int32Array;
  readonly neighbours3D: Int32Array;
  readonly sides: Int32Array;
}

/** Every per-cell list of a result as columns: what `runSheet(..., {cellTables: true})` gives. */
export interface ResultCellTables {
  /** The seeded surface (the JSON's `cells`). */
  readonly cells: CellTable;
  /** In the order of `surfaces`. */
  readonly surfaces: CellTable[];
  /** In the order of `analyses`. */
  readonly analyses: AnalysisCellTable[];
}

/** The JSON's description of the side file. */
export interface CellsFileRecord {
  /** File name, in the result JSON's directory. */
  readonly path: string;
  readonly format: typeof CELLS_FILE_FORMAT;
  readonly byteOrder: 'little-endian';
  readonly bytes: number;
  readonly tables: CellsFileTable[];
}

interface CellsFileTable {
  readonly of: string;
  readonly count: number;
  readonly columns: Record<string, CellsFileColumn>;
}

interface CellsFileColumn {
  readonly type: 'float64' | 'int32' | 'uint8';
  readonly offset: number;
  readonly length: number;
}

export const CELLS_FILE_FORMAT = 'tissue-sheet cells 1';
/** The side file's first 8 bytes. */
export const CELLS_FILE_MAGIC = 'TSCELLS1';
const HEADER_BYTES = 16;

type Column = Float64Array | Int32Array | Uint8Array;

/** Columns of a surface's cells from its adjacency, `placeAll` filling the position and surface columns. */
export function cellTable(surface: SurfaceAdjacency, placeAll: (position: Float64Array, coordinates: Float64Array) => void): CellTable {
  const n = surface.count;
  const { offsets, neighbours, lengths } = surface;
  const position = new Float64Array(3 * n);
  const coordinates = new Float64Array(2 * n);
  const touchesBorder = new Uint8Array(n);
  placeAll(position, coordinates);
  for (let id = 0; id < n; id++) touchesBorder[id] = surface.border[id] !== 0 ? 1 : 0;
  const total = offsets[n];
  // The adjacency's own arrays where they already have the columns' type and length (the exact
  // method's), else copies: no second copy of a million cells' contacts.
  return {
    count: n,
    position,
    surface: coordinates,
    area: surface.areas instanceof Float64Array && surface.areas.length === n ? surface.areas : Float64Array.from(surface.areas),
    touchesBorder,
    neighbourOffsets: offsets.length === n + 1 ? offsets : Int32Array.from(offsets.subarray(0, n + 1)),
    neighbourIds: neighbours.length === total ? neighbours : Int32Array.from(neighbours.subarray(0, total)),
    neighbourLengths:
      lengths instanceof Float64Array && lengths.length === total ? lengths : lengths ? Float64Array.from(lengths.subarray(0, total)) : new Float64Array(total),
  };
}

/** The JSON's cell records from a table. */
export function cellRecordsOf(table: CellTable): CellRecord[] {
  return cellRecordsRange(table, 0, table.count);
}

/** Cells `from` to `to` - 1 of cellRecordsOf (the page builds a large result's records in slices). */
export function cellRecordsRange(table: CellTable, from: number, to: number): CellRecord[] {
  const cells: CellRecord[] = [];
  const { position: p, surface: s, neighbourOffsets: offsets, neighbourIds: ids, neighbourLengths: lengths } = table;
  for (let id = from; id < to; id++) {
    const neighbours = [];
    for (let k = offsets[id]; k < offsets[id + 1]; k++) neighbours.push({ id: ids[k], length: lengths[k] });
    cells.push({
      id,
      position: [p[3 * id], p[3 * id + 1], p[3 * id + 2]],
      surface: [s[2 * id], s[2 * id + 1]],
      area: table.area[id],
      neighbours,
      touchesBorder: table.touchesBorder[id] === 1,
    });
  }
  return cells;
}

/** Columns of an analysis's per-cell statistics. */
export function analysisCellTable(cells: CellStatistics): AnalysisCellTable {
  const n = cells.valid.length;
  const sides = new Int32Array(cells.sides.length * n);
  cells.sides.forEach((perSurface, k) => sides.set(perSurface, k * n));
  return {
    count: n,
    valid: cells.valid,
    scutoid: cells.scutoid,
    won: cells.won,
    lost: cells.lost,
    transitions: cells.transitions,
    neighbours3D: cells.neighbours3D,
    sides,
  };
}

/** The JSON's per-cell statistics records from a table (as analysisRecord writes them). */
export function analysisCellRecordsOf(table: AnalysisCellTable): CellStatisticsRecord[] {
  return analysisCellRecordsRange(table, 0, table.count);
}

/** Cells `from` to `to` - 1 of analysisCellRecordsOf. */
export function analysisCellRecordsRange(table: AnalysisCellTable, from: number, to: number): CellStatisticsRecord[] {
  const n = table.count;
  const surfaces = n > 0 ? table.sides.length / n : 0;
  return cellStatisticsRecords(table, (id) => Array.from({ length: surfaces }, (_, k) => table.sides[k * n + id]), from, to);
}

const CELL_COLUMNS = ['position', 'surface', 'area', 'touchesBorder', 'neighbourOffsets', 'neighbourIds', 'neighbourLengths'] as const;
const ANALYSIS_COLUMNS = ['valid', 'scutoid', 'won', 'lost', 'transitions', 'neighbours3D', 'sides'] as const;

function typeOf(column: Column): CellsFileColumn['type'] {
  return column instanceof Float64Array ? 'float64' : column instanceof Int32Array ? 'int32' : 'uint8';
}

/**
 * Lays out the side file: its JSON record and the byte chunks to write in order (the header,
 * then each column's own bytes and zero padding: nothing is copied).
 */
export function cellsFileLayout(tables: ResultCellTables, path: string): { record: CellsFileRecord; chunks: Uint8Array[] } {
  const header = new Uint8Array(HEADER_BYTES);
  for (let k = 0; k < CELLS_FILE_MAGIC.length; k++) header[k] = CELLS_FILE_MAGIC.charCodeAt(k);
  const chunks: Uint8Array[] = [header];
  let offset = HEADER_BYTES;
  const entries: CellsFileTable[] = [];
  // A column that is the same array as an earlier one (a plane's two surfaces share their
  // adjacency) is written once: both entries name the same bytes.
  const written = new Map<Column, number>();
  const add = (of: string, count: number, names: readonly string[], source: Record<string, Column>) => {
    const columns: Record<string, CellsFileColumn> = {};
    for (const name of names) {
      const column = source[name];
      const earlier = written.get(column);
      if (earlier !== undefined) {
        columns[name] = { type: typeOf(column), offset: earlier, length: column.length };
        continue;
      }
      written.set(column, offset);
      columns[name] = { type: typeOf(column), offset, length: column.length };
      chunks.push(new Uint8Array(column.buffer, column.byteOffset, column.byteLength));
      offset += column.byteLength;
      const pad = (8 - (offset % 8)) % 8;
      if (pad > 0) {
        chunks.push(new Uint8Array(pad));
        offset += pad;
      }
    }
    entries.push({ of, count, columns });
  };
  const asColumns = (table: CellTable | AnalysisCellTable) => table as unknown as Record<string, Column>;
  add('cells', tables.cells.count, CELL_COLUMNS, asColumns(tables.cells));
  tables.surfaces.forEach((table, k) => add(`surfaces[${k}].cells`, table.count, CELL_COLUMNS, asColumns(table)));
  tables.analyses.forEach((table, k) => add(`analyses[${k}].cells`, table.count, ANALYSIS_COLUMNS, asColumns(table)));
  return { record: { path, format: CELLS_FILE_FORMAT, byteOrder: 'little-endian', bytes: offset, tables: entries }, chunks };
}

/** The tables of a side file (its bytes) as its JSON record describes them; refuses a mismatch. */
export function decodeCellsFile(record: CellsFileRecord, bytes: Uint8Array): ResultCellTables {
  if (record.format !== CELLS_FILE_FORMAT) throw new Error(`cellsFile.format: "${String(record.format)}" is not "${CELLS_FILE_FORMAT}"`);
  if (bytes.byteLength !== record.bytes) throw new Error(`${record.path}: ${bytes.byteLength} bytes where the result says ${record.bytes}`);
  const magic = String.fromCharCode(...bytes.subarray(0, CELLS_FILE_MAGIC.length));
  if (magic !== CELLS_FILE_MAGIC) throw new Error(`${record.path}: not a tissue-sheet cells file (no ${CELLS_FILE_MAGIC} header)`);
  // Aligned views need an 8-aligned start: copy once if the bytes are not.
  const data = bytes.byteOffset % 8 === 0 ? bytes : bytes.slice();
  const read = (table: CellsFileTable, name: string): Column => {
    const c = table.columns[name];
    if (!c) throw new Error(`${record.path}: ${table.of} has no column ${name}`);
    const size = c.type === 'float64' ? 8 : c.type === 'int32' ? 4 : 1;
    if (!(
      Number.isInteger(c.offset) &&
      Number.isInteger(c.length) &&
      c.offset >= HEADER_BYTES &&
      c.offset % size === 0 &&
      c.offset + c.length * size <= data.byteLength
    )) {
      throw new Error(`${record.path}: ${table.of}.${name} lies outside the file`);
    }
    const at = data.byteOffset + c.offset;
    return c.type === 'float64'
      ? new Float64Array(data.buffer, at, c.length)
      : c.type === 'int32'
        ? new Int32Array(data.buffer, at, c.length)
        : new Uint8Array(data.buffer, at, c.length);
  };
  const find = (of: string) => {
    const table = record.tables.find((t) => t.of === of);
    if (!table) throw new Error(`${record.path}: no table for ${of}`);
    return table;
  };
  // Every column of the table named in `names`, in that order, with its count.
  const columnsOf = (of: string, names: readonly string[]): Record<string, number | Column> => {
    const t = find(of);
    const table: Record<string, number | Column> = { count: t.count };
    for (const name of names) table[name] = read(t, name);
    return table;
  };
  const cellsOf = (of: string) => columnsOf(of, CELL_COLUMNS) as unknown as CellTable;
  const analysisOf = (of: string) => columnsOf(of, ANALYSIS_COLUMNS) as unknown as AnalysisCellTable;
  const surfaces = record.tables.filter((t) => /^surfaces\[\d+\]\.cells$/.test(t.of)).map((t) => cellsOf(t.of));
  const analyses = record.tables.filter((t) => /^analyses\[\d+\]\.cells$/.test(t.of)).map((t) => analysisOf(t.of));
  const tables = { cells: cellsOf('cells'), surfaces, analyses };
  checkCellTables(record.path, tables);
  return tables;
}

/** A result JSON written with a side file, as a plain SheetResult: every cell list filled from the tables. */
export function withCellRecords(result: SheetResult & { cellsFile?: CellsFileRecord }, tables: ResultCellTables): SheetResult {
  const { cellsFile: _file, ...rest } = result;
  return {
    ...rest,
    cells: cellRecordsOf(tables.cells),
    surfaces: result.surfaces.map((surface, k) => ({ ...surface, cells: cellRecordsOf(tables.surfaces[k]) })),
    analyses: result.analyses.map((analysis: AnalysisRecord, k) => ({ ...analysis, cells: analysisCellRecordsOf(tables.analyses[k]) })),
  };
}
