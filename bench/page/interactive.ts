// Benchmark page for bench/interactive.ts: ratio changes computed on the page's main thread
// (the baseline: a SheetRunner on a page WebGL2 context, as before issue 15) and in the worker
// (WorkerSheetRunner), with the longest main-thread task of each; and <tissue-sheet>.sweep().
import '../../src/element/index';
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { createCanvasContext, SheetRunner, WorkerSheetRunner } from '../../src/run';

const longTasks: number[] = [];
new PerformanceObserver((list) => list.getEntries().forEach((entry) => longTasks.push(entry.duration))).observe({ type: 'longtask' });

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

/** Ratio changes after one warm-up run: compute time per change and the longest page task. */
async function ratioChanges(input: { config: ConfigInput; ratios: number[]; where: 'page' | 'worker' }) {
  const runner =
    input.where === 'page'
      ? new SheetRunner(createCanvasContext(document.createElement('canvas')))
      : new WorkerSheetRunner(() => createCanvasContext(document.createElement('canvas')));
  const base = validateConfig(input.config);
  await runner.run(base);
  longTasks.length = 0;
  const ms: number[] = [];
  for (const ratio of input.ratios) {
    const started = performance.now();
    await runner.run({ ...base, sheet: { ...base.sheet, surfaceRatio: ratio } });
    ms.push(performance.now() - started);
  }
  await new Promise((resolve) => setTimeout(resolve, 60));
  if (runner instanceof WorkerSheetRunner) runner.dispose();
  return { ms, median: median(ms), longestTask: Math.max(0, ...longTasks) };
}

async function elementSweep(spec: unknown) {
  longTasks.length = 0;
  const started = performance.now();
  const result = await document.querySelector('tissue-sheet')!.sweep(spec);
  const seconds = (performance.now() - started) / 1000;
  return { runs: result.runs.length, seconds, longestTask: Math.max(0, ...longTasks) };
}

Object.assign(window, { benchInteractive: { ratioChanges, elementSweep } });
document.title = 'ready';
