/**
 * `tissue-sheet merge DIR... --out DIR`: joins sweep directories (shards of one sweep, or partial
 * runs of it) into one sweep directory, written as the unsharded sweep writes it: runs.csv in the
 * same order, aggregate.csv/json, flintstones.csv, sweep.json.
 *
 * - Every DIR must hold a sweep.json of ours; all must record the same spec, the same input files
 *   (mesh, density: size and SHA-256) and the same software version (else exit 2 naming the first that differs): rows of another spec or version would
 *   mix numbers that are not comparable.
 * - Every runs.csv is validated as a resumed one is (header, key, seed, columns: resume.ts); bad
 *   rows are reported by file and line and left out.
 * - A run found in several DIRs (a shard given twice, a shard rerun) is counted once: the first
 *   DIR's row is kept, with a warning when the rows differ.
 * - --out must not hold a sweep's rows already (merge writes runs.csv anew), unless --force.
 * - Runs that no DIR holds are reported; the aggregate then covers the runs present (its n says
 *   so), and `tissue-sheet sweep SPEC --out DIR` on the merged directory computes the rest.
 */
import { existsSync, mkdirSync, realpathSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileHeader, formatCsvRow, planResume, ResumeError, sortRowsByRuns, validateSweepSpec } from '../core/sweep';
import { version } from '../version';
import { InputError } from './errors';
import { lockDirectory } from './lock';
import { checkOutDir, writeFileAtomic } from './output';
import { sweepLayout } from '../run/sweepLayout';
import { gitCommitSoon, readRunsFile, writeAggregates } from './sweepFiles';
import { canonical, readSweepRecord } from './sweepRecord';

const USAGE = 'usage: tissue-sheet merge DIR... --out DIR [--force]';

interface MergeOptions {
  dirs: string[];
  out: string;
  force: boolean;
}

export function parseMergeArgs(args: string[]): MergeOptions {
  const dirs: string[] = [];
  let out: string | undefined;
  let force = false;
  for (let i = 0; i < args.length; i++) {
    const arg = args[i];
    const [name, inline] = arg.startsWith('--') && arg.includes('=') ? [arg.slice(0, arg.indexOf('=')), arg.slice(arg.indexOf('=') + 1)] : [arg, undefined];
    if (name === '--out' || name === '-o') {
      out = inline ?? args[++i];
      if (out === undefined || out === '') throw new InputError(`--out needs a value; ${USAGE}`);
    } else if (name === '--force') {
      if (inline !== undefined) throw new InputError(`--force takes no value (got ${JSON.stringify(arg)}); ${USAGE}`);
      force = true;
    } else if (arg.startsWith('-') && arg !== '-') throw new InputError(`unknown option ${name}; ${USAGE}`);
    else dirs.push(arg);
  }
  if (dirs.length === 0) throw new InputError(`missing sweep directories to merge; ${USAGE}`);
  if (!out) throw new InputError(`missing --out; ${USAGE}`);
  return { dirs, out, force };
}

export async function mergeCommand(args: string[], log: (line: string) => void): Promise<void> {
  const started = new Date().toISOString();
  const options = parseMergeArgs(args);
  const real = (p: string) => (existsSync(p) ? realpathSync(p) : resolve(p));
  for (const dir of options.dirs) {
    if (real(dir) === real(options.out)) throw new InputError(`--out ${options.out}: is also an input (${dir}); merge into a new directory`);
  }
  const records = options.dirs.map((dir) => ({ dir, record: readSweepRecord(dir) }));
  const first = records[0];
  // One version may span commits (a checkout between shards): said, not refused.
  const commits = [...new Set(records.map((r) => r.record.software!.commit).filter((c): c is string => typeof c === 'string'))];
  if (commits.length > 1)
    log(
      `warning: the directories were written by ${commits.length} commits of tissue-sheet ${String(first.record.software!.version)} (${commits.map((c) => c.slice(0, 10)).join(', ')}); their rows are merged as one version's`,
    );
  for (const { dir, record } of records.slice(1)) {
    if (record.software!.version !== first.record.software!.version) {
      throw new InputError(
        `${join(dir, 'sweep.json')}: written by tissue-sheet ${String(record.software!.version)}, ${join(first.dir, 'sweep.json')} by ${String(first.record.software!.version)}; merge only shards of one version`,
      );
    }
    if (canonical(record.spec) !== canonical(first.record.spec)) {
      throw new InputError(`${join(dir, 'sweep.json')}: another spec than ${join(first.dir, 'sweep.json')}; merge only shards of one sweep spec`);
    }
    // The same spec over other contents of its mesh or density files is another sweep.
    if (canonical(record.inputFiles ?? []) !== canonical(first.record.inputFiles ?? [])) {
      throw new InputError(
        `${join(dir, 'sweep.json')}: read other mesh or density files than ${join(first.dir, 'sweep.json')} (inputFiles: sizes or SHA-256 differ); merge only shards of one sweep`,
      );
    }
  }
  let spec;
  try {
    spec = validateSweepSpec(first.record.spec, { maxRuns: Number.MAX_SAFE_INTEGER });
  } catch (error) {
    throw new InputError(`${join(first.dir, 'sweep.json')}: its spec is not valid for tissue-sheet ${version} (${(error as Error).message})`);
  }
  const layout = sweepLayout(spec);
  checkOutDir(
    options.out,
    options.dirs.map((d) => join(d, 'runs.csv')),
    options.force,
  );
  // merge writes runs.csv anew: a sweep's rows already there would be lost (merged into a new
  // directory with the others, they are kept).
  const rowsThere = (readRunsFile(join(options.out, 'runs.csv')) ?? '').split('\n').filter((line) => line.trim() !== '').length - 1;
  if (rowsThere > 0 && !options.force) {
    throw new InputError(
      `--out ${options.out}: holds a sweep with ${rowsThere} rows in runs.csv, which merge would replace; merge into a new directory, with this one among the inputs to keep its rows, or pass --force to replace them`,
    );
  }

  const t0 = performance.now();
  const kept = new Map<string, { row: Record<string, string>; dir: string; text: string }>();
  let repeated = 0;
  let differing = 0;
  let rejected = 0;
  for (const { dir } of records) {
    const path = join(dir, 'runs.csv');
    const text = readRunsFile(path);
    if (text === null) {
      log(`warning: ${path}: missing; that directory adds no runs`);
      continue;
    }
    let plan;
    try {
      plan = planResume(text, layout.resume, path);
    } catch (error) {
      if (error instanceof ResumeError) throw new InputError(error.message);
      throw error;
    }
    for (const bad of plan.rejected.slice(0, 20)) log(`warning: ${path}:${bad.line}: ${bad.reason}; left out`);
    rejected += plan.rejected.length;
    for (const row of plan.rows) {
      const text = formatCsvRow(layout.header.map((h) => row[h]));
      const seen = kept.get(row.key);
      if (!seen) {
        kept.set(row.key, { row, dir, text });
        continue;
      }
      repeated++;
      if (seen.text !== text) {
        differing++;
        if (differing <= 5) log(`warning: run ${row.key} is in ${seen.dir} and ${dir} with different values; keeping ${seen.dir}'s`);
      }
    }
  }
  const rows = sortRowsByRuns(
    [...kept.values()].map((k) => k.row),
    layout.ordered,
  );
  const missing = layout.runs.filter((run) => !kept.has(run.key));

  mkdirSync(options.out, { recursive: true });
  const release = lockDirectory(options.out, log);
  try {
    writeFileAtomic(
      join(options.out, 'runs.csv'),
      formatCsvRow(fileHeader(layout.header)) + rows.map((r) => formatCsvRow(layout.header.map((h) => r[h]))).join(''),
    );
    await writeAggregates(options.out, rows, layout, log);
    const renderers = [...new Set(records.map((r) => String(r.record.renderer)))];
    writeFileAtomic(
      join(options.out, 'sweep.json'),
      JSON.stringify(
        {
          software: { name: 'tissue-sheet', version: first.record.software!.version, commit: await gitCommitSoon() },
          renderer: renderers.length === 1 ? renderers[0] : renderers,
          started,
          runs: layout.runs.length,
          ended: new Date().toISOString(),
          merged: { from: options.dirs, rows: rows.length, missing: missing.length, repeated, differing, rejected, mergedBy: version },
          ...(first.record.inputFiles ? { inputFiles: first.record.inputFiles } : {}),
          spec: first.record.spec,
        },
        null,
        2,
      ) + '\n',
    );
  } finally {
    release();
  }
  if (missing.length > 0) {
    log(
      `warning: ${missing.length} of ${layout.runs.length} runs are in none of the directories (e.g. ${missing[0].key}); the aggregate covers the ${rows.length} present. Run the missing shards and merge again, or run \`tissue-sheet sweep SPEC --out ${options.out}\` to compute them`,
    );
  }
  log(
    `merge: ${rows.length} runs from ${options.dirs.length} directories (${repeated} repeated, ${rejected} bad rows left out) in ${((performance.now() - t0) / 1000).toFixed(2)} s -> ${options.out}`,
  );
}
