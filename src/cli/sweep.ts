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
import { execFileSync } from 'node:child_process';
import { appendFileSync, existsSync, mkdirSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { ConfigError, validateAnyConfig, type AnyConfig } from '../core/config';
import {
  aggregateRows,
  aggregateToCsv,
  aggregateToJson,
  baseColumns,
  expandSweep,
  planResume,
  ResumeError,
  runSweep,
  summaryColumns,
  sweepColumns,
  SweepSpecError,
  TEXT_COLUMNS,
  validateSweepSpec,
  variedFields,
  type SweepRun,
} from '../core/sweep';
import { createHeadlessContext } from '../node/headless';
import { SheetRunner, seededKey, sweepSummary } from '../run/index';
import { version } from '../version';
import type { CliOptions } from './args';
import { InputError, InterruptedError } from './errors';
import { lockDirectory } from './lock';
import { checkOutDir, writeFileAtomic } from './output';
import { checkRunnable, computeBudget, loadInputs, readJsonFile, type RunInputs } from './prepare';
import { Sources } from './sources';

type Run = SweepRun<AnyConfig & Record<string, unknown>>;

export async function sweepCommand(options: CliOptions, signal: AbortSignal, log: (line: string) => void): Promise<void> {
  const started = new Date().toISOString();
  const spec = validateSweepSpec(readJsonFile(options.input, 'sweep spec'), { maxRuns: options.maxRuns, raiseHint: 'pass --max-runs N to raise the limit' });
  checkOutDir(options.out, [options.input], options.force);
  const fields = variedFields(spec);
  const runs = expandSweep(spec);

  // One check per grid point (realizations differ only in their seed).
  const pointConfigs = new Map<string, AnyConfig>();
  const sources = new Sources({ baseDir: dirname(options.input), allowNetwork: options.allowNetwork });
  const inputs = new Map<string, RunInputs>();
  for (const run of runs) {
    if (pointConfigs.has(run.pointKey)) continue;
    const config = pointConfig(run, (c) => checkRunnable(c, computeBudget(Number.MAX_SAFE_INTEGER, options.allowLarge)));
    pointConfigs.set(run.pointKey, config);
    inputs.set(run.pointKey, await atPoint(run, () => loadInputs(config, sources)));
  }
  const context = createHeadlessContext();
  let release = () => {};
  try {
    // Every column a point may fill (the engine, and so the methods, can depend on the renderer).
    const summary = sweepColumns(pointConfigs.values());
    const header = [...baseColumns(fields), ...summary];
    const filled = new Map([...pointConfigs].map(([key, config]) => [key, new Set(summaryColumns(config))]));
    const budget = computeBudget(context.capabilities.maxTextureSize, options.allowLarge);
    for (const run of runs) if (run.realization === 0) pointConfig(run, (c) => checkRunnable(c, budget));

    mkdirSync(options.out, { recursive: true });
    release = lockDirectory(options.out, log);
    const record = (extra: Record<string, unknown>) =>
      writeFileAtomic(
        join(options.out, 'sweep.json'),
        JSON.stringify({ software: { name: 'tissue-sheet', version, commit: gitCommit() }, renderer: context.capabilities.renderer, started, ...extra, spec }, null, 2) + '\n',
      );
    record({ runs: runs.length });

    const csvPath = join(options.out, 'runs.csv');
    const existing = existsSync(csvPath) ? readFileSync(csvPath, 'utf8') : '';
    let plan;
    try {
      plan = planResume(existing, { header, fields, runs, filledColumns: (run) => filled.get(run.pointKey)!, textColumns: TEXT_COLUMNS }, csvPath);
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

    // Runs sharing a seeded surface (same config but for `sheet`) run consecutively: the runner
    // relaxes it once and reuses it for every ratio or thickness.
    const keyed = runs.map((run) => ({ run, key: seededKey(validateAnyConfig(run.config)) }));
    const firstIndex = new Map<string, number>();
    keyed.forEach(({ key }, index) => firstIndex.has(key) || firstIndex.set(key, index));
    const ordered = keyed.sort((a, b) => firstIndex.get(a.key)! - firstIndex.get(b.key)! || a.run.index - b.run.index).map(({ run }) => run);

    const runner = new SheetRunner(context);
    let result;
    try {
      result = await runSweep({
        runs: ordered,
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
    const numeric = summary.filter((c) => !TEXT_COLUMNS.has(c));
    const aggregate = aggregateRows(result.rows, fields, numeric);
    for (const point of aggregate.points) {
      const partial = Object.entries(point.stats).filter(([, s]) => s.n > 0 && s.missing > 0);
      for (const [column, s] of partial.slice(0, 3)) {
        log(`warning: ${Object.entries(point.point).map(([f, v]) => `${f}=${v}`).join(' ') || 'all runs'}: ${column} has ${s.missing} of ${point.runs} values that are not finite numbers (not counted: n = ${s.n})`);
      }
    }
    writeFileAtomic(join(options.out, 'aggregate.csv'), aggregateToCsv(aggregate));
    writeFileAtomic(join(options.out, 'aggregate.json'), JSON.stringify(aggregateToJson(aggregate), null, 2) + '\n');
    record({ runs: runs.length, ended: new Date().toISOString(), computed: result.completed, resumed: result.skipped });
    if (result.aborted) throw new InterruptedError(`interrupted after ${result.completed} runs; rerun the same command to resume`);
    log(`sweep: ${result.completed} runs computed, ${result.skipped} resumed -> ${options.out}`);
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

/** The git commit of the checkout the CLI runs from, when it is one. */
function gitCommit(): string | null {
  try {
    return execFileSync('git', ['rev-parse', 'HEAD'], { cwd: dirname(fileURLToPath(import.meta.url)), encoding: 'utf8', timeout: 2000, stdio: ['ignore', 'pipe', 'ignore'] }).trim() || null;
  } catch {
    return null;
  }
}
