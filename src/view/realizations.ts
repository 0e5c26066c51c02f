/**
 * The headline over realizations in the page, for the app and `<tissue-sheet>` alike: once a
 * result is on screen (realization 1, the configuration's own seed), the other realizations
 * (seeds seed + 1, ...) run in a worker of their own (acquirePipelineRunner: results only, no
 * pictures; the worker keeps each realization's converged seeded surface, so a later ratio or
 * thickness change recomputes only their stacks), and their headlines are combined with the
 * shown one by core/analysis/realizations.ts, as `tissue-sheet run --realizations N` does.
 *
 * `startRealizations` sends the other seeds to their worker before realization 1's result is
 * back (the element does, issue 27: its result event waits for the headline), so both workers
 * compute at once; `realizationsHeadline` starts them once a result is there (the app).
 */
import type { Config } from '../core/config';
import type { Headline } from '../core/analysis/headline';
import { headlineOverRealizations, realizationSeeds } from '../core/analysis/realizations';
import type { SheetOutput, WorkerSheetRunner } from '../run';
import { acquirePipelineRunner, releasePipelineRunner, runInputs, type RunRequest } from './pageRunner';

export interface RealizationsRequest {
  /** The result on screen: realization 1. */
  readonly output: SheetOutput;
  /** Realizations in all (1: none more is run). */
  readonly n: number;
  readonly signal?: AbortSignal;
  /** The run's own inputs (a decoded density image, a mesh file), as given to the first run. */
  readonly inputs?: Pick<RunRequest, 'densityImage' | 'meshFile'>;
  /** After each realization: how many are done, of n. */
  readonly onProgress?: (done: number, n: number) => void;
}

/** Realizations 2..n of a configuration, running; `combine` adds realization 1's result. */
export interface StartedRealizations {
  /**
   * The headline of realization 1's `output` (of the same configuration) over the n
   * realizations (output's own headline when n is 1 or it has none). Rejects with an
   * AbortError when the signal fires.
   */
  combine(output: SheetOutput, onProgress?: (done: number, n: number) => void): Promise<Headline | null>;
}

/** Sends realizations 2..n of `config` to their worker now (nothing when n is 1); `runner`: the caller's own. */
export function startRealizations(
  config: Config,
  n: number,
  options: { signal?: AbortSignal; inputs?: Pick<RunRequest, 'densityImage' | 'meshFile'>; runner?: WorkerSheetRunner } = {},
): StartedRealizations {
  const { signal } = options;
  const seeds = n > 1 ? realizationSeeds(config.seed, n).slice(1) : [];
  const runs = new Map<number, Promise<Headline | null>>();
  if (seeds.length > 0) {
    // A caller's own runner (the element keeps one: a run superseded while its realizations are
    // still being cancelled would otherwise start a worker, and terminate one, per change).
    const runner = options.runner ?? acquirePipelineRunner();
    const inputs = runInputs(config, options.inputs ?? {});
    for (const seed of seeds) {
      const run = inputs.then((given) => {
        if (signal?.aborted) throw new DOMException('The realizations were cancelled', 'AbortError');
        // Only the headline is read: no label images drawn or sent.
        return runner.run({ ...config, seed }, { ...given, signal, views: false }).then((other) => other.result.headline);
      });
      run.catch(() => undefined); // read by combine, or dropped with a failed first run
      runs.set(seed, run);
    }
    if (!options.runner) void Promise.allSettled(runs.values()).then(() => releasePipelineRunner(runner));
  }
  return {
    combine: (output, onProgress) => {
      if (n <= 1 || !output.result.headline) return Promise.resolve(output.result.headline);
      return headlineOverRealizations(config.seed, n, output.result.headline, (seed) => runs.get(seed)!, onProgress);
    },
  };
}

/**
 * The headline of `output`'s configuration over `n` realizations (output's own headline when n
 * is 1). Rejects with an AbortError when the signal fires.
 */
export async function realizationsHeadline(request: RealizationsRequest): Promise<Headline | null> {
  const { output, n, signal } = request;
  if (n <= 1 || !output.result.headline) return output.result.headline;
  const started = startRealizations(output.result.config, n, { ...(signal ? { signal } : {}), ...(request.inputs ? { inputs: request.inputs } : {}) });
  return started.combine(output, request.onProgress);
}
