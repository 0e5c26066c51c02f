// Test page: <tissue-sheet>.sweep() with its sweep-progress events and cancellation, and the
// page's long tasks while it runs.
import '../../src/element/index';
import type { TissueSheetSweepProgressDetail } from '../../src/element/events';

const element = document.querySelector('tissue-sheet')!;
const longTasks: number[] = [];
new PerformanceObserver((list) => list.getEntries().forEach((entry) => longTasks.push(entry.duration))).observe({ type: 'longtask' });

/** Runs `spec`; with `abortAfter`, aborts once that many runs have finished. */
async function sweep(input: { spec: unknown; abortAfter?: number; resume?: string }) {
  const controller = new AbortController();
  const progress: TissueSheetSweepProgressDetail[] = [];
  const listener = (event: Event) => {
    const detail = (event as CustomEvent<TissueSheetSweepProgressDetail>).detail;
    progress.push(detail);
    if (input.abortAfter !== undefined && progress.length >= input.abortAfter) controller.abort();
  };
  element.addEventListener('sweep-progress', listener);
  longTasks.length = 0;
  const started = performance.now();
  try {
    const result = await element.sweep(input.spec, { signal: controller.signal, ...(input.resume ? { resume: input.resume } : {}) });
    return {
      ...result,
      ms: performance.now() - started,
      longTasks: [...longTasks],
      progress: progress.map((p) => ({ finished: p.finished, total: p.total, key: p.run.key, hasRow: p.row !== undefined })),
      site: element.computeSite,
    };
  } finally {
    element.removeEventListener('sweep-progress', listener);
  }
}

/** A bad spec: the error's name and message. */
async function badSweep(spec: unknown) {
  try {
    await element.sweep(spec);
    return { name: 'none', message: '' };
  } catch (error) {
    return { name: (error as Error).name, message: (error as Error).message };
  }
}

(window as unknown as Record<string, unknown>).tissueSheetInteractive = { sweep, badSweep };
document.title = 'ready';
