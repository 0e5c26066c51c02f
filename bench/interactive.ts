// `xvfb-run -a npx tsx bench/interactive.ts`: issue 15's figures in headless Chromium
// (SwiftShader), each beside a baseline measured in the same run:
// - the app: cold first result (page load to first picture), input -> picture latency of surface
//   ratio changes (median, 95th percentile), longest main-thread task while they run;
// - compute only: ratio changes on the page's main thread (the old path, the baseline) against
//   the pipeline worker, with the longest main-thread task of each;
// - sweep runs/s: <tissue-sheet>.sweep() against `tissue-sheet sweep` (the CLI, headless-gl) on
//   the same spec.
// Options: --changes N (ratio changes, default 12), --realizations N (sweep, default 2).
import { execFileSync } from 'node:child_process';
import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { chromium, type Page } from '@playwright/test';
import { createServer } from 'vite';
import { chromiumArgs } from '../playwright.config';
import { APP_START } from '../src/core/config/presets';

/** The benchmark's sheet: the app's example, small enough for a software GPU (resolution 256, Voronoi 6). */
const BENCH_SHEET = { ...APP_START, resolution: 256, lloyd: { maxIterations: 5 } };

function option(name: string, fallback: number): number {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? Number(process.argv[index + 1]) : fallback;
}
const changes = option('changes', 12);
const realizations = option('realizations', 2);
const ratios = Array.from({ length: changes }, (_, k) => Number((1.25 + (k % 6) * 0.5).toFixed(2)));
const quantile = (xs: number[], q: number) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];
const fmt = (ms: number) => `${ms.toFixed(0)} ms`;

const port = 5176;
const server = await createServer({ server: { port, strictPort: true }, logLevel: 'error' });
await server.listen();
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
const lines: string[] = [];
const say = (line: string) => {
  lines.push(line);
  console.log(line);
};

try {
  // 1. The app at its default configuration.
  const app = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  await app.addInitScript(() => {
    const w = window as unknown as { longTasks: number[] };
    w.longTasks = [];
    new PerformanceObserver((list) => list.getEntries().forEach((entry) => w.longTasks.push(entry.duration))).observe({ type: 'longtask' });
  });
  const loadStart = Date.now();
  await app.goto(`http://127.0.0.1:${port}/`);
  await app.waitForFunction(() => document.body.dataset.state === 'done', null, { timeout: 180_000 });
  const cold = Date.now() - loadStart;
  const site = await app.evaluate(() => document.body.dataset.computeSite);
  await app.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
  const latencies: number[] = [];
  for (const ratio of ratios) latencies.push(await ratioToPicture(app, ratio));
  const appLongest = Math.max(0, ...(await app.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks)));
  // One slider step (input then change at once, as a key press or a click on the track): the
  // draft picture, then the full one after the app's settle delay.
  await app.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
  const steps: number[] = [];
  for (const ratio of ratios.slice(0, 6)) steps.push(await stepToFullPicture(app, ratio + 0.1));
  const stepLongest = Math.max(0, ...(await app.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks)));
  await app.close();

  // 2. Compute only: main thread (baseline) against the worker.
  const bench = await browser.newPage();
  await bench.goto(`http://127.0.0.1:${port}/bench/page/interactive.html`);
  await bench.waitForFunction(() => document.title === 'ready');
  type Changes = { ms: number[]; median: number; longestTask: number };
  const call = <T>(name: string, input: unknown) =>
    bench.evaluate(
      ([name, input]) => (window as unknown as { benchInteractive: Record<string, (i: unknown) => Promise<unknown>> }).benchInteractive[name as string](input),
      [name, input] as const,
    ) as Promise<T>;
  const onPage = await call<Changes>('ratioChanges', { config: BENCH_SHEET, ratios, where: 'page' });
  const inWorker = await call<Changes>('ratioChanges', { config: BENCH_SHEET, ratios, where: 'worker' });

  // 3. Sweep runs/s: the element against the CLI, same spec.
  const spec = { base: BENCH_SHEET, vary: { 'sheet.surfaceRatio': [1.5, 2.5, 3.5] }, realizations, seedMode: 'per-realization' };
  const page = await call<{ runs: number; seconds: number; longestTask: number }>('elementSweep', spec);
  const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-bench-'));
  writeFileSync(join(dir, 'spec.json'), JSON.stringify(spec));
  const cliStart = Date.now();
  execFileSync(process.execPath, ['tests/cli/fromSource.mjs', 'sweep', join(dir, 'spec.json'), '--out', join(dir, 'out')], { stdio: 'pipe', timeout: 300_000 });
  const cliSeconds = (Date.now() - cliStart) / 1000;
  const runs = spec.vary['sheet.surfaceRatio'].length * realizations;

  say(
    `\nissue 15 interactive benchmark (headless Chromium, SwiftShader; default config: ${BENCH_SHEET.cells} cells, resolution ${BENCH_SHEET.resolution}); pipeline site: ${site}`,
  );
  say(`app cold first result (load -> first picture): ${fmt(cold)}`);
  const p50 = quantile(latencies, 0.5);
  const p95 = quantile(latencies, 0.95);
  say(`app ratio change, input -> picture, ${latencies.length} changes: median ${fmt(p50)}, p95 ${fmt(p95)}; longest main-thread task ${fmt(appLongest)}`);
  say(
    `app slider step (input + change), input -> full picture (draft first, full after the 400 ms settle): median ${fmt(quantile(steps, 0.5))} of ${steps.length}; longest main-thread task ${fmt(stepLongest)}`,
  );
  say(
    `compute only, ratio change: main thread (baseline) median ${fmt(onPage.median)}, longest task ${fmt(onPage.longestTask)} | worker median ${fmt(inWorker.median)} (x${(inWorker.median / onPage.median).toFixed(2)} of baseline), longest task ${fmt(inWorker.longestTask)}`,
  );
  say(`app latency / worker compute median: x${(p50 / inWorker.median).toFixed(2)} (the rest is transfer and drawing)`);
  say(
    `sweep of ${runs} runs: page ${(page.runs / page.seconds).toFixed(2)} runs/s (longest task ${fmt(page.longestTask)}) | CLI ${(runs / cliSeconds).toFixed(2)} runs/s incl. start-up (baseline); page/CLI x${(page.runs / page.seconds / (runs / cliSeconds)).toFixed(2)}`,
  );
} finally {
  await browser.close();
  await server.close();
}

/** Sets the app's surface-ratio slider and waits for the picture of that ratio (one frame after the result). */
async function ratioToPicture(page: Page, ratio: number): Promise<number> {
  return page.evaluate(async (ratio) => {
    const slider = document.querySelector<HTMLInputElement>('input[name="sheet.surfaceRatio"]')!;
    const before = Number(document.body.dataset.runs);
    const started = performance.now();
    slider.value = String(ratio);
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    // (no named functions in here: tsx would wrap them in a helper the page lacks)
    while (!(Number(document.body.dataset.runs) > before && document.body.dataset.state === 'done')) await new Promise((resolve) => setTimeout(resolve, 2));
    await new Promise((resolve) => requestAnimationFrame(resolve));
    const elapsed = performance.now() - started;
    slider.dispatchEvent(new Event('change', { bubbles: true }));
    return elapsed;
  }, ratio);
}

/** A slider step (input and change together): time until the full pictures are on screen. */
async function stepToFullPicture(page: Page, ratio: number): Promise<number> {
  return page.evaluate(async (ratio) => {
    const slider = document.querySelector<HTMLInputElement>('input[name="sheet.surfaceRatio"]')!;
    const before = Number(document.body.dataset.runs);
    const started = performance.now();
    slider.value = String(ratio);
    slider.dispatchEvent(new Event('input', { bubbles: true }));
    slider.dispatchEvent(new Event('change', { bubbles: true }));
    while (!(Number(document.body.dataset.runs) > before && document.body.dataset.state === 'done' && document.body.dataset.pictures === 'full'))
      await new Promise((resolve) => setTimeout(resolve, 5));
    await new Promise((resolve) => requestAnimationFrame(resolve));
    return performance.now() - started;
  }, ratio);
}
