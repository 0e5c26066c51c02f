/**
 * The headline over realizations in the page, for the app and `<tissue-sheet>` alike: once a
 * result is on screen (realization 1, the configuration's own seed), the other realizations
 * (seeds seed + 1, ...) run in a worker of their own (acquirePipelineRunner: results only, no
 * pictures, the live view's seeded surface is kept), and their headlines are combined with the
 * shown one by core/analysis/realizations.ts, as `tissue-sheet run --realizations N` does.
 */
import type { Headline } from '../core/analysis/headline';
import { headlineOverRealizations } from '../core/analysis/realizations';
import type { SheetOutput } from '../run';
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

/**
 * The headline of `output`'s configuration over `n` realizations (output's own headline when n
 * is 1). Rejects with an AbortError when the signal fires.
 */
export async function realizationsHeadline(request: RealizationsRequest): Promise<Headline | null> {
  const { output, n, signal } = request;
  const { config } = output.result;
  if (n <= 1 || !output.result.headline) return output.result.headline;
  const runner = acquirePipelineRunner();
  try {
    const inputs = await runInputs(config, request.inputs ?? {});
    return await headlineOverRealizations(
      config.seed,
      n,
      output.result.headline,
      async (seed) => {
        if (signal?.aborted) throw new DOMException('The realizations were cancelled', 'AbortError');
        const other = await runner.run({ ...config, seed }, { ...inputs, signal });
        return other.result.headline;
      },
      request.onProgress,
    );
  } finally {
    releasePipelineRunner(runner);
  }
}
