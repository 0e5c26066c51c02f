// Benchmark page for bench/elementRatio.ts (issue 27): a converged <tissue-sheet>'s
// `surface-ratio` / `thickness` attribute change -> its `result` event, beside the app's slider
// path (LatestRunner.live on the page's shared runner, as src/app/main.ts runs a drag), with the
// longest main-thread task of each.
import '../../src/element/index';
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { LatestRunner } from '../../src/view/pageRunner';
import type { TissueSheetElement } from '../../src/element/TissueSheetElement';

const element = document.querySelector('tissue-sheet') as TissueSheetElement;
const longTasks: number[] = [];
new PerformanceObserver((list) => list.getEntries().forEach((entry) => longTasks.push(entry.duration))).observe({ type: 'longtask' });

const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor(xs.length / 2)];

interface Changes {
  ms: number[];
  median: number;
  longestTask: number;
}

/** Sets `attributes` on the element (manual: it runs now) and waits for its result event. */
async function elementChanges(input: { attributes: Record<string, string>; attribute: string; values: number[] }): Promise<Changes> {
  element.setAttribute('manual', '');
  for (const [name, value] of Object.entries(input.attributes)) element.setAttribute(name, value);
  await element.run();
  element.removeAttribute('manual');
  await new Promise((resolve) => setTimeout(resolve, 100));
  longTasks.length = 0;
  const ms: number[] = [];
  for (const value of input.values) {
    const started = performance.now();
    const fired = new Promise((resolve) => element.addEventListener('result', resolve, { once: true }));
    element.setAttribute(input.attribute, String(value));
    await fired;
    ms.push(performance.now() - started);
  }
  await new Promise((resolve) => setTimeout(resolve, 100));
  element.setAttribute('manual', '');
  return { ms, median: median(ms), longestTask: Math.max(0, ...longTasks) };
}

/** The app's slider path: LatestRunner.live on the shared runner, each value after the last. */
async function appChanges(input: { config: ConfigInput; field: 'surfaceRatio' | 'thickness'; values: number[] }): Promise<Changes> {
  const runner = new LatestRunner();
  const base = validateConfig(input.config);
  await runner.start({ config: base });
  await new Promise((resolve) => setTimeout(resolve, 100));
  longTasks.length = 0;
  const ms: number[] = [];
  for (const value of input.values) {
    const started = performance.now();
    await runner.live({ config: { ...base, sheet: { ...base.sheet, [input.field]: value } } });
    ms.push(performance.now() - started);
  }
  await new Promise((resolve) => setTimeout(resolve, 100));
  return { ms, median: median(ms), longestTask: Math.max(0, ...longTasks) };
}

Object.assign(window, { benchElement: { elementChanges, appChanges, config: () => element.config } });
document.title = 'ready';
