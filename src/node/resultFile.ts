/**
 * Reads a result written by `tissue-sheet run`: the JSON and, where the per-cell lists were
 * written to a side file (README, "Result JSON"), that file next to it, decoded into columns.
 * `records: true` also fills the JSON's cell lists from the columns (a plain SheetResult, as a
 * small run writes it; millions of objects for a million cells).
 */
import { readFileSync } from 'node:fs';
import { basename, dirname, join } from 'node:path';
import { decodeCellsFile, withCellRecords, type CellsFileRecord, type ResultCellTables } from '../run/cellTables';
import type { SheetResult } from '../run/result';

export interface ResultFile {
  /** The JSON; its cell lists are null where `tables` holds them, unless read with `records`. */
  readonly result: SheetResult & { readonly cellsFile?: CellsFileRecord };
  /** The side file's columns; null for a result written as JSON alone. */
  readonly tables: ResultCellTables | null;
}

export function readResultFile(path: string, options: { records?: boolean } = {}): ResultFile {
  const result = JSON.parse(readFileSync(path, 'utf8')) as ResultFile['result'];
  const record = result.cellsFile;
  if (!record) return { result, tables: null };
  // The side file is named relative to the JSON and never leaves its directory.
  if (typeof record.path !== 'string' || basename(record.path) !== record.path || record.path.startsWith('.')) {
    throw new Error(`${path}: cellsFile.path ${JSON.stringify(record.path)} is not a file name in the result's directory`);
  }
  const bytes = readFileSync(join(dirname(path), record.path));
  const tables = decodeCellsFile(record, new Uint8Array(bytes.buffer, bytes.byteOffset, bytes.byteLength));
  return { result: options.records ? withCellRecords(result, tables) : result, tables };
}
