import type { Config } from '../core/config';
import type { GpuContext } from '../gpu/context';
import type { GpuEngine } from '../gpu/engine';
import type { IterationRecord, LloydIterations } from '../core/iterationRecord';
import type { EngineChoice } from './enginePolicy';
import type { Relaxation, RunOptions, StackLayer, SurfaceFamily } from './family';

/** The converged seeded surface: what every other surface of the sheet is projected from. */
export interface SeededSurface<Geometry, Sites> {
  readonly geometry: Geometry;
  /** The final sites, as the family keeps them. */
  readonly sites: Sites;
  /** Label image of the final sites (site id per texel); null where the engine makes none (exact). */
  readonly labels: Int32Array | null;
  readonly engine: EngineChoice;
  readonly iterations: IterationRecord[];
  readonly converged: boolean;
  readonly finalEnergy: number;
  readonly emptyCells: number;
  readonly setupMs: number;
  readonly lloydMs: number;
}

/**
 * Prepares the seeded surface, places the sites and runs Lloyd's method on it, one iteration at
 * a time (a page yields between iterations; a signal cancels). Depends only on the config's
 * fields other than `sheet`, so runs that differ only in the sheet reuse it (SheetRunner).
 */
export async function relaxSeededSurface<C extends Config, G, S, L extends StackLayer, P>(
  family: SurfaceFamily<C, G, S, L, P>,
  config: C,
  context: GpuContext,
  engine: EngineChoice,
  callbacks: RunOptions = {},
): Promise<SeededSurface<G, S>> {
  const start = performance.now();
  const geometry = await family.prepare(config, callbacks);
  family.checkSheet(config, geometry);
  const { sites, relaxation } = family.relax(context, config, geometry, engine);
  try {
    const setupMs = performance.now() - start;
    while (!relaxation.done) {
      throwIfAborted(callbacks.signal);
      const record = relaxation.step();
      callbacks.onIteration?.(record, config.lloyd.maxIterations);
      await yieldToEventLoop();
    }
    const final = relaxation.finish();
    return {
      geometry,
      sites,
      labels: final.labels,
      engine,
      iterations: relaxation.iterations,
      converged: relaxation.converged,
      finalEnergy: final.energy,
      emptyCells: final.emptyCells,
      setupMs,
      lloydMs: performance.now() - start - setupMs,
    };
  } finally {
    relaxation.dispose();
  }
}

/**
 * A Lloyd loop as the pipeline drives it. `labels` gives the final label image after the final
 * sums (null: this engine makes none), `beforeFinish` runs before them (the planar GPU family re-labels the final sites with a
 * cold flood there), `dispose` frees the engine.
 */
export function relaxation(
  run: LloydIterations,
  labels: () => Int32Array | null,
  dispose: () => void = () => {},
  beforeFinish: () => void = () => {},
): Relaxation {
  return {
    get done() {
      return run.done;
    },
    get converged() {
      return run.converged;
    },
    iterations: run.iterations,
    step: () => run.step(),
    finish() {
      beforeFinish();
      const final = run.finish();
      return { ...final, labels: labels() };
    },
    dispose,
  };
}

/**
 * The relaxation of a GPU engine's Lloyd run that `start` sets up: labels read from the engine,
 * which it disposes of (also where `start` throws); `beforeFinish` as for relaxation.
 */
export function engineRelaxation(engine: GpuEngine, start: () => LloydIterations, beforeFinish?: () => void): Relaxation {
  try {
    return relaxation(
      start(),
      () => engine.readLabels(),
      () => engine.dispose(),
      beforeFinish,
    );
  } catch (error) {
    engine.dispose();
    throw error;
  }
}

export function throwIfAborted(signal: AbortSignal | undefined): void {
  if (signal?.aborted) throw new DOMException('The run was cancelled', 'AbortError');
}

/**
 * One turn of the event loop, so that an abort (or a worker message) is seen between Lloyd
 * iterations. Not setTimeout(0): Node waits at least 1 ms for it and browsers 4 ms once nested,
 * which a sweep paid at every iteration (a thread idle 1.5-5 ms per step, ~10 % of the published
 * grid's time). setImmediate in Node and, in a browser worker, a MessageChannel message are
 * macrotasks without that delay; a page's main thread keeps setTimeout, which leaves the browser
 * room to draw.
 */
export function yieldToEventLoop(): Promise<void> {
  if (typeof setImmediate === 'function') return new Promise((resolve) => setImmediate(resolve));
  if (typeof document === 'undefined' && typeof MessageChannel === 'function') return new Promise((resolve) => workerTurn(resolve));
  return new Promise((resolve) => setTimeout(resolve, 0));
}

/** A browser worker's turn: one channel, its messages answered in the order they were sent. */
let turnChannel: MessageChannel | null = null;
const turnsWaiting: (() => void)[] = [];
function workerTurn(resolve: () => void): void {
  if (!turnChannel) {
    turnChannel = new MessageChannel();
    turnChannel.port1.onmessage = () => turnsWaiting.shift()?.();
  }
  turnsWaiting.push(resolve);
  turnChannel.port2.postMessage(null);
}
