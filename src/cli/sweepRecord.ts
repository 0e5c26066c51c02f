/**
 * A sweep directory's record (sweep.json: software, spec, shard) read back, and what a sweep or a
 * merge may do with a directory that already holds one. A row of runs.csv names its grid point
 * by the varied values only, and a resumed row is checked against those (resume.ts): rows
 * computed under another base config, another version of the software or another shard would
 * pass that check and be mixed, unseen, with rows of this sweep. So a directory is resumed only
 * by the sweep that wrote it.
 */
import { existsSync, lstatSync } from 'node:fs';
import { join } from 'node:path';
import { ConfigError, validateConfig } from '../core/config';
import type { Shard, ValidSweepSpec } from '../core/sweep';
import type { InputFileRecord } from '../run/result';
import { version } from '../version';
import { InputError } from './errors';
import { readJsonFile } from './prepare';
import { readRunsFile } from './sweepFiles';

export interface SweepRecord {
  software?: { name?: unknown; version?: unknown; commit?: unknown };
  renderer?: unknown;
  spec?: unknown;
  shard?: { index: number; count: number };
  /** The mesh and density files the spec points to, as read (sources.ts). */
  inputFiles?: InputFileRecord[];
}

/** Object keys sorted at every level: two specs (or configs) are the same when these texts are. */
export function canonical(value: unknown): string {
  return JSON.stringify(value, (_key, v) =>
    v && typeof v === 'object' && !Array.isArray(v) ? Object.fromEntries(Object.entries(v).sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0))) : v,
  );
}

/** sweep.json of `dir`, which must be a sweep directory of ours (InputError otherwise). */
export function readSweepRecord(dir: string): SweepRecord {
  let stat;
  try {
    stat = lstatSync(dir);
  } catch {
    throw new InputError(`${dir}: no such directory; give sweep output directories (each holding sweep.json)`);
  }
  if (!stat.isDirectory()) throw new InputError(`${dir}: is not a directory; give sweep output directories (each holding sweep.json)`);
  const path = join(dir, 'sweep.json');
  if (!existsSync(path)) throw new InputError(`${dir}: has no sweep.json; is it a tissue-sheet sweep directory?`);
  const record = readJsonFile(path, 'sweep record') as SweepRecord;
  if (
    typeof record !== 'object' ||
    record === null ||
    record.software?.name !== 'tissue-sheet' ||
    typeof record.software.version !== 'string' ||
    record.spec === undefined
  ) {
    throw new InputError(`${path}: not a tissue-sheet sweep record (no software name, version and spec)`);
  }
  return record;
}

/** The first path (`cells`, `lloyd.overRelaxation`) where two plain JSON values differ, with both values; null when equal. */
function firstDifference(a: unknown, b: unknown, path = ''): { path: string; a: unknown; b: unknown } | null {
  const isObject = (v: unknown): v is Record<string, unknown> => typeof v === 'object' && v !== null && !Array.isArray(v);
  if (isObject(a) && isObject(b)) {
    for (const key of [...new Set([...Object.keys(a), ...Object.keys(b)])].sort()) {
      const found = firstDifference(a[key], b[key], path ? `${path}.${key}` : key);
      if (found) return found;
    }
    return null;
  }
  return canonical(a) === canonical(b) ? null : { path, a, b };
}

const shardText = (shard: Shard | { index: number; count: number } | null | undefined) => (shard ? `shard ${shard.index}/${shard.count}` : 'the whole sweep');

/**
 * Refuses (InputError) to resume in `out` a sweep that did not write it: another base config
 * (compared validated, so a default written out is the same config), another software version,
 * or another shard (a shard's directory may be completed as the whole sweep, not the reverse).
 * Nothing to check where `out` holds no sweep.json (a new directory; checkOutDir judged the rest)
 * or no row yet.
 * The seed, the varied values and the realizations may change: every row is checked against them
 * and the rows that do not fit are set aside and computed again (resume.ts).
 */
export function checkResumable(out: string, spec: ValidSweepSpec, shard: Shard | null): void {
  const held = heldSweep(out);
  if (!held) return;
  const { record, path, refuse } = held;
  if (record.software!.version !== version) {
    throw refuse(`holds a sweep written by tissue-sheet ${String(record.software!.version)} (${path}), and this is ${version}`);
  }
  const validBase = (base: unknown): unknown => {
    try {
      return validateConfig(base);
    } catch (error) {
      if (error instanceof ConfigError) return null;
      throw error;
    }
  };
  const recordedBase = validBase((record.spec as { base?: unknown }).base);
  if (recordedBase === null) throw refuse(`holds a sweep whose base config is not valid for this version (${path})`);
  const difference = firstDifference(recordedBase, validBase(spec.base));
  if (difference) {
    throw refuse(`holds a sweep of another base config (base.${difference.path}: ${JSON.stringify(difference.a)} there, ${JSON.stringify(difference.b)} here)`);
  }
  const recordedShard = record.shard ?? null;
  const sameShard = recordedShard && shard && recordedShard.index === shard.index && recordedShard.count === shard.count;
  if (shard && !sameShard) throw refuse(`holds ${shardText(recordedShard)}, and this is ${shardText(shard)}`);
}

/**
 * Refuses to resume in `out` a sweep whose mesh or density files changed since its rows were
 * computed: the spec names them by path, their contents are recorded (size and SHA-256).
 */
export function checkResumedInputs(out: string, files: readonly InputFileRecord[]): void {
  const held = heldSweep(out);
  if (!held?.record.inputFiles) return;
  const before = new Map(held.record.inputFiles.map((f) => [`${f.field} ${f.src}`, f]));
  for (const file of files) {
    const old = before.get(`${file.field} ${file.src}`);
    if (old && old.sha256 !== file.sha256) {
      throw held.refuse(
        `${file.field} "${file.src}" has changed since (${old.bytes} bytes, SHA-256 ${old.sha256.slice(0, 12)}… then; ${file.bytes} bytes, ${file.sha256.slice(0, 12)}… now)`,
      );
    }
  }
}

/** The sweep `out` holds with rows computed (its record, and how to refuse to mix them), or null. */
function heldSweep(out: string): { record: SweepRecord; path: string; refuse: (why: string) => InputError } | null {
  if (!existsSync(join(out, 'sweep.json'))) return null;
  const record = readSweepRecord(out);
  // No row computed yet (a sweep stopped at once): nothing to mix.
  const lines = (readRunsFile(join(out, 'runs.csv')) ?? '').split('\n').filter((line) => line.trim() !== '');
  if (lines.length <= 1) return null;
  const refuse = (why: string) =>
    new InputError(
      `--out ${out}: ${why}; its ${lines.length - 1} rows would be mixed with this sweep's: give a new directory, or resume with the spec that wrote it`,
    );
  return { record, path: join(out, 'sweep.json'), refuse };
}
