/**
 * `tissue-sheet run CONFIG.json --out RESULT.json`: one sheet. Everything that can be refused is
 * refused before the GPU computes anything: the schema, feasibility, scale guards and budget
 * (with this GPU's texture limit), the density image or mesh; then --out is checked (never the
 * input, never through a link, never over someone else's file without --force) and the result
 * written atomically.
 */
import { dirname } from 'node:path';
import { describeHeadline } from '../core/analysis/headline';
import type { Headline } from '../core/analysis/headline';
import { DEFAULT_REALIZATIONS, headlineOverRealizations, realizationSeeds } from '../core/analysis/realizations';
import { ConfigError, validateConfig } from '../core/config';
import { threadsWithinBudget } from '../core/config/limits';
import { surfaceLayout } from '../core/config/surfaceLayout';
import { createHeadlessContext } from '../node/headless';
import { chooseEngine } from '../run/enginePolicy';
import { describeEngine, runSheet } from '../run/index';
import { findForbiddenKey } from '../core/sweep';
import { InputError, InterruptedError } from './errors';
import type { CliOptions } from './args';
import { cellsFilePath, checkOutFile, isOurCellsFile, MAX_CELL_RECORDS_IN_JSON, writeResult } from './output';
import { checkRunnable, computeBudget, loadInputs, readJsonFile } from './prepare';
import { RealizationThreads } from './realizationThreads';
import { Sources } from './sources';
import { defaultWorkers } from './threads';

export async function runCommand(options: CliOptions, signal: AbortSignal, log: (line: string) => void): Promise<void> {
  const json = readJsonFile(options.input, 'config');
  // JSON.parse keeps "__proto__" as an own key; refuse it before any code copies the object.
  const forbidden = findForbiddenKey(json, []);
  if (forbidden) throw new InputError(`${options.input}: ${forbidden}: not allowed as a key (it would reach an object prototype); remove it`);
  const config = validateConfig(json);
  checkOutFile(options.out, [options.input], options.force);
  // Schema-level scale checks first (no GPU needed), then the texture limit once a context exists.
  const estimate = checkRunnable(config, computeBudget(Number.MAX_SAFE_INTEGER, options.allowLarge));
  // Large results keep their cells as columns and write them to a side file (README, "Result JSON").
  const cellTables = options.cellsFile || config.cells * estimate.surfaces > MAX_CELL_RECORDS_IN_JSON;
  if (cellTables) checkOutFile(cellsFilePath(options.out), [options.input], options.force, isOurCellsFile);
  const sources = new Sources({ baseDir: dirname(options.input), allowNetwork: options.allowNetwork });
  const inputs = await loadInputs(config, sources);
  const context = createHeadlessContext();
  let threads: RealizationThreads | null = null;
  try {
    const budget = computeBudget(context.capabilities.maxTextureSize, options.allowLarge);
    checkRunnable(config, budget);
    // The headline is the mean over realizations (seeds seed, seed + 1, ...): the file is
    // realization 1's, the one drawn; the others only give their headline. On the exact engine
    // they run on threads from the start, beside realization 1 (realizationThreads.ts).
    const n = options.realizations ?? DEFAULT_REALIZATIONS;
    const seeds = realizationSeeds(config.seed, n);
    let r = 1;
    const reported = (seed: number, headline: Headline | null, where = '') => {
      const value = headline?.percentScutoids;
      log(`realization ${++r} of ${n} (seed ${seed}${where}): ${typeof value === 'number' ? `${value.toFixed(1)} % scutoids` : 'no % scutoids'}`);
    };
    const exact = chooseEngine(config, surfaceLayout(config).name, context.capabilities).name === 'exact';
    // At most one thread a core beyond this one (at least one where asked): each holds a whole
    // run, so threads past the cores add memory, not speed.
    const cores = Math.max(2, defaultWorkers());
    const wanted = exact ? Math.min((options.workers ?? cores) - 1, n - 1, cores - 1) : 0;
    // Each thread holds a whole run: no more than the memory budget holds beside this one.
    const threadCount = threadsWithinBudget(config, estimate, budget, wanted);
    if (threadCount < wanted) {
      log(
        `memory: ${threadCount} of ${wanted} realization thread${wanted > 1 ? 's' : ''} fit the memory limit beside this run; the rest of the realizations run here`,
      );
    }
    if (threadCount > 0) {
      threads = new RealizationThreads(threadCount, config, seeds, context.capabilities, inputs, (index, headline) =>
        reported(seeds[index], headline, ', on a thread'),
      );
      log(`realizations 2–${n} on ${threadCount} worker thread${threadCount > 1 ? 's' : ''}, and on this one after realization 1`);
    }
    const { result: drawn, tables } = await runSheet(config, context, {
      ...inputs,
      signal,
      cellTables,
      onIteration(record, total) {
        log(`iteration ${record.iteration}/${total}  energy ${record.energy.toPrecision(8)}  max displacement ${record.maxDisplacement.toPrecision(4)} µm`);
      },
    });
    if (signal.aborted) throw new InterruptedError('interrupted; nothing was written');
    checkFinite(drawn.lloyd.finalEnergy);
    // Another realization gives only its headline: no cell tables, no records built.
    const runOne = async (seed: number) => {
      if (signal.aborted) throw new InterruptedError('interrupted; nothing was written');
      const { result: other } = await runSheet({ ...config, seed }, context, { ...inputs, signal, views: false });
      if (signal.aborted) throw new InterruptedError('interrupted; nothing was written');
      reported(seed, other.headline);
      return other.headline;
    };
    const headline = threads ? await threads.headline(drawn.headline, runOne, signal) : await headlineOverRealizations(config.seed, n, drawn.headline, runOne);
    const files = sources.files();
    const result = { ...drawn, headline, ...(files.length > 0 ? { inputFiles: files } : {}) };
    const side = writeResult(options.out, result, tables, [options.input], options.force);
    log(
      `done: ${tables?.cells.count ?? result.cells.length} cells, ${result.lloyd.iterations.length} iterations, ` +
        `${describeEngine(result.engine)}, ${result.timings.totalMs.toFixed(0)} ms -> ${options.out}${side ? ` (cells in ${side})` : ''}`,
    );
    // Last, the number a biologist reads: result.headline, with its method and Voronoi k.
    log(`headline: ${describeHeadline(result.headline)}`);
  } finally {
    await threads?.close();
    context.dispose();
  }
}

/** A last guard: a run whose energy overflowed is not reported as a result. */
function checkFinite(energy: number): void {
  if (!Number.isFinite(energy)) {
    throw new ConfigError('surface', `surface: the Lloyd energy is ${String(energy)} (out of single-precision range); rescale the surface`);
  }
}
