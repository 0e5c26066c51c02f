/**
 * Writing results without writing over what we were not asked to: --out never names an input
 * file, never follows a symbolic link, and replaces an existing file only when it is a previous
 * result of ours (or with --force). Files are written atomically: a temporary file next to the
 * target, then a rename, so a reader never sees half a file.
 */
import { closeSync, existsSync, lstatSync, openSync, readdirSync, readSync, realpathSync, renameSync, rmSync, writeFileSync, writeSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { CELLS_FILE_MAGIC, cellsFileLayout, type ResultCellTables } from '../run/cellTables';
import type { SheetResult } from '../run/result';
import { EnvironmentError, InputError } from './errors';

/** Whether two paths name the same file (through links and relative parts). */
function sameFile(a: string, b: string): boolean {
  const real = (p: string) => (existsSync(p) ? realpathSync(p) : resolve(p));
  return real(a) === real(b);
}

/** The first `bytes` bytes of a file as text. */
function head(path: string, bytes = 512): string {
  const fd = openSync(path, 'r');
  try {
    const buffer = Buffer.alloc(bytes);
    const n = readSync(fd, buffer, 0, bytes, 0);
    return buffer.subarray(0, n).toString('utf8');
  } finally {
    closeSync(fd);
  }
}

/** A result JSON written by `tissue-sheet run` starts with its software record. */
const isOurResult = (path: string): boolean => /^\{\s*"software":\s*\{\s*"name":\s*"tissue-sheet"/.test(head(path));

/** Refuses an --out file that is an input, a link, a directory, or someone else's file. */
export function checkOutFile(out: string, inputs: readonly string[], force: boolean, isOurs: (path: string) => boolean = isOurResult): void {
  for (const input of inputs) {
    if (sameFile(out, input)) throw new InputError(`--out ${out}: that is the input file ${input}; give another output path`);
  }
  let stat;
  try {
    stat = lstatSync(out);
  } catch {
    if (!existsSync(dirname(resolve(out))))
      throw new InputError(`--out ${out}: the directory ${dirname(resolve(out))} does not exist; create it or give another path`);
    return; // a new file
  }
  if (stat.isSymbolicLink()) throw new InputError(`--out ${out}: is a symbolic link, which is never followed; give the path of a regular file`);
  if (stat.isDirectory()) throw new InputError(`--out ${out}: is a directory; give a file path`);
  // A sweep's record starts as a result does, but it is not one to replace.
  if (!force && (SWEEP_FILES as readonly string[]).includes(basename(out)) && isOurSweep(dirname(resolve(out)))) {
    throw new InputError(`--out ${out}: is a file of the sweep in ${dirname(resolve(out))}; give another path, or pass --force to overwrite it`);
  }
  if (!force && !isOurs(out)) {
    throw new InputError(`--out ${out}: exists and is not a tissue-sheet result; pass --force to overwrite it, or give another path`);
  }
}

/** Files a sweep writes in its output directory. */
const SWEEP_FILES = ['sweep.json', 'runs.csv', 'aggregate.csv', 'aggregate.json', 'flintstones.csv', 'runs.rejected.csv'] as const;

/**
 * Refuses an --out directory that is a link or a file, holds an input, or is a non-empty
 * directory that is not a previous sweep of ours (without --force); refuses links among the
 * files a sweep writes there.
 */
export function checkOutDir(dir: string, inputs: readonly string[], force: boolean): void {
  let stat;
  try {
    stat = lstatSync(dir);
  } catch {
    return; // created later
  }
  if (stat.isSymbolicLink()) throw new InputError(`--out ${dir}: is a symbolic link, which is never followed; give a directory path`);
  if (!stat.isDirectory()) throw new InputError(`--out ${dir}: exists and is not a directory; give a directory path`);
  for (const name of SWEEP_FILES) {
    const path = join(dir, name);
    for (const input of inputs) if (sameFile(path, input)) throw new InputError(`--out ${dir}: would overwrite the input ${input}; give another directory`);
    if (existsSync(path) || isLink(path)) {
      if (isLink(path)) throw new InputError(`--out ${dir}: ${name} is a symbolic link, which is never followed; remove it`);
    }
  }
  const entries = readdirSync(dir).filter((e) => !e.startsWith('.'));
  if (entries.length > 0 && !isOurSweep(dir) && !force) {
    throw new InputError(`--out ${dir}: is a non-empty directory that is not a tissue-sheet sweep; pass --force to write into it, or give a new directory`);
  }
}

/** Whether `dir` holds a sweep record of ours. */
function isOurSweep(dir: string): boolean {
  const record = join(dir, 'sweep.json');
  return existsSync(record) && /"name":\s*"tissue-sheet"/.test(head(record));
}

function isLink(path: string): boolean {
  try {
    return lstatSync(path).isSymbolicLink();
  } catch {
    return false;
  }
}

/** Writes `data` to `path` through a temporary file and a rename (never half a file, never through a link). */
export function writeFileAtomic(path: string, data: string): void {
  const temp = join(dirname(path), `.${basename(path)}.${process.pid}.tmp`);
  try {
    writeFileSync(temp, data, { flag: 'w' });
    renameSync(temp, path);
  } catch (error) {
    rmSync(temp, { force: true });
    throw new EnvironmentError(`cannot write ${path} (${(error as Error).message})`);
  }
}

/**
 * Above this many cell records (cells x surfaces of the stack), `tissue-sheet run` writes the
 * per-cell lists to a binary side file instead of the JSON (README, "Result JSON"): 100,000
 * records are about 100 MB of JSON.
 */
export const MAX_CELL_RECORDS_IN_JSON = 100_000;

/** The side file of a result: RESULT.json -> RESULT.cells.bin (any other name: NAME.cells.bin). */
export function cellsFilePath(out: string): string {
  return out.endsWith('.json') ? `${out.slice(0, -'.json'.length)}.cells.bin` : `${out}.cells.bin`;
}

/** A side file written by `tissue-sheet run` starts with its magic bytes. */
export const isOurCellsFile = (path: string): boolean => head(path, CELLS_FILE_MAGIC.length) === CELLS_FILE_MAGIC;

/**
 * Writes a result: the JSON alone, or with `tables` the side file (checked like --out, written
 * atomically column by column from the tables' own memory: no second copy) and then the JSON,
 * whose cell lists are null and whose `cellsFile` describes the side file.
 */
export function writeResult(out: string, result: SheetResult, tables: ResultCellTables | undefined, inputs: readonly string[], force: boolean): string | null {
  if (!tables) {
    writeFileAtomic(out, JSON.stringify(result, null, 2) + '\n');
    return null;
  }
  const side = cellsFilePath(out);
  checkOutFile(side, inputs, force, isOurCellsFile);
  const { record, chunks } = cellsFileLayout(tables, basename(side));
  writeChunksAtomic(side, chunks);
  const json = {
    ...result,
    cells: null,
    surfaces: result.surfaces.map((surface) => ({ ...surface, cells: null })),
    analyses: result.analyses.map((analysis) => ({ ...analysis, cells: null })),
    cellsFile: record,
  };
  writeFileAtomic(out, JSON.stringify(json, null, 2) + '\n');
  return side;
}

/** Writes byte chunks to `path` through a temporary file and a rename. */
function writeChunksAtomic(path: string, chunks: readonly Uint8Array[]): void {
  const temp = join(dirname(path), `.${basename(path)}.${process.pid}.tmp`);
  try {
    const fd = openSync(temp, 'w');
    try {
      for (const chunk of chunks) {
        let done = 0;
        while (done < chunk.byteLength) done += writeSync(fd, chunk, done, chunk.byteLength - done);
      }
    } finally {
      closeSync(fd);
    }
    renameSync(temp, path);
  } catch (error) {
    rmSync(temp, { force: true });
    throw new EnvironmentError(`cannot write ${path} (${(error as Error).message})`);
  }
}
