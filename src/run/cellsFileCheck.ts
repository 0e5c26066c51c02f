/**
 * The structure a side file's tables (RESULT.cells.bin, decoded by decodeCellsFile) must have
 * before anything reads them: a file from anyone is untrusted. Column bounds within the file are
 * checked where the columns are read; here, each column's type and length against its table's
 * count, neighbour lists as CSR (offsets from 0, never decreasing, ending at the list's length;
 * ids of cells of the table), every table of one result of the same count, and the values read
 * as they are (flags 0 or 1, counts >= 0, finite positions, areas and contact lengths finite and
 * >= 0). Without it a
 * wrong file gave wrong neighbours silently, and an offset of 2^31 made a reader loop for minutes.
 */
import type { AnalysisCellTable, CellTable, ResultCellTables } from './cellTables';

type Column = Float64Array | Int32Array | Uint8Array;

/** Refuses tables that break their structure, naming the file, the table and the column. */
export function checkCellTables(path: string, tables: ResultCellTables): void {
  const count = tables.cells.count;
  if (!(Number.isInteger(count) && count >= 0)) throw new Error(`${path}: cells: count ${String(count)} is not a whole number of cells`);
  checkCells(path, 'cells', tables.cells, count);
  tables.surfaces.forEach((table, k) => checkCells(path, `surfaces[${k}].cells`, table, count));
  tables.analyses.forEach((table, k) => checkAnalysis(path, `analyses[${k}].cells`, table, count));
}

function checkCells(path: string, of: string, table: CellTable, count: number): void {
  checkCount(path, of, table.count, count);
  finite(path, of, 'position', column(path, of, 'position', table.position, Float64Array, 3 * count));
  finite(path, of, 'surface', column(path, of, 'surface', table.surface, Float64Array, 2 * count));
  measures(path, of, 'area', column(path, of, 'area', table.area, Float64Array, count));
  flags(path, of, 'touchesBorder', column(path, of, 'touchesBorder', table.touchesBorder, Uint8Array, count));
  const offsets = column(path, of, 'neighbourOffsets', table.neighbourOffsets, Int32Array, count + 1);
  const ids = table.neighbourIds;
  if (offsets[0] !== 0) throw new Error(`${path}: ${of}.neighbourOffsets starts at ${offsets[0]}, not 0`);
  for (let i = 0; i < count; i++) {
    if (offsets[i + 1] < offsets[i]) throw new Error(`${path}: ${of}.neighbourOffsets decreases at cell ${i}`);
  }
  column(path, of, 'neighbourIds', ids, Int32Array, offsets[count]);
  measures(path, of, 'neighbourLengths', column(path, of, 'neighbourLengths', table.neighbourLengths, Float64Array, offsets[count]));
  for (let k = 0; k < ids.length; k++) {
    if (!(ids[k] >= 0 && ids[k] < count)) throw new Error(`${path}: ${of}.neighbourIds[${k}] is ${ids[k]}, not a cell of the ${count}`);
  }
}

function checkAnalysis(path: string, of: string, table: AnalysisCellTable, count: number): void {
  checkCount(path, of, table.count, count);
  flags(path, of, 'valid', column(path, of, 'valid', table.valid, Uint8Array, count));
  flags(path, of, 'scutoid', column(path, of, 'scutoid', table.scutoid, Uint8Array, count));
  for (const name of ['won', 'lost', 'transitions', 'neighbours3D'] as const) counts(path, of, name, column(path, of, name, table[name], Int32Array, count));
  // Side counts per surface, surface-major: a whole number of surfaces.
  const sides = table.sides;
  if (!(sides instanceof Int32Array) || (count > 0 ? sides.length % count !== 0 : sides.length !== 0)) {
    throw new Error(`${path}: ${of}.sides holds ${sides.length} values, not a whole number of surfaces of ${count} cells`);
  }
  counts(path, of, 'sides', sides);
}

/**
 * The values the views and exports read as they are: flags 0 or 1 (a `valid` of 7 was drawn as
 * a border cell while the summary counted it), counts never negative, positions finite (the JSON
 * form is refused otherwise too: app/model/project.ts).
 */
function flags(path: string, of: string, name: string, values: Uint8Array): void {
  const k = values.findIndex((v) => v > 1);
  if (k >= 0) throw new Error(`${path}: ${of}.${name}[${k}] is ${values[k]}, not 0 or 1`);
}

function counts(path: string, of: string, name: string, values: Int32Array): void {
  const k = values.findIndex((v) => v < 0);
  if (k >= 0) throw new Error(`${path}: ${of}.${name}[${k}] is ${values[k]}, not a count`);
}

function finite(path: string, of: string, name: string, values: Float64Array): void {
  const k = values.findIndex((v) => !Number.isFinite(v));
  if (k >= 0) throw new Error(`${path}: ${of}.${name}[${k}] is ${values[k]}, not a finite number`);
}

/** Areas (µm²) and contact lengths (µm): an area of -1e300 was shown and summed as a cell's. */
function measures(path: string, of: string, name: string, values: Float64Array): void {
  const k = values.findIndex((v) => !(Number.isFinite(v) && v >= 0));
  if (k >= 0) throw new Error(`${path}: ${of}.${name}[${k}] is ${values[k]}, not a finite measure >= 0`);
}

function checkCount(path: string, of: string, actual: number, count: number): void {
  if (actual !== count) throw new Error(`${path}: ${of} has ${String(actual)} cells where the file's cells table has ${count}`);
}

/** The column, once its type and length are the expected ones. */
function column<T extends Column>(path: string, of: string, name: string, values: Column, type: { new (length: number): T; name: string }, length: number): T {
  if (!(values instanceof type)) throw new Error(`${path}: ${of}.${name} must be ${typeName(type.name)}`);
  if (values.length !== length) throw new Error(`${path}: ${of}.${name} holds ${values.length} values where ${length} are expected`);
  return values;
}

function typeName(constructorName: string): string {
  return constructorName === 'Float64Array' ? 'float64' : constructorName === 'Int32Array' ? 'int32' : 'uint8';
}
