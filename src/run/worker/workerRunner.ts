import { ConfigError, type Config } from '../../core/config';
import { GpuCapabilityError, type GpuContext } from '../../gpu/context';
import type { RunOptions } from '../family';
import type { SheetOutput } from '../result';
import { SheetRunner } from '../runSheet';
import { WORKER_KEEP_SEEDED } from '../seededCache';
import { withLazyCellRecords } from '../lazyRecords';
import type { FromWorker, SerializedError, ToWorker } from './protocol';

/** Where a WorkerSheetRunner computes. */
export type ComputeSite = { readonly where: 'worker' } | { readonly where: 'page'; readonly reason: string };

/** A run's callbacks, and what to ask of the worker's Presenter (servePipeline.ts). */
export interface WorkerRunOptions extends RunOptions {
  /** Options for the worker's Presenter; absent: nothing is presented. */
  present?: unknown;
  /** Called before the run resolves with what the worker presented (never on the page fallback). */
  onPresented?: (presented: unknown) => void;
}

interface Pending {
  readonly resolve: (output: SheetOutput) => void;
  readonly reject: (error: unknown) => void;
  readonly callbacks: WorkerRunOptions;
  readonly message: Extract<ToWorker, { type: 'run' }>;
}

/**
 * SheetRunner's interface, with the pipeline in a Web Worker (src/run/worker/pipelineWorker.ts)
 * so that the page's main thread only draws. Where the browser cannot give the worker a WebGL2
 * context on an OffscreenCanvas (or cannot start the worker), it falls back to a SheetRunner on
 * the page, once and for good, and says so in `site`.
 */
export class WorkerSheetRunner {
  private worker: Worker | null = null;
  private pageRunner: SheetRunner | null = null;
  private nextId = 1;
  private readonly pending = new Map<number, Pending>();
  site: ComputeSite = { where: 'worker' };

  /**
   * @param pageContext creates the page's own context for the fallback (called at most once).
   * @param createWorker starts the worker; the default is the bundled pipeline worker.
   */
  constructor(
    private readonly pageContext: () => GpuContext,
    createWorker: () => Worker = () => new Worker(new URL('./pipelineWorker.ts', import.meta.url), { type: 'module' }),
  ) {
    try {
      this.worker = createWorker();
      this.worker.onmessage = (event: MessageEvent<FromWorker>) => this.receive(event.data);
      this.worker.onerror = (event) => this.fallBack(`the worker failed to start (${event.message || 'no details'})`);
    } catch (error) {
      this.fallBack(`workers are not available here (${(error as Error).message})`);
    }
  }

  run(config: Config, callbacks: WorkerRunOptions = {}): Promise<SheetOutput> {
    if (!this.worker) return this.onPage().run(config, pageCallbacks(callbacks));
    const { signal } = callbacks;
    if (signal?.aborted) return Promise.reject(abortError());
    const id = this.nextId++;
    const message: Extract<ToWorker, { type: 'run' }> = {
      type: 'run',
      id,
      config,
      ...(callbacks.densityImage ? { densityImage: callbacks.densityImage } : {}),
      ...(callbacks.meshFile ? { meshFile: callbacks.meshFile } : {}),
      ...(callbacks.views === false ? { views: false } : {}),
      ...(callbacks.present !== undefined ? { present: callbacks.present } : {}),
    };
    return new Promise<SheetOutput>((resolve, reject) => {
      this.pending.set(id, { resolve, reject, callbacks, message });
      // Latest wins: a cancelled run is answered at once; the worker stops it at its next yield.
      signal?.addEventListener('abort', () => {
        if (!this.pending.delete(id)) return;
        this.worker?.postMessage({ type: 'cancel', id } satisfies ToWorker);
        reject(abortError());
      });
      this.worker!.postMessage(message);
    });
  }

  dispose(): void {
    this.worker?.terminate();
    this.worker = null;
    for (const { reject } of this.pending.values()) reject(abortError());
    this.pending.clear();
  }

  private receive(message: FromWorker): void {
    const pending = this.pending.get(message.id);
    if (!pending) return; // cancelled on the page already
    switch (message.type) {
      case 'iteration':
        pending.callbacks.onIteration?.(message.record, message.maxIterations);
        return;
      case 'result':
        this.pending.delete(message.id);
        if (message.presented !== undefined) pending.callbacks.onPresented?.(message.presented);
        // A large result came as columns (servePipeline.ts): its records are made when read.
        pending.resolve(
          message.output.tables ? { ...message.output, result: withLazyCellRecords(message.output.result, message.output.tables) } : message.output,
        );
        return;
      case 'error':
        this.pending.delete(message.id);
        pending.reject(rebuildError(message.error));
        return;
      case 'unavailable':
        this.fallBack(`no WebGL2 in a worker here (${message.reason})`);
        return;
    }
  }

  /** Moves every run, waiting or future, to the page. */
  private fallBack(reason: string): void {
    this.site = { where: 'page', reason };
    this.worker?.terminate();
    this.worker = null;
    const waiting = [...this.pending.values()];
    this.pending.clear();
    for (const { resolve, reject, callbacks, message } of waiting) {
      this.onPage().run(message.config, pageCallbacks(callbacks)).then(resolve, reject);
    }
  }

  private onPage(): SheetRunner {
    this.pageRunner ??= new SheetRunner(this.pageContext(), { keepSeeded: WORKER_KEEP_SEEDED });
    return this.pageRunner;
  }
}

/** The callbacks a SheetRunner on the page takes (nothing is presented there). */
function pageCallbacks({ present: _present, onPresented: _onPresented, ...callbacks }: WorkerRunOptions): RunOptions {
  return callbacks;
}

/** What a cancelled run throws, on the page and from the worker alike. */
export function abortError(): DOMException {
  return new DOMException('The run was cancelled', 'AbortError');
}

/** The same error classes as a run on the page throws. */
function rebuildError(error: SerializedError): Error {
  if (error.name === 'AbortError') return abortError();
  if (error.name === 'ConfigError') return new ConfigError(error.field ?? '', error.message);
  if (error.name === 'GpuCapabilityError') return new GpuCapabilityError(error.message);
  const rebuilt = new Error(error.message);
  rebuilt.name = error.name;
  return rebuilt;
}
