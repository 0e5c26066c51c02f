/**
 * What the CLI's worker threads share (`sweep --workers`, `run`'s realizations): loading a
 * thread module from the compiled bundle or from the TypeScript sources, errors that cross
 * threads as the classes the CLI maps to exit codes, and a context for the exact engine only.
 *
 * Threads never open a GL context: headless-gl is a native module that loads in one thread of a
 * process only (a second gets "Module did not self-register"), so GPU runs stay on the main
 * thread. A thread gets the main context's capabilities, from which the engine policy picks the
 * same engine as it does there.
 */
import { createRequire } from 'node:module';
import { availableParallelism } from 'node:os';
import { pathToFileURL } from 'node:url';
import { setFlagsFromString } from 'node:v8';
import { Worker } from 'node:worker_threads';
import { ConfigError } from '../core/config';
import type { GpuCapabilities, GpuContext } from '../gpu/context';
import { InputError } from './errors';

/** The default number of threads: the machine's cores. */
export function defaultWorkers(): number {
  return Math.max(1, availableParallelism());
}

/**
 * V8's settings for `threads` compute threads about to start beside this one, where together
 * they fill every core (measured in docs/sweep.md, "Speed", "The JIT on full cores"):
 * - Optimized code is compiled in the thread that runs it, not on V8's background threads: with
 *   every core computing, a background compile waits for a core while the function it would
 *   speed up runs unoptimized. The published grid's sweep on 2 cores spent a third of its CPU
 *   time on those threads.
 * - For many short runs (a sweep), a smaller inlining budget: every thread's isolate compiles
 *   the same few hundred functions for a job of seconds, and V8's default budget made TurboFan
 *   take about 1.1 s of CPU per isolate there. Steady-state speed is the same (bench/
 *   exactSweep.ts and a Lloyd iteration at 100,000 sites within their noise either way).
 * Process-wide (v8.setFlagsFromString): the first applies to isolates started after the call (this
 * thread keeps its background compiler), the second to every compile after it. Results are the
 * same bits: V8's tiers compute the same floating-point operations.
 */
export function tuneJitForThreads(threads: number, manyShortRuns: boolean): void {
  if (threads <= 0 || threads + 1 < availableParallelism()) return;
  setFlagsFromString('--no-concurrent-recompilation');
  if (manyShortRuns) setFlagsFromString('--max-inlined-bytecode-size-cumulative=460 --max-inlined-bytecode-size=230');
}

/**
 * A thread running the module at `entry` (its import.meta.url; the module starts its loop when it
 * finds its workerData). From the TypeScript sources (tests, `npx tsx`) the thread first registers
 * tsx's loader (`--import` in a worker's execArgv does not reach its entry in Node 20).
 */
export function newThread(entry: string, workerData: unknown): Worker {
  if (!entry.endsWith('.ts')) return new Worker(new URL(entry), { workerData });
  const api = pathToFileURL(createRequire(entry).resolve('tsx/esm/api')).href;
  const code = `import(${JSON.stringify(api)}).then((tsx) => { tsx.register(); return import(${JSON.stringify(entry)}); });`;
  return new Worker(code, { eval: true, workerData });
}

export interface SerializedError {
  name: string;
  message: string;
  field?: string;
  stack?: string;
}

export function serializeError(error: unknown): SerializedError {
  if (error instanceof Error) {
    const field = (error as { field?: unknown }).field;
    return { name: error.name, message: error.message, ...(typeof field === 'string' ? { field } : {}), ...(error.stack ? { stack: error.stack } : {}) };
  }
  return { name: 'Error', message: String(error) };
}

/** The error a thread threw, as the class the CLI maps to its exit code where it is one of ours. */
export function deserializeError(e: SerializedError): Error {
  let error: Error;
  if (e.name === 'ConfigError') error = new ConfigError(e.field ?? '', e.message);
  else if (e.name === 'InputError') error = new InputError(e.message);
  else if (e.name === 'AbortError') error = new DOMException(e.message, 'AbortError');
  else {
    error = new Error(e.message);
    error.name = e.name;
  }
  if (e.stack) error.stack = e.stack;
  return error;
}

/** A context for the exact engine only: the capabilities the engine policy reads, no GL. */
export function capabilitiesOnly(capabilities: GpuCapabilities): GpuContext {
  const noGl = (): never => {
    throw new Error('a worker thread has no GL context: GPU runs stay on the main thread');
  };
  return {
    capabilities,
    get renderer() {
      return noGl();
    },
    get gl() {
      return noGl();
    },
    dispose() {},
  };
}
