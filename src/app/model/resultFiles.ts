/**
 * Opening files chosen together in the page (issue 27): a project, a result JSON, or a result
 * JSON with its cells side file (`tissue-sheet run` writes RESULT.json + RESULT.cells.bin where
 * the JSON would be huge: the JSON's cell lists are null and its `cellsFile` names the side file).
 * Both files are read with the library's own readers (decodeCellsFile, withCellRecords) and the
 * result is then checked as any result (model/project.ts). One file of the pair alone is refused
 * with a message naming the missing one.
 */
import { decodeCellsFile, withCellRecords, type CellsFileRecord } from '../../run/cellTables';
import type { SheetResult } from '../../run';
import { openParsed, parseFileJson, type OpenedFile } from './project';

/** What the page needs of a chosen or dropped file (a File is one). */
export interface GivenFile {
  readonly name: string;
  readonly size: number;
  text(): Promise<string>;
  arrayBuffer(): Promise<ArrayBuffer>;
}

/** Largest JSON file the page opens, bytes (a side file may be larger: it is columns, read once). */
const MAX_JSON_BYTES = 256 * 1024 * 1024;
/** Largest cells side file the page opens, bytes (a million cells with a thickness is ~0.6 GB). */
const MAX_CELLS_FILE_BYTES = 1024 * 1024 * 1024;

const isSideFile = (file: GivenFile) => /\.cells\.bin$/i.test(file.name) || /\.bin$/i.test(file.name);

/**
 * Opens a result JSON (`data`, parsed) with its side file off the main thread (openClient.ts);
 * without one, the pair is opened here.
 */
export type SideFileOpener = (data: unknown, record: CellsFileRecord, side: GivenFile, name: string) => Promise<OpenedFile>;

/**
 * A JSON over this many bytes chosen alone (a project, or a result with its cells inline) is
 * read, parsed and checked off the main thread when the page can (openWhole): a 25,000-cell
 * project (28 MB) held it ~0.5 s (issue 27). A result JSON with a side file is ~15 kB.
 */
export const WORKER_JSON_BYTES = 4 * 1024 * 1024;

/** Opens a large JSON chosen alone off the main thread (openClient.ts). */
export type WholeFileOpener = (json: GivenFile, name: string) => Promise<OpenedFile>;

/** The file opened from `files` (one JSON, or a result JSON and its side file) and its name. */
export async function openFiles(
  files: readonly GivenFile[],
  openSide?: SideFileOpener,
  openWhole?: WholeFileOpener,
): Promise<{ file: OpenedFile; name: string }> {
  if (files.length === 0) throw new Error('No file was given.');
  const sides = files.filter(isSideFile);
  const jsons = files.filter((f) => !isSideFile(f));
  if (jsons.length > 1 || sides.length > 1 || files.length > 2) {
    throw new Error(`${files.map((f) => f.name).join(', ')}: open one project or result JSON, or one result JSON with its .cells.bin side file.`);
  }
  if (jsons.length === 0) {
    const side = sides[0].name;
    throw new Error(
      `${side} is a cells side file: choose it together with its result JSON (${side.replace(/\.cells\.bin$/i, '.json')}, the file whose cellsFile.path names it).`,
    );
  }
  const json = jsons[0];
  if (json.size > MAX_JSON_BYTES) throw new Error(`${json.name}: ${json.size} bytes; a project or result file over 256 MiB is refused.`);
  if (openWhole && sides.length === 0 && json.size > WORKER_JSON_BYTES) return { file: await openWhole(json, json.name), name: json.name };
  const data = parseFileJson(await json.text(), json.name);
  const record = cellsFileOf(data);
  if (!record) {
    if (sides.length)
      throw new Error(`${json.name} has no cellsFile: its cells are in the JSON, so ${sides[0].name} is not its side file; open the JSON alone.`);
    return { file: openParsed(data, json.name), name: json.name };
  }
  const side = sides[0];
  if (!side) {
    throw new Error(`${json.name}: its cells are in the side file ${record.path} (written beside it by tissue-sheet run); choose or drop both files together.`);
  }
  if (side.name !== record.path) {
    throw new Error(`${json.name}: its cells are in ${record.path}, not in ${side.name}; choose or drop ${json.name} with ${record.path}.`);
  }
  if (side.size > MAX_CELLS_FILE_BYTES) throw new Error(`${side.name}: ${side.size} bytes; a cells file over 1 GiB is refused.`);
  if (openSide) return { file: await openSide(data, record, side, json.name), name: `${json.name} + ${side.name}` };
  let result: SheetResult;
  try {
    const tables = decodeCellsFile(record, new Uint8Array(await side.arrayBuffer()));
    result = withCellRecords(data as SheetResult & { cellsFile: CellsFileRecord }, tables);
  } catch (error) {
    throw new Error(`${json.name} with ${side.name}: ${(error as Error).message}`);
  }
  return { file: openParsed(result, json.name), name: `${json.name} + ${side.name}` };
}

/** The JSON's `cellsFile` record, when it has one (a result written with a side file). */
function cellsFileOf(data: unknown): CellsFileRecord | null {
  if (typeof data !== 'object' || data === null || !('cellsFile' in data)) return null;
  const record = (data as { cellsFile: unknown }).cellsFile;
  if (typeof record !== 'object' || record === null || typeof (record as CellsFileRecord).path !== 'string') {
    throw new Error('cellsFile: expected {path, format, byteOrder, bytes, tables} as tissue-sheet run writes it.');
  }
  return record as CellsFileRecord;
}
