/**
 * A parameter sweep in the page, for the app and `<tissue-sheet>` alike, doing what
 * `tissue-sheet sweep` does (src/cli/sweep.ts) with the same code from src/core/sweep:
 * - the spec is validated by validateSweepSpec (one-line errors naming the field), expanded by
 *   expandSweep (same keys and seeds), and every grid point is validated and checked before the
 *   first run (errors name the point);
 * - runs.csv has the CLI's header (baseColumns + sweepColumns over the grid points) and rows
 *   (runSweep + sweepSummary); aggregate.csv is aggregateRows/aggregateToCsv over its numeric
 *   columns;
 * - runs sharing a seeded surface (same config but for `sheet`) run one after another, as in the
 *   CLI, so the pipeline relaxes each realization once and reuses it for every ratio/thickness;
 * - a previous runs.csv of the same spec (a download) resumes the sweep: planResume keeps its
 *   valid rows (bad ones are reported and computed again), only the missing runs are computed;
 * - cancelling (the signal) keeps every finished run: the result then has `aborted: true`.
 * The pipeline runs on a pool of workers of the sweep's own (acquirePipelineRunner, see
 * defaultPageWorkers), given back at the end; each takes one realization's Lloyd run (chainKey).
 */
import { ConfigError, validateConfig, type Config } from '../core/config';
import { surfaceLayout } from '../core/config/surfaceLayout';
import {
  aggregateColumns,
  aggregateRows,
  aggregateToCsv,
  fileHeader,
  flintstonesProblems,
  formatCsvRow,
  meanSd,
  parseCsv,
  planResume,
  runSweep,
  sweepFlintstones,
  SweepSpecError,
  TEXT_COLUMNS,
  validateSweepSpec,
  type Aggregate,
  type ColumnStats,
  type RejectedRow,
  type ResumePlan,
  type SweepFlintstonesFit,
  type SweepRun,
  type ValidSweepSpec,
} from '../core/sweep';
import { cachedFitter, fitOutcome, pointsKey, type FitOutcome } from '../core/sweep/fitOutcomes';
import { sweepSummary, type WorkerSheetRunner } from '../run';
import { yieldToEventLoop } from '../run/relax';
import { chainKey } from '../run/runSheet';
import { seedGroups, sweepLayout, type Run, type SweepLayout } from '../run/sweepLayout';
import { tQuantile975 } from '../core/analysis/realizations';
import { acquirePipelineRunner, isAbort, releasePipelineRunner, runInputs } from './pageRunner';

export interface PageSweepProgress {
  phase: 'done' | 'error';
  /** Runs finished in this call (done or failed), and how many it has to do. */
  finished: number;
  total: number;
  /** Runs taken from the resumed runs.csv. */
  skipped: number;
  elapsedMs: number;
  /** The run that just finished: its key, grid point, realization and seed. */
  run: { key: string; point: Record<string, unknown>; realization: number; seed: number };
  /** Its runs.csv row (text cells, as the file holds them); absent when it failed. */
  row?: Record<string, string>;
  error?: string;
}

export interface PageSweepOptions {
  signal?: AbortSignal;
  /** runs.csv of an earlier (partial) sweep of the same spec: its runs are not computed again. */
  resumeCsv?: string;
  /** Largest number of runs accepted (validateSweepSpec's default otherwise). */
  maxRuns?: number;
  onProgress?: (progress: PageSweepProgress) => void;
  /** Pipeline workers to spread the runs over; default defaultPageWorkers(). */
  workers?: number;
}

/** At most this many pipeline workers for one sweep: each holds its own pipeline and surfaces. */
const MAX_PAGE_WORKERS = 8;

/**
 * The page's default number of sweep workers: the browser's cores (hardwareConcurrency) less one
 * for the page itself, at least 1, at most MAX_PAGE_WORKERS. As many busy workers as cores
 * starve the main thread (the app's own pipeline worker is there too): its tasks then run
 * past 50 ms in wall time.
 */
function defaultPageWorkers(): number {
  const cores = typeof navigator !== 'undefined' && Number.isInteger(navigator.hardwareConcurrency) ? navigator.hardwareConcurrency : 2;
  return Math.max(1, Math.min(MAX_PAGE_WORKERS, cores - 1));
}

export interface PageSweepResult {
  spec: ValidSweepSpec;
  /** Varied fields, in the spec's order. */
  fields: string[];
  /** runs.csv's columns. */
  header: string[];
  /** runs.csv's rows (resumed ones first, then in completion order), as text cells. */
  runs: Record<string, string>[];
  aggregate: Aggregate;
  runsCsv: string;
  aggregateCsv: string;
  completed: number;
  skipped: number;
  /** Rows of the resumed runs.csv that were dropped (and computed again), with why. */
  rejected: RejectedRow[];
  /** True when the signal stopped the sweep: `runs` holds the runs finished until then. */
  aborted: boolean;
  /** Pipeline workers the runs were spread over. */
  workers: number;
}

/** Everything fixed before the first run: the spec and its layout (the CLI's: src/run/sweepLayout.ts). */
export interface SweepPlan extends SweepLayout {
  spec: ValidSweepSpec;
}

/** Plans already made, by spec object: a panel plans before it runs, and runs plan again. */
const plans = new WeakMap<object, { maxRuns?: number; plan: SweepPlan }>();

export function planSweep(input: unknown, maxRuns?: number): SweepPlan {
  const known = typeof input === 'object' && input !== null ? plans.get(input) : undefined;
  if (known && known.maxRuns === maxRuns) return known.plan;
  const spec = validateSweepSpec(input, maxRuns === undefined ? {} : { maxRuns });
  const plan = { ...sweepLayout(spec, pointConfig), spec };
  if (typeof input === 'object' && input !== null) plans.set(input, { maxRuns, plan });
  return plan;
}

/**
 * The rows of an earlier runs.csv that a resume of this plan keeps, and those it sets aside with
 * why (planResume, as sweepInPage reads it): what the panel draws for a loaded file, so a row of
 * another configuration never reaches the chart. Throws, naming the file, where the file is not
 * a runs.csv of this spec (another header).
 */
export function resumableRows(plan: SweepPlan, csv: string): { rows: Record<string, string>[]; rejected: RejectedRow[] } {
  const { rows, rejected } = resumeOf(plan, csv);
  return { rows, rejected };
}

/** The last resume planned: the panel asks for the same plan and file at load, to offer Resume and to run. */
let lastResume: { plan: SweepPlan; csv: string; resume: ResumePlan } | null = null;

function resumeOf(plan: SweepPlan, csv: string): ResumePlan {
  if (lastResume?.plan !== plan || lastResume.csv !== csv) lastResume = { plan, csv, resume: planResume(csv, { ...plan.resume, runs: plan.ordered }) };
  return lastResume.resume;
}

/** A grid point's validated, feasible config; errors name the point. */
function pointConfig(run: Run): Config {
  try {
    const config = validateConfig(run.config);
    surfaceLayout(config).checkFeasible();
    return config;
  } catch (error) {
    if (error instanceof ConfigError) throw new SweepSpecError(error.field, `grid point ${run.pointKey || '(base)'}: ${error.message}`);
    throw error;
  }
}

export async function sweepInPage(input: unknown, options: PageSweepOptions = {}): Promise<PageSweepResult> {
  const plan = planSweep(input, options.maxRuns);
  const { spec, fields, ordered: runs, header, summary } = plan;
  const resumed = resumeOf(plan, options.resumeCsv ?? '');
  let csv = resumed.cleanText;
  const rows = [...resumed.rows];
  // Each run's row by its key: a progress event names its run, whose row is already appended.
  const rowByKey = new Map<string, Record<string, string>>();
  const started = performance.now();
  // A pool of pipeline workers, one task at a time each. A task is one Lloyd run of one
  // realization (the runs sharing chainKey: every Voronoi k and every sheet.* value of it), run
  // in order of Lloyd iterations on one worker, whose SheetRunner continues the Lloyd run from one
  // Voronoi k to the next and relaxes each seeded surface once for every ratio or thickness: the
  // CLI's reuse, with the same numbers (each equals the grid point computed alone). Rows are
  // written in run order whatever order the workers finish in (runSweep), so runs.csv is the CLI's.
  const done = new Set(resumed.rows.map((row) => row.key));
  const chainOf = seedGroups(plan.pointConfigOf, chainKey);
  const tasks = new Set(runs.filter((run) => !done.has(run.key)).map(chainOf)).size;
  const asked = options.workers ?? defaultPageWorkers();
  if (!Number.isInteger(asked) || asked < 1 || asked > MAX_PAGE_WORKERS)
    throw new RangeError(`sweep workers: ${asked} is not a whole number from 1 to ${MAX_PAGE_WORKERS}`);
  const size = Math.max(1, Math.min(asked, tasks));
  const idle: WorkerSheetRunner[] = Array.from({ length: size }, acquirePipelineRunner);
  const pool = [...idle];
  const iterationsOf = (run: Run) => plan.pointConfigOf(run).lloyd.maxIterations;
  let aborted = false;
  let result: Awaited<ReturnType<typeof runSweep>> | null = null;
  try {
    result = await runSweep<Config & Record<string, unknown>, Record<string, unknown>>({
      runs,
      fields,
      summaryColumns: [...plan.geometry, ...summary],
      existingCsv: csv,
      signal: options.signal,
      concurrency: size,
      // The row carries the run's base geometry beside its summary, as the CLI's does.
      runValues: plan.geometryOf,
      append: (text) => {
        csv += text;
        const records = parseCsv(text).records;
        const record = records[records.length - 1];
        const row: Record<string, string> = {};
        header.forEach((h, k) => (row[h] = record[k]));
        rows.push(row);
        rowByKey.set(row.key, row);
      },
      runner: () => Promise.reject(new Error('page sweep: runs go through tasks')),
      tasks: {
        key: chainOf,
        run: async (task, report) => {
          const runner = idle.pop()!;
          try {
            const order = [...task].sort((a, b) => iterationsOf(a) - iterationsOf(b));
            for (const run of order) {
              const valid = validateConfig(run.config);
              const inputs = await runInputs(valid);
              // Only the summary is kept: no label images cross from the worker.
              const output = await runner.run(valid, { signal: options.signal, views: false, ...inputs });
              report(run, sweepSummary(output.result));
            }
          } finally {
            idle.push(runner);
          }
        },
      },
      onProgress: (p) => {
        if (p.phase === 'start' || (p.phase === 'error' && isAbort(p.error))) return;
        const { key, point, realization, seed } = p.run;
        options.onProgress?.({
          phase: p.phase,
          finished: p.finished,
          total: p.total,
          skipped: p.skipped,
          elapsedMs: performance.now() - started,
          run: { key, point, realization, seed },
          ...(p.phase === 'done' ? { row: rowByKey.get(key) } : { error: p.error instanceof Error ? p.error.message : String(p.error) }),
        });
      },
    });
    aborted = result.aborted;
  } catch (error) {
    // The run in flight was cancelled: the finished ones stay.
    if (!(isAbort(error) && options.signal?.aborted)) throw error;
    aborted = true;
  } finally {
    for (const runner of pool) releasePipelineRunner(runner);
  }
  // The rows runSweep made keep their numbers (typedCells.ts): the same statistics as the text
  // rows parsed here, several times faster (this is the page's main thread).
  const aggregate = aggregateRows(result && result.rows.length === rows.length ? result.rows : rows, fields, aggregateColumns(summary, TEXT_COLUMNS));
  return {
    spec,
    fields,
    header,
    runs: rows,
    aggregate,
    runsCsv: csv === '' ? formatCsvRow(fileHeader(header)) : csv,
    aggregateCsv: aggregateToCsv(aggregate),
    completed: result?.completed ?? rows.length - resumed.rows.length,
    skipped: resumed.rows.length,
    rejected: resumed.rejected,
    aborted,
    workers: size,
  };
}

export interface IntervalPoint {
  mean: number;
  /** 95 % confidence interval of the mean (t distribution), clamped to [lower, upper] bounds. */
  low: number;
  high: number;
  n: number;
}

/** Mean and 95 % confidence interval of `values` (percentages), the interval clamped to [0, 100]. */
export function meanInterval(values: readonly number[]): IntervalPoint {
  const stats: ColumnStats = meanSd(values);
  if (stats.n === 0) return { mean: Number.NaN, low: Number.NaN, high: Number.NaN, n: 0 };
  const half = stats.n >= 2 ? tQuantile975(stats.n - 1) * stats.se : 0;
  const clamp = (x: number) => Math.min(100, Math.max(0, x));
  return { mean: stats.mean, low: clamp(stats.mean - half), high: clamp(stats.mean + half), n: stats.n };
}

/**
 * sweepFlintstones(rows, runs, fields), its fits made one per turn of the event loop: a fit of a
 * published grid's group takes up to about 10 ms, and the ten of them at once were one long
 * task of the page's main thread. The same fits (fitOutcomes.ts: taken for exactly the same
 * points, made by the same code).
 */
export async function flintstonesInTurns<C extends Record<string, unknown>>(
  rows: readonly Record<string, string>[],
  runs: readonly SweepRun<C>[],
  fields: readonly string[],
): Promise<SweepFlintstonesFit[]> {
  const outcomes = new Map<string, FitOutcome>();
  for (const points of flintstonesProblems(rows, runs, fields)) {
    await yieldToEventLoop();
    outcomes.set(pointsKey(points), fitOutcome(points));
  }
  await yieldToEventLoop();
  return sweepFlintstones(rows, runs, fields, cachedFitter(outcomes));
}
