/**
 * The extra realizations of `tissue-sheet run` (seeds seed + 1, ..., see core/analysis/
 * realizations.ts) on worker threads, for runs on the exact CPU engine: a 1,000,000-cell run's
 * five realizations took five times one on a single core (issue 27).
 *
 * The threads start with the run, while the main thread computes realization 1 (the one drawn,
 * whose result is written); every thread, and the main thread once realization 1 is done, takes
 * the next realization from a counter shared by all (Atomics: a thread takes its next one without
 * waiting for the main thread's event loop, which a long synchronous step can hold). Each
 * realization gives only its headline (a plain object): no cell records or tables are built for
 * it. The headlines are combined in seed order (combineHeadlines), so RESULT.json is the same
 * whatever the number of threads and whichever finishes first.
 *
 * A realization that fails in a thread fails the run with its error; a thread that exits or
 * crashes hands its realization back (the main thread computes what is missing, the same
 * numbers). Closing terminates the threads wherever they are (Ctrl-C: nothing is written).
 *
 * This module is also the threads' entry (see newThread): the code at the end starts a thread's
 * loop when it finds its workerData.
 */
import { isMainThread, parentPort, type Worker, workerData } from 'node:worker_threads';
import type { Headline } from '../core/analysis/headline';
import { combineHeadlines } from '../core/analysis/realizations';
import type { Config } from '../core/config';
import type { GpuCapabilities } from '../gpu/context';
import { runSheet } from '../run/index';
import { InterruptedError } from './errors';
import type { RunInputs } from './prepare';
import { capabilitiesOnly, deserializeError, newThread, serializeError, tuneJitForThreads, type SerializedError } from './threads';

interface ThreadSetup {
  readonly tissueSheetRealizationThread: true;
  readonly capabilities: GpuCapabilities;
  readonly config: Config;
  readonly inputs: RunInputs;
  /** The seeds of realizations 1..n (index 0, the drawn one, is the main thread's). */
  readonly seeds: number[];
  /** [0]: the index of the next realization to compute, shared by every thread. */
  readonly next: Int32Array;
}

type FromThread = { type: 'done'; index: number; headline: Headline | null } | { type: 'failed'; index: number; error: SerializedError } | { type: 'finished' };

/** Computes realization `index` (its seed `seeds[index]`) and gives its headline. */
export type RunRealization = (seed: number, index: number) => Promise<Headline | null>;

export class RealizationThreads {
  private readonly headlines: (Headline | null | undefined)[];
  private readonly next: Int32Array;
  private readonly threads: Worker[] = [];
  private running: number;
  private failure: Error | null = null;
  private wake: (() => void) | null = null;
  private closed = false;

  /**
   * Starts `count` threads on the realizations 2..n of `config` (seeds `seeds`, index 0 the drawn
   * one); `onDone(index, headline)` is called as each thread's realization arrives.
   */
  constructor(
    count: number,
    config: Config,
    private readonly seeds: readonly number[],
    capabilities: GpuCapabilities,
    inputs: RunInputs,
    private readonly onDone: (index: number, headline: Headline | null) => void,
    /** The threads' module (this one; tests give one that fails or exits on purpose). */
    entry: string = import.meta.url,
  ) {
    this.headlines = new Array<Headline | null | undefined>(seeds.length);
    this.next = new Int32Array(new SharedArrayBuffer(4));
    this.next[0] = 1;
    const setup: ThreadSetup = {
      tissueSheetRealizationThread: true,
      capabilities: { ...capabilities },
      config,
      // Threads run only exact-engine planes and tubes: no mesh crosses.
      inputs: inputs.densityImage ? { densityImage: inputs.densityImage } : {},
      seeds: [...seeds],
      next: this.next,
    };
    this.running = count;
    tuneJitForThreads(count, false);
    for (let k = 0; k < count; k++) {
      const thread = newThread(entry, setup);
      let over = false;
      const end = () => {
        if (over) return;
        over = true;
        this.running--;
        this.wake?.();
      };
      thread.on('message', (message: FromThread) => {
        if (message.type === 'done') {
          this.headlines[message.index] = message.headline;
          this.onDone(message.index, message.headline);
        } else if (message.type === 'failed') {
          this.failure ??= deserializeError(message.error);
          end();
        } else end();
      });
      // A thread lost: its realization (taken, not reported) is computed by the main thread.
      thread.on('error', end);
      thread.on('exit', end);
      this.threads.push(thread);
    }
  }

  /**
   * The headline over the n realizations, `drawn` being realization 1's: the main thread computes
   * realizations with `runHere` while some are left, waits for the threads, computes any a lost
   * thread left, and combines them in seed order. Like headlineOverRealizations: `drawn`
   * unchanged when n is 1 or it is null; a realization without a headline throws.
   */
  async headline(drawn: Headline | null, runHere: RunRealization, signal: AbortSignal): Promise<Headline | null> {
    const n = this.seeds.length;
    if (!drawn || n <= 1) return drawn;
    this.headlines[0] = drawn;
    for (let k = Atomics.add(this.next, 0, 1); k < n && !this.failure; k = Atomics.add(this.next, 0, 1)) {
      this.headlines[k] = await runHere(this.seeds[k], k);
    }
    await this.settled(signal);
    if (this.failure) throw this.failure;
    const headlines: Headline[] = [];
    for (let k = 0; k < n; k++) {
      if (this.headlines[k] === undefined) this.headlines[k] = await runHere(this.seeds[k], k);
      const headline = this.headlines[k];
      if (!headline) throw new Error(`realization ${k + 1} (seed ${this.seeds[k]}) gave no analysis`);
      headlines.push(headline);
    }
    return combineHeadlines(headlines, this.seeds);
  }

  /** Stops the threads wherever they are. */
  async close(): Promise<void> {
    this.closed = true;
    await Promise.all(this.threads.map((thread) => thread.terminate()));
  }

  /** Resolves when every thread finished, failed or exited; rejects when `signal` aborts. */
  private settled(signal: AbortSignal): Promise<void> {
    return new Promise<void>((resolve, reject) => {
      const check = () => {
        if (signal.aborted) reject(new InterruptedError('interrupted; nothing was written'));
        else if (this.running <= 0 || this.failure || this.closed) resolve();
        else return;
        this.wake = null;
        signal.removeEventListener('abort', check);
      };
      this.wake = check;
      signal.addEventListener('abort', check);
      check();
    });
  }
}

/** The thread's loop: the next realization from the shared counter, until none is left. */
async function startThread(setup: ThreadSetup): Promise<void> {
  const port = parentPort!;
  const context = capabilitiesOnly(setup.capabilities);
  for (let index = Atomics.add(setup.next, 0, 1); index < setup.seeds.length; index = Atomics.add(setup.next, 0, 1)) {
    try {
      // Only the headline is read: no cell tables, records left unbuilt (they are made on first read).
      const { result } = await runSheet({ ...setup.config, seed: setup.seeds[index] }, context, { ...setup.inputs, cellTables: false, views: false });
      port.postMessage({ type: 'done', index, headline: result.headline } satisfies FromThread);
    } catch (error) {
      port.postMessage({ type: 'failed', index, error: serializeError(error) } satisfies FromThread);
      return;
    }
  }
  port.postMessage({ type: 'finished' } satisfies FromThread);
}

if (!isMainThread && (workerData as Partial<ThreadSetup> | null)?.tissueSheetRealizationThread === true) void startThread(workerData as ThreadSetup);
