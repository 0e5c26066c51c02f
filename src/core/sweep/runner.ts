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
 * finished are appended, so a rerun resumes); with 'skip' failures are collected and the sweep
 * goes on. An aborted `signal` stops starting new runs.
 *
 * Parallel runs: `concurrency` tasks at once (default 1). A task is one run, or with `tasks` the
 * runs sharing a `tasks.key` (in `runs` order; tasks start in order of their first run), computed
 * together by `tasks.run`, which reports each run as it finishes (e.g. a worker that relaxes one
 * Lloyd run for every Voronoi k). Rows are appended in `runs` order whatever order runs finish
 * in, so the file is the same for any concurrency: a finished run waits for the runs before it.
 * When the sweep stops early (an error, an abort) the finished rows still waiting are appended
 * too, in `runs` order, so no finished run is lost.
 */
import { flattenSummary, formatCsvRow, readCsvTable } from './csv';
import { fileHeader, plainColumn } from './units';
import type { ConfigObject, SweepRun } from './expand';
import { runCells } from './rows';

export type SweepRunner<C extends ConfigObject, S> = (config: C, run: SweepRun<C>) => Promise<S>;

/**
 * Computes a task's runs (given in `runs` order) and calls `done` once per run as it finishes,
 * in any order; rejects on the first failure (runs already reported stay done).
 */
type SweepTaskRunner<C extends ConfigObject, S> = (runs: SweepRun<C>[], done: (run: SweepRun<C>, summary: S) => void) => Promise<void>;

export interface SweepProgress<C extends ConfigObject = ConfigObject> {
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

export interface RunSweepOptions<C extends ConfigObject, S> {
  runs: SweepRun<C>[];
  fields: string[];
  runner: SweepRunner<C, S>;
  append: (text: string) => void | Promise<void>;
  existingCsv?: string;
  truncate?: (length: number) => void | Promise<void>;
  summaryColumns?: string[];
  /**
   * Values a run's row carries beside its summary (e.g. its base geometry), by column; they
   * take their columns' places in the header (summaryColumns) without being copied into the
   * summary.
   */
  runValues?: (run: SweepRun<C>) => Readonly<Record<string, unknown>>;
  onProgress?: (p: SweepProgress<C>) => void;
  onError?: 'throw' | 'skip';
  concurrency?: number;
  /**
   * Runs computed together: those with the same key form one task, run by `run`. Tasks start in
   * order of their first run, or as `before` sorts their first runs (stable), e.g. the tasks of one
   * Lloyd run next to each other; rows are still written in `runs` order.
   */
  tasks?: { key: (run: SweepRun<C>) => string; run: SweepTaskRunner<C, S>; before?: (a: SweepRun<C>, b: SweepRun<C>) => number };
  signal?: AbortSignal;
}

export interface RunSweepResult<C extends ConfigObject> {
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

interface ResumeState<C extends ConfigObject> {
  remaining: SweepRun<C>[];
  done: SweepRun<C>[];
  /** Done rows whose seed differs from the run's seed. */
  mismatched: SweepRun<C>[];
}

/** Which runs remain given the rows already written (matched by `key`). */
export function remainingRuns<C extends ConfigObject>(runs: readonly SweepRun<C>[], rows: readonly Record<string, string>[]): ResumeState<C> {
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
 * A runs.csv's table with the plain column names (units removed from the header: units.ts), as
 * the program's rows use them.
 */
export function readRunsCsv(text: string): ReturnType<typeof readCsvTable> {
  const table = readCsvTable(text);
  if (table.header.length === 0) return table;
  const plain = table.header.map(plainColumn);
  const rows = table.rows.map((row) => Object.fromEntries(table.header.map((h, k) => [plain[k], row[h]])));
  return { ...table, header: plain, rows };
}

/** A finished run waiting for its turn in the file, with its row when it could be formatted already. */
type Finished<C extends ConfigObject, S> =
  | { readonly run: SweepRun<C>; readonly summary: S; readonly cells?: undefined }
  | { readonly run: SweepRun<C>; readonly summary?: undefined; readonly cells: { row: Record<string, string>; line: string } };

export async function runSweep<C extends ConfigObject, S>(options: RunSweepOptions<C, S>): Promise<RunSweepResult<C>> {
  const { runs, fields, runner } = options;
  const existing = readRunsCsv(options.existingCsv ?? '');
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
  const remaining = state.remaining;
  const total = remaining.length;
  const skipped = state.done.length;
  const t0 = Date.now();
  let finished = 0;
  let completed = 0;
  let stop = false;
  let aborted = false;

  // Rows go out in `runs` order: finished summaries wait in `ready` until every run before them
  // has finished (or failed); appends are serialized through `writes`.
  const position = new Map(remaining.map((run, k) => [run.key, k]));
  const ready = new Map<number, Finished<C, S> | null>();
  let cursor = 0;
  let writes: Promise<void> = Promise.resolve();
  /** The 'done' progress of each finished run, given once its row is appended. */
  const announcements = new Map<string, () => void>();
  // The file's header, when it is fixed before any run (given, or the existing file's): a row is
  // then formatted as soon as its run finishes, while later runs are still computing, instead of
  // when every run before it has finished (most rows of a sweep wait for the last realization).
  const fixedHeader = header ?? (options.summaryColumns ? [...baseColumns(fields), ...options.summaryColumns] : null);
  const formatted = (run: SweepRun<C>, summary: S): Finished<C, S> => {
    if (!fixedHeader) return { run, summary };
    try {
      // The summary is not kept once its row is made (it would live on until the row's turn).
      // Its row and line only: the typed cells are not kept (the row keeps its numbers).
      const { row, line } = runCells(run, fields, summary, fixedHeader, options.runValues?.(run));
      return { run, cells: { row, line } };
    } catch {
      // A row that cannot be made fails when its turn comes to be written, as it always did.
      return { run, summary };
    }
  };
  const writeRows = (items: Finished<C, S>[]): Promise<void> => {
    if (items.length === 0) return writes;
    // One append per row (the header with the first), as a caller reading each append expects.
    writes = writes.then(async () => {
      for (const item of items) {
        const { run } = item;
        let text = '';
        if (!header) {
          // No row is formatted before the header is fixed (`formatted`): the item has its summary.
          const summary = item.summary as S;
          const summaryColumns = options.summaryColumns ?? Object.keys(flattenSummary(summary)).filter((c) => !baseColumns(fields).includes(c));
          header = [...baseColumns(fields), ...summaryColumns];
          text += formatCsvRow(fileHeader(header));
        }
        const { row, line } = item.cells ?? runCells(run, fields, item.summary, header, options.runValues?.(run));
        text += line;
        await options.append(text);
        rows.push(row);
        // 'done' once the run's row is in the file (rows go out in run order, so a finished
        // run may wait here for an earlier one): a listener reading the file then finds it.
        const announce = announcements.get(run.key);
        announcements.delete(run.key);
        announce?.();
      }
    });
    return writes;
  };
  /** Appends the finished prefix; `all`: every finished row, past gaps too (the sweep stopped). */
  const flush = (all = false): Promise<void> => {
    const items: Finished<C, S>[] = [];
    while (cursor < remaining.length && (ready.has(cursor) || all)) {
      const item = ready.get(cursor);
      ready.delete(cursor);
      if (item) items.push(item);
      cursor++;
    }
    return writeRows(items);
  };

  const settle = (run: SweepRun<C>, summary: S | null): Promise<void> => {
    const at = position.get(run.key);
    if (at === undefined || at < cursor || ready.has(at)) throw new Error(`run ${run.key}: reported twice or not a run of this sweep`);
    ready.set(at, summary === null ? null : formatted(run, summary));
    return flush();
  };

  const fail = (run: SweepRun<C>, error: unknown): void => {
    finished++;
    failed.push({ run, error });
    options.onProgress?.({ phase: 'error', run, finished, total, skipped, elapsedMs: Date.now() - t0, error });
    if ((options.onError ?? 'throw') === 'throw') stop = true;
  };

  // Tasks: single runs, or the runs sharing a task key (in `runs` order).
  const taskList: SweepRun<C>[][] = [];
  if (options.tasks) {
    const byKey = new Map<string, SweepRun<C>[]>();
    for (const run of remaining) {
      const key = options.tasks.key(run);
      let task = byKey.get(key);
      if (!task) {
        byKey.set(key, (task = []));
        taskList.push(task);
      }
      task.push(run);
    }
    const before = options.tasks.before;
    if (before) taskList.sort((a, b) => before(a[0], b[0]));
  } else {
    for (const run of remaining) taskList.push([run]);
  }
  const runTask: SweepTaskRunner<C, S> =
    options.tasks?.run ??
    (async (task, done) => {
      for (const run of task) done(run, await runner(run.config, run));
    });

  let nextTask = 0;
  let firstError: unknown = undefined;
  let thrown = false;
  const lane = async (): Promise<void> => {
    while (!stop) {
      if (options.signal?.aborted) {
        aborted = true;
        return;
      }
      if (nextTask >= taskList.length) return;
      const task = taskList[nextTask++];
      const pending = new Set(task.map((run) => run.key));
      for (const run of task) options.onProgress?.({ phase: 'start', run, finished, total, skipped, elapsedMs: Date.now() - t0 });
      let written: Promise<void> = Promise.resolve();
      try {
        await runTask(task, (run, summary) => {
          if (!pending.delete(run.key)) throw new Error(`run ${run.key}: reported twice or not in its task`);
          finished++;
          completed++;
          const done: SweepProgress<C> = { phase: 'done', run, finished, total, skipped, elapsedMs: Date.now() - t0 };
          announcements.set(run.key, () => options.onProgress?.(done));
          written = settle(run, summary);
        });
        await written;
        if (pending.size > 0) throw new Error(`a sweep task ended without ${pending.size} of its runs`);
      } catch (error) {
        await written.catch(() => {});
        // The task's unfinished runs failed (the first with the error; where failures are
        // skipped, the others too: they were not computed).
        const left = task.filter((run) => pending.has(run.key));
        const skipping = (options.onError ?? 'throw') === 'skip';
        for (const run of skipping ? left : left.slice(0, 1)) fail(run, error);
        for (const run of left) settle(run, null).catch(() => {});
        if ((options.onError ?? 'throw') === 'throw' && !thrown) {
          thrown = true;
          firstError = error;
        }
        if (stop) return;
      }
    }
  };

  const n = Math.max(1, Math.floor(options.concurrency ?? 1));
  await Promise.all(Array.from({ length: Math.min(n, Math.max(1, taskList.length)) }, lane));
  // Stopped early: the finished rows after a gap are kept too.
  await flush(true);
  await writes;
  if (thrown) throw firstError;
  return { header: header ?? baseColumns(fields), rows, completed, skipped, failed, aborted };
}
