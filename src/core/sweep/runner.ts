/**
 * The sweep loop: calls an injected runner for every run that is not done yet, and appends one
 * tidy CSV row per run as soon as it completes, so an interrupted sweep resumes where it stopped.
 *
 * Row layout: `key`, the varied fields (CSV text of the value), `realization`, `seed`, then the
 * summary columns. Summary columns are `options.summaryColumns` (the CLI passes the union every
 * grid point produces, see columns.ts, and an existing header must equal it), else the header
 * of the existing CSV when resuming, else the flattened keys (see `flattenSummary`) of the
 * first summary to complete; the header is appended together with the first row when the file
 * has none. A summary missing a column leaves the cell empty; a summary with a column the
 * header lacks fails its run (never a silently dropped value).
 *
 * Resume: `existingCsv` is what the output already holds. Runs whose key appears in it are
 * skipped (`remainingRuns`). If it ends with an incomplete record (a write was cut off), the loop
 * calls `truncate(validLength)` before appending, or throws when no `truncate` is given. An
 * existing header that lacks the key, varied, realization and seed columns is an error, and so
 * is a done row whose seed differs from the run's (the spec changed).
 *
 * Errors: with `onError: 'throw'` (default) the first failing run stops the sweep (rows already
 * appended stay, so a rerun resumes); with 'skip' failures are collected and the sweep goes on.
 * `concurrency` runs that many at once (default 1); rows are appended in completion order.
 * An aborted `signal` stops starting new runs.
 */
import { flattenSummary, formatCsvRow, readCsvTable } from './csv';
import type { Config, SweepRun } from './expand';
import { valueText } from './expand';

export type SweepRunner<C extends Config, S> = (config: C, run: SweepRun<C>) => Promise<S>;

export interface SweepProgress<C extends Config = Config> {
  phase: 'start' | 'done' | 'error';
  run: SweepRun<C>;
  /** Runs finished in this invocation (done or failed). */
  finished: number;
  /** Runs this invocation has to do. */
  total: number;
  /** Runs already done before this invocation. */
  skipped: number;
  elapsedMs: number;
  error?: unknown;
}

export interface RunSweepOptions<C extends Config, S> {
  runs: SweepRun<C>[];
  fields: string[];
  runner: SweepRunner<C, S>;
  append: (text: string) => void | Promise<void>;
  existingCsv?: string;
  truncate?: (length: number) => void | Promise<void>;
  summaryColumns?: string[];
  onProgress?: (p: SweepProgress<C>) => void;
  onError?: 'throw' | 'skip';
  concurrency?: number;
  signal?: AbortSignal;
}

export interface RunSweepResult<C extends Config> {
  header: string[];
  /** Rows already present plus rows appended now, as objects. */
  rows: Record<string, string>[];
  completed: number;
  skipped: number;
  failed: { run: SweepRun<C>; error: unknown }[];
  aborted: boolean;
}

export function baseColumns(fields: readonly string[]): string[] {
  return ['key', ...fields, 'realization', 'seed'];
}

export interface ResumeState<C extends Config> {
  remaining: SweepRun<C>[];
  done: SweepRun<C>[];
  /** Done rows whose seed differs from the run's seed. */
  mismatched: SweepRun<C>[];
}

/** Which runs remain given the rows already written (matched by `key`). */
export function remainingRuns<C extends Config>(runs: readonly SweepRun<C>[], rows: readonly Record<string, string>[]): ResumeState<C> {
  const byKey = new Map<string, Record<string, string>>();
  for (const r of rows) if (r.key !== undefined) byKey.set(r.key, r);
  const remaining: SweepRun<C>[] = [];
  const done: SweepRun<C>[] = [];
  const mismatched: SweepRun<C>[] = [];
  for (const run of runs) {
    const row = byKey.get(run.key);
    if (!row) remaining.push(run);
    else {
      done.push(run);
      if (row.seed !== undefined && row.seed !== String(run.seed)) mismatched.push(run);
    }
  }
  return { remaining, done, mismatched };
}

/**
 * The cells of one run's row in `header` order, typed (numbers stay numbers, so the CSV writer
 * never treats them as text), and the same row as the text a reader gets back. A summary
 * column missing from the header is an error: the header is fixed before the first run and
 * must cover every column (see columns.ts), and a dropped column would be a silent lie.
 */
export function runCells<C extends Config>(run: SweepRun<C>, fields: readonly string[], summary: unknown, header: readonly string[]): { cells: unknown[]; row: Record<string, string> } {
  const flat = flattenSummary(summary);
  const base = new Map<string, unknown>([['key', run.key], ['realization', run.realization], ['seed', run.seed]]);
  for (const f of fields) base.set(f, valueText(run.point[f]));
  const known = new Set(header);
  const extra = Object.keys(flat).find((c) => !known.has(c) && !base.has(c));
  if (extra !== undefined) throw new Error(`run ${run.key}: its summary has a column "${extra}" that the sweep's header lacks`);
  const cells = header.map((h) => (base.has(h) ? base.get(h) : Object.prototype.hasOwnProperty.call(flat, h) ? flat[h] : undefined));
  const row: Record<string, string> = {};
  header.forEach((h, k) => {
    const v = cells[k];
    row[h] = v === null || v === undefined ? '' : typeof v === 'string' ? v : typeof v === 'object' ? JSON.stringify(v) : String(v);
  });
  return { cells, row };
}

/** The text cells of one run's row (see runCells). */
export function runRow<C extends Config>(run: SweepRun<C>, fields: readonly string[], summary: unknown, header: readonly string[]): Record<string, string> {
  return runCells(run, fields, summary, header).row;
}

export async function runSweep<C extends Config, S>(options: RunSweepOptions<C, S>): Promise<RunSweepResult<C>> {
  const { runs, fields, runner } = options;
  const existing = readCsvTable(options.existingCsv ?? '');
  let header: string[] | null = existing.header.length > 0 ? existing.header : null;
  if (header) {
    const missing = baseColumns(fields).filter((c) => !header!.includes(c));
    if (missing.length > 0) throw new Error(`existing sweep CSV lacks columns: ${missing.join(', ')}`);
    if (options.summaryColumns) {
      const expected = [...baseColumns(fields), ...options.summaryColumns];
      if (expected.length !== header.length || expected.some((c, k) => header![k] !== c)) {
        throw new Error('existing sweep CSV has another header than this sweep writes');
      }
    }
  }
  if (existing.truncated) {
    if (!options.truncate) throw new Error(`existing sweep CSV ends with an incomplete row; truncate it to ${existing.validLength} characters`);
    await options.truncate(existing.validLength);
    if (existing.validLength === 0) header = null;
  }
  const state = remainingRuns(runs, existing.rows);
  if (state.mismatched.length > 0) {
    throw new Error(`existing sweep CSV has rows with other seeds (e.g. ${state.mismatched[0].key}); the spec changed`);
  }
  const rows = [...existing.rows];
  const failed: { run: SweepRun<C>; error: unknown }[] = [];
  const total = state.remaining.length;
  const skipped = state.done.length;
  const t0 = Date.now();
  let finished = 0;
  let completed = 0;
  let next = 0;
  let stop = false;
  let aborted = false;
  // Appends are serialized through this chain, in completion order.
  let writes: Promise<void> = Promise.resolve();

  const write = (run: SweepRun<C>, summary: S): Promise<void> => {
    writes = writes.then(async () => {
      let text = '';
      if (!header) {
        const summaryColumns = options.summaryColumns ?? Object.keys(flattenSummary(summary)).filter((c) => !baseColumns(fields).includes(c));
        header = [...baseColumns(fields), ...summaryColumns];
        text += formatCsvRow(header);
      }
      const { cells, row } = runCells(run, fields, summary, header);
      text += formatCsvRow(cells);
      await options.append(text);
      rows.push(row);
    });
    return writes;
  };

  const worker = async (): Promise<void> => {
    while (!stop) {
      if (options.signal?.aborted) {
        aborted = true;
        return;
      }
      if (next >= state.remaining.length) return;
      const run = state.remaining[next++];
      options.onProgress?.({ phase: 'start', run, finished, total, skipped, elapsedMs: Date.now() - t0 });
      try {
        const summary = await runner(run.config, run);
        await write(run, summary);
        finished++;
        completed++;
        options.onProgress?.({ phase: 'done', run, finished, total, skipped, elapsedMs: Date.now() - t0 });
      } catch (error) {
        finished++;
        failed.push({ run, error });
        options.onProgress?.({ phase: 'error', run, finished, total, skipped, elapsedMs: Date.now() - t0, error });
        if ((options.onError ?? 'throw') === 'throw') {
          stop = true;
          throw error;
        }
      }
    }
  };

  const n = Math.max(1, Math.floor(options.concurrency ?? 1));
  await Promise.all(Array.from({ length: Math.min(n, Math.max(1, total)) }, worker));
  await writes;
  return { header: header ?? baseColumns(fields), rows, completed, skipped, failed, aborted };
}


