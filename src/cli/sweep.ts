/**
 * `tissue-sheet sweep SWEEP.json --out DIR`: a grid of configurations x realizations (the spec:
 * src/core/sweep/spec.ts, docs/sweep.md). In order, before any run:
 * 1. the spec is validated (schema, varied paths and values, run cap);
 * 2. every grid point is validated and checked (feasibility, scale guards, budget, then this
 *    GPU's texture limit), and every density image and mesh is loaded and checked once;
 * 3. the output directory is checked and locked, runs.csv's header is fixed from the spec
 *    (the union of every column the grid produces) and an existing runs.csv is validated row by
 *    row (see resume.ts): bad rows are reported by line, kept aside in runs.rejected.csv and
 *    recomputed.
 * Rows are appended as runs finish; aggregate.csv/json and sweep.json are written atomically.
 * Ctrl-C stops after the current run (exit 130); rerunning the same command resumes.
 */
import { appendFileSync, closeSync, mkdirSync, openSync, writeSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { ConfigError, validateConfig, type Config } from '../core/config';
import { estimateRun, threadsWithinBudget, type RunEstimate } from '../core/config/limits';
import { surfaceLayout } from '../core/config/surfaceLayout';
import {
  countRuns,
  flatList,
  flintstonesProblems,
  parseShard,
  planResume,
  ResumeError,
  runSweep,
  shardRuns,
  sortRowsByRuns,
  SweepSpecError,
  validateSweepSpec,
  type FlintstonesFitter,
  type Shard,
} from '../core/sweep';
import { createHeadlessContext } from '../node/headless';
import { chooseEngine } from '../run/enginePolicy';
import { SheetRunner, sweepSummary } from '../run/index';
import { yieldToEventLoop } from '../run/relax';
import { chainKey } from '../run/runSheet';
import { version } from '../version';
import type { CliOptions } from './args';
import { InputError, InterruptedError } from './errors';
import { lockDirectory } from './lock';
import { checkOutDir, writeFileAtomic } from './output';
import { FlatSummaries } from './flatSummaries';
import { checkRunnable, computeBudget, loadInputs, readJsonFile, type RunInputs } from './prepare';
import { Sources } from './sources';
import { cachedFitter, fitOutcomes } from '../core/sweep/fitOutcomes';
import { defaultWorkers, SweepThreadLost, SweepWorkers } from './sweepWorkers';
import { seedGroups, sweepLayout, type Run } from '../run/sweepLayout';
import { gitCommitSoon, readRunsFile, writeAggregates } from './sweepFiles';
import { checkResumable, checkResumedInputs } from './sweepRecord';

export async function sweepCommand(options: CliOptions, signal: AbortSignal, writeLine: (line: string) => void): Promise<void> {
  const lines = batchedLines(writeLine);
  try {
    await sweepLogging(options, signal, lines.log);
  } finally {
    lines.flush();
  }
}

/**
 * Lines written together once per turn of the event loop, in order: a sweep logs a line per run,
 * and most rows (so most lines) come at once after the last run, where thousands of writes to
 * stderr took a tenth of a second. A run's line still follows its row into runs.csv, at the
 * next turn of the event loop.
 */
function batchedLines(writeLine: (line: string) => void): { log: (line: string) => void; flush: () => void } {
  let pending: string[] = [];
  const flush = () => {
    if (pending.length > 0) writeLine(pending.join('\n'));
    pending = [];
  };
  return {
    log(line) {
      if (pending.length === 0) setImmediate(flush);
      pending.push(line);
    },
    flush,
  };
}

async function sweepLogging(options: CliOptions, signal: AbortSignal, log: (line: string) => void): Promise<void> {
  const started = new Date().toISOString();
  const shard: Shard | null = options.shard === undefined ? null : parseShard(options.shard, process.env);
  const spec = validateSweepSpec(readJsonFile(options.input, 'sweep spec'), { maxRuns: options.maxRuns, raiseHint: 'pass --max-runs N to raise the limit' });
  checkOutDir(options.out, [options.input], options.force);
  checkResumable(options.out, spec, shard);
  // The threads start now, before the grid is laid out and checked, the inputs, the GL context
  // and the checks below (about half a second on this thread), and load their modules meanwhile;
  // they get the context's capabilities once it exists (setUp). As many as the runs could use:
  // those the sweep turns out not to need (runs resumed or on the GPU engine, tasks fewer than
  // threads) are ended once that is known. N workers are this thread and N - 1 threads: this
  // thread computes runs too (below), and one thread more than the cores would only contend.
  const workers = options.workers ?? defaultWorkers();
  const commitSoon = gitCommitSoon();
  const earlyThreads = Math.min(workers - 1, countRuns(spec));
  let early: SweepWorkers | null = earlyThreads > 0 ? new SweepWorkers(earlyThreads) : null;
  try {
    await sweepWith(early);
  } finally {
    await early?.close();
  }

  async function sweepWith(prestarted: SweepWorkers | null): Promise<void> {
    // Every grid point is checked, also in a shard: the header is the whole grid's, so shards
    // merge, and a bad point is found by every shard before any run.
    const layout = sweepLayout(spec, (run) => pointConfig(run, (c) => checkRunnable(c, computeBudget(Number.MAX_SAFE_INTEGER, options.allowLarge))));
    const { fields, summary } = layout;
    const runs = shard ? shardRuns(layout.runs, shard, layout.reuseGroup) : layout.ordered;
    // A grid point's config (the same for all its runs but for `seed`: for the engine, chain and
    // iterations; a run itself is computed from its own config).
    const configOf = layout.pointConfigOf;
    const sources = new Sources({ baseDir: dirname(options.input), allowNetwork: options.allowNetwork });
    const inputs = new Map<string, RunInputs>();
    for (const run of layout.runs) {
      if (inputs.has(run.pointKey)) continue;
      inputs.set(run.pointKey, await atPoint(run, () => loadInputs(configOf(run), sources)));
    }
    const inputFiles = sources.files();
    checkResumedInputs(options.out, inputFiles);
    const context = createHeadlessContext();
    let release = () => {};
    try {
      const budget = computeBudget(context.capabilities.maxTextureSize, options.allowLarge);
      // The largest grid point's run (memory): what each thread may hold beside this thread's run.
      let largest: { config: Config; estimate: RunEstimate } | undefined;
      for (const run of layout.runs) {
        if (run.realization !== 0) continue;
        const config = configOf(run);
        atPointSync(run, () => checkRunnable(config, budget));
        const estimate = estimateRun(config);
        if (!largest || estimate.bytes > largest.estimate.bytes) largest = { config, estimate };
      }
      const threadsForLargestPoint = (wanted: number) => (largest ? threadsWithinBudget(largest.config, largest.estimate, budget, wanted) : wanted);

      mkdirSync(options.out, { recursive: true });
      release = lockDirectory(options.out, log);
      // One `git` call for both records, started with the sweep.
      const commit = await commitSoon;
      const record = (extra: Record<string, unknown>) =>
        writeFileAtomic(
          join(options.out, 'sweep.json'),
          JSON.stringify(
            {
              software: { name: 'tissue-sheet', version, commit },
              renderer: context.capabilities.renderer,
              started,
              ...(shard ? { shard: { index: shard.index, count: shard.count, of: layout.runs.length } } : {}),
              ...(inputFiles.length > 0 ? { inputFiles } : {}),
              ...extra,
              spec,
            },
            null,
            2,
          ) + '\n',
        );
      record({ runs: runs.length });

      const csvPath = join(options.out, 'runs.csv');
      const existing = readRunsFile(csvPath) ?? '';
      let plan;
      try {
        plan = planResume(existing, { ...layout.resume, runs }, csvPath);
      } catch (error) {
        if (error instanceof ResumeError) throw new InputError(error.message);
        throw error;
      }
      for (const bad of plan.rejected.slice(0, 20)) {
        log(
          `warning: ${csvPath}:${bad.line}: ${bad.reason}; ${bad.reason.startsWith('duplicate') ? 'dropped (the first row is kept)' : 'dropped, the run is computed again'}`,
        );
      }
      if (plan.rejected.length > 20) log(`warning: ${csvPath}: ${plan.rejected.length - 20} more bad rows dropped`);
      if (plan.rejected.length > 0) {
        appendFileSync(join(options.out, 'runs.rejected.csv'), plan.rejected.map((r) => (r.text.endsWith('\n') ? r.text : `${r.text}\r\n`)).join(''));
        log(`warning: ${plan.rejected.length} rows moved to ${join(options.out, 'runs.rejected.csv')}`);
      }
      if (plan.rewrite) writeFileAtomic(csvPath, plan.cleanText);

      // Tasks: the runs sharing a seeded surface (same config but for `sheet`, same seed), computed
      // by one SheetRunner, which relaxes the surface once for every ratio or thickness and keeps
      // the layers and validity its runs share. Tasks of one Lloyd run (same config but for `sheet`
      // and `lloyd.maxIterations`) start next to each other, fewer iterations first: a thread that
      // still holds that Lloyd run continues it to the next Voronoi k. Exact-engine tasks go to
      // worker threads, and to this thread whenever it is free and every thread is busy; GPU
      // tasks run here on the one GL context. Rows are written in the sweep's order (runSweep),
      // so the files are the same whatever the number of threads and whoever computed a run.
      // The engine is the grid point's (its runs differ in the seed only): chosen once per point.
      const exactPoints = new Map<string, boolean>();
      const onThreads = (run: Run): boolean => {
        let exact = exactPoints.get(run.pointKey);
        if (exact === undefined) {
          const config = configOf(run);
          exactPoints.set(run.pointKey, (exact = chooseEngine(config, surfaceLayout(config).name, context.capabilities).name === 'exact'));
        }
        return exact;
      };
      const chainOf = seedGroups(configOf, chainKey);
      const firstOfChain = new Map<string, number>();
      runs.forEach((run, k) => {
        const chain = chainOf(run);
        if (!firstOfChain.has(chain)) firstOfChain.set(chain, k);
      });
      const iterationsOf = (run: Run) => configOf(run).lloyd.maxIterations;
      const doneKeys = new Set(plan.rows.map((row) => row.key));
      const groups = new Set(runs.filter((run) => !doneKeys.has(run.key) && onThreads(run)).map((run) => layout.reuseGroup(run)));
      // Each thread holds a run at a time beside this thread's: no more than the memory budget
      // holds beside the largest grid point's run.
      const wanted = Math.min(workers - 1, groups.size);
      const threads = wanted > 0 ? threadsForLargestPoint(wanted) : 0;
      if (threads < wanted)
        log(`memory: ${threads} of ${wanted} worker thread${wanted > 1 ? 's' : ''} fit the memory limit beside a run of the largest grid point`);
      // The threads started above, as many as needed (never fewer: `threads` counts a subset of their tasks).
      const pool = threads > 0 ? (prestarted ?? new SweepWorkers(threads)) : null;
      if (prestarted && prestarted !== pool) await prestarted.close();
      else if (prestarted) await prestarted.shrink(threads);
      early = pool;
      pool?.setUp(context.capabilities, inputs);
      const stopThreads = () => pool?.abort();
      signal.addEventListener('abort', stopThreads);
      const runner = new SheetRunner(context);
      let mainThread: Promise<void> = Promise.resolve();
      /** Tasks given to this thread and not finished (GPU tasks, and exact ones while every thread is busy). */
      let mainTasks = 0;
      // This thread's summaries take the threads' flat path (no nested summary flattened per run).
      const summaries = new FlatSummaries();
      const runHere = (task: Run[], done: (run: Run, summary: unknown) => void): Promise<void> => {
        mainTasks++;
        const next = mainThread.then(async () => {
          const order = [...task].sort((a, b) => iterationsOf(a) - iterationsOf(b));
          for (const run of order) {
            const { keys, values } = summaries.of((await runner.run(validateConfig(run.config), { ...inputs.get(run.pointKey), signal, views: false })).result);
            done(run, flatList(keys, values));
            // A turn of the event loop between runs: the threads' messages (their results, and
            // with them their next tasks) would otherwise wait for this whole task.
            await yieldToEventLoop();
          }
        });
        mainThread = next.catch(() => {});
        return next.finally(() => mainTasks--);
      };
      // One descriptor for the rows (appendFileSync opened and closed the file for each of them).
      const rowsFile = appender(csvPath);
      let result;
      let fit: Promise<FlintstonesFitter> | undefined;
      try {
        result = await runSweep<Config & Record<string, unknown>, unknown>({
          runs,
          fields,
          summaryColumns: [...layout.geometry, ...summary],
          existingCsv: plan.cleanText,
          append: (text) => rowsFile.append(text),
          // Each row carries its run's base geometry beside what the run measured.
          runValues: layout.geometryOf,
          runner: async (config, run) => sweepSummary((await runner.run(validateConfig(config), { ...inputs.get(run.pointKey), signal, views: false })).result),
          tasks: {
            key: layout.reuseGroup,
            before: (a, b) => firstOfChain.get(chainOf(a))! - firstOfChain.get(chainOf(b))! || iterationsOf(a) - iterationsOf(b),
            run: async (task, done) => {
              if (!pool?.usable || !onThreads(task[0])) return runHere(task, done);
              // This thread computes too, when it has nothing to do and every thread is busy.
              if (mainTasks === 0 && !pool.hasIdleThread) return runHere(task, done);
              const byKey = new Map(task.map((run) => [run.key, run]));
              const reported = new Set<string>();
              try {
                await pool.run(
                  task.map((run) => ({ key: run.key, pointKey: run.pointKey, config: run.config })),
                  chainOf(task[0]),
                  (key, summary) => {
                    reported.add(key);
                    done(byKey.get(key)!, summary);
                  },
                );
              } catch (error) {
                // A thread that failed or exited (not a run that failed): the main thread computes
                // the task's other runs, the same numbers.
                if (!(error instanceof SweepThreadLost) || signal.aborted) throw error;
                log(`warning: ${error.message}; its runs are computed on the main thread`);
                await runHere(
                  task.filter((run) => !reported.has(run.key)),
                  done,
                );
              }
            },
          },
          // As many tasks as the threads hold (two each: SweepWorkers), and one for this thread.
          concurrency: (pool?.capacity ?? 0) + 1,
          signal,
          onProgress: (p) => {
            if (p.phase === 'start') return;
            const eta = p.finished > 0 ? ((p.elapsedMs / p.finished) * (p.total - p.finished)) / 1000 : 0;
            log(`${p.phase === 'done' ? 'done' : 'FAILED'} ${p.finished}/${p.total} ${p.run.key}  (${p.skipped} resumed, ~${eta.toFixed(0)} s left)`);
          },
        });
        // The Flintstones fits on the threads, idle now (the files are the same: core/sweep/fitOutcomes.ts),
        // while this thread computes the aggregate (writeAggregates awaits them for the fits):
        // on one core fewer than the machine has, so the aggregate keeps one.
        if (pool?.usable && !result.aborted && !signal.aborted) {
          const problems = flintstonesProblems(sortRowsByRuns(result.rows, layout.ordered), layout.runs, layout.fields);
          fit = pool.fitMany(problems, defaultWorkers() - 1).then((outcomes) => cachedFitter(fitOutcomes(problems, outcomes)));
        }
      } catch (error) {
        rowsFile.close();
        await pool?.close();
        if (signal.aborted) throw new InterruptedError(`interrupted; finished runs are in ${csvPath}: rerun the same command to resume`);
        throw error;
      } finally {
        signal.removeEventListener('abort', stopThreads);
      }
      rowsFile.close();
      try {
        await writeAggregates(options.out, result.rows, layout, log, fit);
      } finally {
        await pool?.close();
      }
      record({ runs: runs.length, ended: new Date().toISOString(), computed: result.completed, resumed: result.skipped });
      if (result.aborted) throw new InterruptedError(`interrupted after ${result.completed} runs; rerun the same command to resume`);
      log(
        `sweep: ${result.completed} runs computed, ${result.skipped} resumed${shard ? ` (shard ${shard.index}/${shard.count}: ${runs.length} of ${layout.runs.length} runs)` : ''} -> ${options.out}`,
      );
    } finally {
      release();
      context.dispose();
    }
  }
}

/** The validated config of a run's grid point, checked by `check`; errors name the point. */
function pointConfig(run: Run, check: (config: Config) => void): Config {
  return atPointSync(run, () => {
    const config = validateConfig(run.config);
    check(config);
    return config;
  });
}

/** `check()`, its config errors naming the run's grid point. */
function atPointSync<T>(run: Run, check: () => T): T {
  try {
    return check();
  } catch (error) {
    if (error instanceof ConfigError) throw new SweepSpecError(error.field, `grid point ${run.pointKey || '(base)'}: ${error.message}`);
    throw error;
  }
}

async function atPoint<T>(run: Run, load: () => Promise<T>): Promise<T> {
  try {
    return await load();
  } catch (error) {
    if (error instanceof InputError && run.pointKey) throw new InputError(`grid point ${run.pointKey}: ${error.message}`);
    throw error;
  }
}

/** Appends text to a file through one descriptor, opened on the first append; `close` is idempotent. */
function appender(path: string): { append: (text: string) => void; close: () => void } {
  let fd: number | null = null;
  return {
    append(text) {
      fd ??= openSync(path, 'a');
      const bytes = Buffer.from(text, 'utf8');
      for (let at = 0; at < bytes.length;) at += writeSync(fd, bytes, at, bytes.length - at);
    },
    close() {
      if (fd !== null) closeSync(fd);
      fd = null;
    },
  };
}
