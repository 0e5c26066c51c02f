/**
 * The element's realizations (issue 27): its `realizations` attribute (1 to 100, default 5)
 * says over how many seeds the headline of the result event is; realization 1 is the run on
 * screen, the others start at once in a worker of their own (src/view/realizations.ts), so both
 * compute together. The element keeps that worker while connected (with the seeded surfaces it
 * caches), and a newer run, or disconnecting, stops the realizations of the previous one.
 */
import type { Config } from '../core/config';
import { checkRealizations, DEFAULT_REALIZATIONS, realizationSeed } from '../core/analysis/realizations';
import type { WorkerSheetRunner } from '../run';
import { acquirePipelineRunner, releasePipelineRunner, type RunRequest } from '../view/pageRunner';
import { startRealizations, type StartedRealizations } from '../view/realizations';

/** The `realizations` attribute's value (null: absent), checked; throws a RangeError naming it. */
export function realizationsOf(attribute: string | null): number {
  return attribute === null ? DEFAULT_REALIZATIONS : checkRealizations(attribute, 'realizations');
}

/** The status line while realization `done + 1` of `total` runs (`done` of them finished). */
export function realizationStatus(config: Config, done: number, total: number): string {
  return `Realization ${done + 1} of ${total} (seed ${realizationSeed(config.seed, done + 1)}) for the mean % scutoids…`;
}

/** The realizations of the element's latest run, in the element's own worker. */
export class ElementRealizations {
  private runner: WorkerSheetRunner | null = null;
  private controller: AbortController | null = null;

  /** Starts realizations 2..n of `config` (stopping the previous run's): combine them with realization 1's output. */
  start(config: Config, n: number, inputs: Pick<RunRequest, 'densityImage' | 'meshFile'>): StartedRealizations {
    this.controller?.abort();
    this.controller = new AbortController();
    // One worker kept: a run superseded while its realizations are still being cancelled would
    // otherwise start a worker, and terminate one, per change.
    this.runner ??= acquirePipelineRunner();
    return startRealizations(config, n, { signal: this.controller.signal, runner: this.runner, inputs });
  }

  /** Stops the realizations running and gives their worker back (on disconnect). */
  stop(): void {
    this.controller?.abort();
    this.controller = null;
    if (this.runner) releasePipelineRunner(this.runner);
    this.runner = null;
  }
}
