// Test page for e2e/element-change.spec.ts (issue 27): a converged <tissue-sheet>'s `sheet.*`
// attribute change, the page's long tasks around it, and fresh runs of the same configuration
// on a runner of their own (nothing cached) to compare it with.
import '../../src/element/index';
import type { Config } from '../../src/core/config';
import type { TissueSheetElement } from '../../src/element/TissueSheetElement';
import { createCanvasContext, WorkerSheetRunner, type SheetResult } from '../../src/run';
import { observeLongTasks } from './longTasks';

const element = document.querySelector('tissue-sheet') as TissueSheetElement;
const longTasks = observeLongTasks();

/** What a result's numbers are, without its timings (`timings`, every `...Ms`: they differ from run to run). */
function numbers(result: SheetResult) {
  const { headline, ...rest } = JSON.parse(JSON.stringify(result), (key, value) =>
    key === 'timings' || key.endsWith('Ms') ? undefined : value,
  ) as SheetResult;
  return { ...rest, headline: headline?.realizationValues[0] ?? null };
}

/**
 * Runs the element with `attributes`, then sets `attribute` to `value` (the element not manual):
 * the result event's numbers, the long tasks from the change until `settleMs` after its result
 * event (the full pictures drawn after live changes included) and the ms to the event.
 */
async function change(input: { attributes: Record<string, string>; attribute: string; value: string; settleMs: number }) {
  element.setAttribute('manual', '');
  for (const [name, value] of Object.entries(input.attributes)) element.setAttribute(name, value);
  await element.run();
  element.removeAttribute('manual');
  await new Promise((resolve) => setTimeout(resolve, 500));
  longTasks.length = 0;
  const started = performance.now();
  const fired = new Promise<SheetResult>((resolve) => element.addEventListener('result', (e) => resolve(e.detail.result), { once: true }));
  element.setAttribute(input.attribute, input.value);
  const result = await fired;
  const ms = performance.now() - started;
  await new Promise((resolve) => setTimeout(resolve, input.settleMs));
  element.setAttribute('manual', '');
  return { ms, longTasks: [...longTasks], config: result.config, numbers: numbers(result), headline: result.headline };
}

/** Fresh runs of `config` for `seeds` on a runner of its own (nothing cached): their numbers and headlines. */
async function fresh(input: { config: Config; seeds: number[] }) {
  const runner = new WorkerSheetRunner(() => createCanvasContext(document.createElement('canvas')));
  try {
    const runs = [];
    for (const seed of input.seeds) {
      const output = await runner.run({ ...input.config, seed });
      runs.push({ numbers: numbers(output.result), percent: output.result.headline?.percentScutoids ?? null });
    }
    return runs;
  } finally {
    runner.dispose();
  }
}

Object.assign(window, { elementChange: { change, fresh } });
document.title = 'ready';
