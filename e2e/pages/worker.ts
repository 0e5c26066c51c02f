// Test page: the pipeline in its Web Worker against the same pipeline on the page, and the
// page's longest task while the worker computes.
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { createCanvasContext, SheetRunner } from '../../src/run';
import { WorkerSheetRunner } from '../../src/run/worker/workerRunner';
import { observeLongTasks } from './longTasks';

const pageContext = () => createCanvasContext(document.createElement('canvas'));

const longTasks = observeLongTasks();

/** Long tasks (> 50 ms) the page saw while `work` ran, in ms. */
async function longTasksDuring<T>(work: () => Promise<T>): Promise<{ value: T; longTasks: number[] }> {
  longTasks.length = 0;
  const value = await work();
  await new Promise((resolve) => setTimeout(resolve, 50)); // the observer reports a task after it ends
  return { value, longTasks: [...longTasks] };
}

/** The result without timings (which differ run to run). */
function comparable(result: unknown): string {
  return JSON.stringify(result, (key, value) => (/Ms$/.test(key) || key === 'timings' ? undefined : value));
}

async function compareWorkerAndPage(input: ConfigInput) {
  const config = validateConfig(input);
  const worker = new WorkerSheetRunner(pageContext);
  const iterations: number[] = [];
  const inWorker = await longTasksDuring(() => worker.run(config, { onIteration: (record) => iterations.push(record.iteration) }));
  const site = worker.site;
  worker.dispose();
  const onPage = await new SheetRunner(pageContext()).run(config);
  return {
    site,
    iterations,
    longTasks: inWorker.longTasks,
    same: comparable(inWorker.value.result) === comparable(onPage.result),
    labelsSame: inWorker.value.labelImages.every((image, k) => image.labels.join() === onPage.labelImages[k].labels.join()),
  };
}

/** A worker that cannot start: the runner must fall back to the page and say why. */
async function fallBack(input: ConfigInput) {
  const runner = new WorkerSheetRunner(pageContext, () => {
    throw new Error('no workers in this test');
  });
  const output = await runner.run(validateConfig(input));
  return { site: runner.site, cells: output.result.cells.length };
}

/** Cancelling answers at once with an AbortError, and the worker keeps serving later runs. */
async function cancelThenRun(input: ConfigInput) {
  const runner = new WorkerSheetRunner(pageContext);
  const controller = new AbortController();
  const first = runner.run(validateConfig({ ...input, lloyd: { maxIterations: 200, tolerance: 0 } }), { signal: controller.signal });
  setTimeout(() => controller.abort(), 20);
  const firstError = await first.then(
    () => 'finished',
    (error: Error) => error.name,
  );
  const second = await runner.run(validateConfig(input));
  runner.dispose();
  return { firstError, cells: second.result.cells.length };
}

/** A result-only run (a sweep's): the same result, no label images sent back. */
async function resultOnly(input: ConfigInput) {
  const runner = new WorkerSheetRunner(pageContext);
  const config = validateConfig(input);
  const full = await runner.run(config);
  const bare = await runner.run(config, { views: false });
  runner.dispose();
  return { same: comparable(full.result) === comparable(bare.result), images: bare.labelImages.length, fullImages: full.labelImages.length };
}

(window as unknown as Record<string, unknown>).tissueSheetWorkerTest = { compareWorkerAndPage, fallBack, cancelThenRun, resultOnly };
document.title = 'ready';
