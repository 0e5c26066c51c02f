/**
 * The pipeline's side of the worker protocol: a WebGL2 context on an OffscreenCanvas and one
 * SheetRunner (so a ratio or thickness change reuses the converged seeded surface here, as on the
 * page). Runs are taken one at a time in the order they arrive; a cancel aborts its run between
 * Lloyd iterations or stack surfaces.
 *
 * A worker entry may pass a Presenter: work done on each result in the worker before it is sent
 * (the view's worker paints the label images there), so that the page's main thread only uploads
 * what it receives. Its product travels as the result message's `presented`, its buffers
 * transferred, not copied.
 */
import { createCanvasContext, type GpuContext } from '../../gpu/context';
import type { SheetOutput } from '../result';
import { SheetRunner } from '../runSheet';
import { WORKER_KEEP_SEEDED } from '../seededCache';
import type { FromWorker, SerializedError, ToWorker } from './protocol';
import { withLazyCellRecords } from '../lazyRecords';

/** Results of more cells than this are sent as columns (SheetOutput.tables), their lists empty. */
const COLUMNS_ABOVE_CELLS = 20_000;

/** What this module uses of the worker's global scope (the DOM typings describe a window). */
interface WorkerScope {
  postMessage(message: FromWorker, options?: StructuredSerializeOptions): void;
  onmessage: ((event: MessageEvent<ToWorker>) => void) | null;
}

/** Work on a result in the worker, asked for by the run's `present` options. */
export type Presenter = (output: SheetOutput, options: unknown) => { presented: unknown; transfer: Transferable[] };

export function servePipeline(presenter?: Presenter): void {
  const scope = self as WorkerScope;
  let runner: SheetRunner | null = null;
  let unavailable: string | null = null;
  const controllers = new Map<number, AbortController>();
  let queue: Promise<unknown> = Promise.resolve();

  const post = (message: FromWorker, transfer: Transferable[] = []) => scope.postMessage(message, { transfer });

  function sheetRunner(): SheetRunner | null {
    if (runner || unavailable) return runner;
    try {
      if (typeof OffscreenCanvas === 'undefined') throw new Error('OffscreenCanvas is not available in workers here');
      const context: GpuContext = createCanvasContext(new OffscreenCanvas(1, 1));
      runner = new SheetRunner(context, { keepSeeded: WORKER_KEEP_SEEDED });
    } catch (error) {
      unavailable = error instanceof Error ? error.message : String(error);
    }
    return runner;
  }

  async function run(message: Extract<ToWorker, { type: 'run' }>): Promise<void> {
    const controller = controllers.get(message.id);
    if (!controller || controller.signal.aborted) {
      post({ type: 'error', id: message.id, error: { name: 'AbortError', message: 'The run was cancelled' } });
      return;
    }
    const sheets = sheetRunner();
    if (!sheets) {
      post({ type: 'unavailable', id: message.id, reason: unavailable ?? 'no WebGL2 context in the worker' });
      return;
    }
    try {
      // A large result travels as columns (issue 27): its 300,000 records took the page's main
      // thread ~2.7 s to receive at 100,000 cells; the page reads them lazily (lazyRecords.ts).
      const columns = message.config.cells > COLUMNS_ABOVE_CELLS;
      const output = await sheets.run(message.config, {
        signal: controller.signal,
        onIteration: (record, maxIterations) => post({ type: 'iteration', id: message.id, record, maxIterations }),
        ...(message.densityImage ? { densityImage: message.densityImage } : {}),
        ...(message.meshFile ? { meshFile: message.meshFile } : {}),
        ...(columns ? { cellTables: true } : {}),
      });
      if (message.views === false) {
        // Label images are most of the message (and lazily drawn ones would be drawn to send them).
        post({ type: 'result', id: message.id, output: { result: output.result, labelImages: [], ...(output.tables ? { tables: output.tables } : {}) } });
        return;
      }
      const shown = output.tables ? { ...output, result: withLazyCellRecords(output.result, output.tables) } : output;
      const presentation = presenter && message.present !== undefined ? presenter(shown, message.present) : null;
      post({ type: 'result', id: message.id, output, ...(presentation ? { presented: presentation.presented } : {}) }, presentation?.transfer ?? []);
    } catch (error) {
      post({ type: 'error', id: message.id, error: serialize(error) });
    } finally {
      controllers.delete(message.id);
    }
  }

  scope.onmessage = (event: MessageEvent<ToWorker>) => {
    const message = event.data;
    if (message.type === 'cancel') {
      controllers.get(message.id)?.abort();
      return;
    }
    controllers.set(message.id, new AbortController());
    queue = queue.then(() => run(message));
  };
}

function serialize(error: unknown): SerializedError {
  if (error instanceof Error || error instanceof DOMException) {
    const field = (error as { field?: unknown }).field;
    return { name: error.name, message: error.message, ...(typeof field === 'string' ? { field } : {}) };
  }
  return { name: 'Error', message: String(error) };
}
