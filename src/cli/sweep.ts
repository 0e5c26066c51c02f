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
import { appendFileSync, existsSync, mkdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { ConfigError, validateAnyConfig, type AnyConfig } from '../core/config';
import { parseShard, planResume, ResumeError, runSweep, shardRuns, SweepSpecError, validateSweepSpec, type Shard } from '../core/sweep';
import { createHeadlessContext } from '../node/headless';
import { SheetRunner, sweepSummary } from '../run/index';
import { version } from '../version';
import type { CliOptions } from './args';
import { InputError, InterruptedError } from './errors';
import { lockDirectory } from './lock';
import { checkOutDir, writeFileAtomic } from './output';
import { checkRunnable, computeBudget, loadInputs, readJsonFile, type RunInputs } from './prepare';
import { Sources } from './sources';
import { gitCommit, sweepLayout, writeAggregates, type Run } from './sweepFiles';

export async function sweepCommand(options: CliOptions, signal: AbortSignal, log: (line: string) => void): Promise<void> {
  const started = new Date().toISOString();
  const shard: Shard | null = options.shard === undefined ? null : parseShard(options.shard, process.env);
  const spec = validateSweepSpec(readJsonFile(options.input, 'sweep spec'), { maxRuns: options.maxRuns, raiseHint: 'pass --max-runs N to raise the limit' });
  checkOutDir(options.out, [options.input], options.force);

  // Every grid point is checked, also in a shard: the header is the whole grid's, so shards
  // merge, and a bad point is found by every shard before any run.
  const layout = sweepLayout(spec, (run) => pointConfig(run, (c) => checkRunnable(c, computeBudget(Number.MAX_SAFE_INTEGER, options.allowLarge))));
  const { fields, summary } = layout;
  const runs = shard ? shardRuns(layout.runs, shard, layout.reuseGroup) : layout.ordered;
  const sources = new Sources({ baseDir: dirname(options.input), allowNetwork: options.allowNetwork });
  const inputs = new Map<string, RunInputs>();
  for (const run of layout.runs) {
    if (inputs.has(run.pointKey)) continue;
    inputs.set(run.pointKey, await atPoint(run, () => loadInputs(validateAnyConfig(run.config), sources)));
  }
  const context = createHeadlessContext();
  let release = () => {};
  try {
    const budget = computeBudget(context.capabilities.maxTextureSize, options.allowLarge);
    for (const run of layout.runs) if (run.realization === 0) pointConfig(run, (c) => checkRunnable(c, budget));

    mkdirSync(options.out, { recursive: true });
    release = lockDirectory(options.out, log);
    const record = (extra: Record<string, unknown>) =>
      writeFileAtomic(
        join(options.out, 'sweep.json'),
        JSON.stringify(
          {
            software: { name: 'tissue-sheet', version, commit: gitCommit() },
            renderer: context.capabilities.renderer,
            started,
            ...(shard ? { shard: { index: shard.index, count: shard.count, of: layout.runs.length } } : {}),
            ...extra,
            spec,
          },
          null,
          2,
        ) + '\n',
      );
    record({ runs: runs.length });

    const csvPath = join(options.out, 'runs.csv');
    const existing = existsSync(csvPath) ? readFileSync(csvPath, 'utf8') : '';
    let plan;
    try {
      plan = planResume(existing, { ...layout.resume, runs }, csvPath);
    } catch (error) {
      if (error instanceof ResumeError) throw new InputError(error.message);
      throw error;
    }
    for (const bad of plan.rejected.slice(0, 20)) {
      log(`warning: ${csvPath}:${bad.line}: ${bad.reason}; ${bad.reason.startsWith('duplicate') ? 'dropped (the first row is kept)' : 'dropped, the run is computed again'}`);
    }
    if (plan.rejected.length > 20) log(`warning: ${csvPath}: ${plan.rejected.length - 20} more bad rows dropped`);
    if (plan.rejected.length > 0) {
      appendFileSync(join(options.out, 'runs.rejected.csv'), plan.rejected.map((r) => (r.text.endsWith('\n') ? r.text : `${r.text}\r\n`)).join(''));
      log(`warning: ${plan.rejected.length} rows moved to ${join(options.out, 'runs.rejected.csv')}`);
    }
    if (plan.rewrite) writeFileAtomic(csvPath, plan.cleanText);

    // Runs sharing a seeded surface (same config but for `sheet`) run consecutively (layout.ordered,
    // and shards keep those groups whole): the runner relaxes it once for every ratio or thickness.
    const runner = new SheetRunner(context);
    let result;
    try {
      result = await runSweep({
        runs,
        fields,
        summaryColumns: summary,
        existingCsv: plan.cleanText,
        append: (text) => appendFileSync(csvPath, text),
        runner: async (config, run) => sweepSummary((await runner.run(validateAnyConfig(config), { ...inputs.get(run.pointKey), signal })).result),
        signal,
        onProgress: (p) => {
          if (p.phase === 'start') return;
          const eta = p.finished > 0 ? ((p.elapsedMs / p.finished) * (p.total - p.finished)) / 1000 : 0;
          log(`${p.phase === 'done' ? 'done' : 'FAILED'} ${p.finished}/${p.total} ${p.run.key}  (${p.skipped} resumed, ~${eta.toFixed(0)} s left)`);
        },
      });
    } catch (error) {
      if (signal.aborted) throw new InterruptedError(`interrupted; finished runs are in ${csvPath}: rerun the same command to resume`);
      throw error;
    }
    writeAggregates(options.out, result.rows, layout, log);
    record({ runs: runs.length, ended: new Date().toISOString(), computed: result.completed, resumed: result.skipped });
    if (result.aborted) throw new InterruptedError(`interrupted after ${result.completed} runs; rerun the same command to resume`);
    log(`sweep: ${result.completed} runs computed, ${result.skipped} resumed${shard ? ` (shard ${shard.index}/${shard.count}: ${runs.length} of ${layout.runs.length} runs)` : ''} -> ${options.out}`);
  } finally {
    release();
    context.dispose();
  }
}

/** The validated config of a run's grid point, checked by `check`; errors name the point. */
function pointConfig(run: Run, check: (config: AnyConfig) => void): AnyConfig {
  try {
    const config = validateAnyConfig(run.config);
    check(config);
    return config;
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
