/**
 * Writing results without writing over what we were not asked to: --out never names an input
 * file, never follows a symbolic link, and replaces an existing file only when it is a previous
 * result of ours (or with --force). Files are written atomically: a temporary file next to the
 * target, then a rename, so a reader never sees half a file.
 */
import { closeSync, existsSync, lstatSync, openSync, readdirSync, readSync, realpathSync, renameSync, rmSync, writeFileSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
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
export const isOurResult = (path: string): boolean => /^\{\s*"software":\s*\{\s*"name":\s*"tissue-sheet"/.test(head(path));

/** Refuses an --out file that is an input, a link, a directory, or someone else's file. */
export function checkOutFile(out: string, inputs: readonly string[], force: boolean, isOurs: (path: string) => boolean = isOurResult): void {
  for (const input of inputs) {
    if (sameFile(out, input)) throw new InputError(`--out ${out}: that is the input file ${input}; give another output path`);
  }
  let stat;
  try {
    stat = lstatSync(out);
  } catch {
    if (!existsSync(dirname(resolve(out)))) throw new InputError(`--out ${out}: the directory ${dirname(resolve(out))} does not exist; create it or give another path`);
    return; // a new file
  }
  if (stat.isSymbolicLink()) throw new InputError(`--out ${out}: is a symbolic link, which is never followed; give the path of a regular file`);
  if (stat.isDirectory()) throw new InputError(`--out ${out}: is a directory; give a file path`);
  if (!force && !isOurs(out)) {
    throw new InputError(`--out ${out}: exists and is not a tissue-sheet result; pass --force to overwrite it, or give another path`);
  }
}

/** Files a sweep writes in its output directory. */
export const SWEEP_FILES = ['sweep.json', 'runs.csv', 'aggregate.csv', 'aggregate.json', 'flintstones.csv', 'runs.rejected.csv'] as const;

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
  const ours = existsSync(join(dir, 'sweep.json')) && /"name":\s*"tissue-sheet"/.test(head(join(dir, 'sweep.json')));
  if (entries.length > 0 && !ours && !force) {
    throw new InputError(`--out ${dir}: is a non-empty directory that is not a tissue-sheet sweep; pass --force to write into it, or give a new directory`);
  }
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
