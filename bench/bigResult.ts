// `xvfb-run -a npx tsx bench/bigResult.ts RESULT.json RESULT.cells.bin`: issue 27's "the page shows
// 100,000 cells smoothly" measured in headless Chromium (SwiftShader, the project's flags): the
// app opens a CLI result with its cells side file; time to open (choose -> pictures on screen)
// and the longest main-thread task then; frame times while the 3D view orbits (pointer drags),
// beside the same orbit on the app's own small default result in the same run (the baseline);
// picking latency (a click on the 3D view -> the cell panel names the cell) and the longest
// main-thread task while picking; the cell table's rows in the DOM; the scutoid highlight
// toggled off and on, and each export of the big result (PLY, VTK, SVG, result JSON, project):
// the time from the click to the picture shown / the file downloaded and the main thread's
// longest task meanwhile.
// Options: --port P (default 5187); --save DIR writes the downloaded exports there (to compare
// two trees' files byte for byte).
import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { chromium, type Page } from '@playwright/test';
import { createServer } from 'vite';
import { chromiumArgs } from '../playwright.config';

const [json, side] = process.argv.slice(2).filter((a) => !a.startsWith('--'));
if (!json || !side) throw new Error('usage: bench/bigResult.ts RESULT.json RESULT.cells.bin');
const portIndex = process.argv.indexOf('--port');
const port = portIndex >= 0 ? Number(process.argv[portIndex + 1]) : 5187;
const quantile = (xs: number[], q: number) => [...xs].sort((a, b) => a - b)[Math.min(xs.length - 1, Math.floor(q * xs.length))];
const fmt = (ms: number) => `${ms.toFixed(0)} ms`;
const saveIndex = process.argv.indexOf('--save');
const saveDir = saveIndex >= 0 ? process.argv[saveIndex + 1] : null;
const takeTasks = (page: Page) => page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
const frames = async (page: Page, n: number) => {
  for (let k = 0; k < n; k++) await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(resolve)));
};
const tasksLine = (tasks: number[]) => `longest task ${fmt(Math.max(0, ...tasks))} (${tasks.filter((d) => d > 50).length} over 50 ms)`;

/** The scutoid highlight toggled off then on: ms to the pictures shown (body data-stripes), and the long tasks. */
async function toggles(page: Page): Promise<string[]> {
  const out: string[] = [];
  for (const on of [false, true]) {
    await takeTasks(page);
    console.log(`highlight ${on ? 'on' : 'off'}…`);
    const started = Date.now();
    await page.locator('#highlight').setChecked(on, { force: true, timeout: 10_000 });
    const want = on ? 'on' : 'off';
    await page.evaluate(async (want) => {
      while ((document.body.dataset.stripes ?? want) !== want) await new Promise((resolve) => setTimeout(resolve, 10));
    }, want);
    await frames(page, 3);
    out.push(`highlight ${on ? 'on' : 'off'}: ${fmt(Date.now() - started)}; ${tasksLine(await takeTasks(page))}`);
  }
  return out;
}

/** Each saved file opened again (the project, the result JSON with its cells inline): ms to "Opened", and the long tasks. */
async function reopen(page: Page, paths: string[]): Promise<string[]> {
  const out: string[] = [];
  for (const path of paths) {
    await takeTasks(page);
    console.log(`open ${path}…`);
    await page.evaluate(() => (document.querySelector('#status')!.textContent = ''));
    const started = Date.now();
    await page.locator('#open-file').setInputFiles([path]);
    await page.waitForFunction(() => /^Opened /.test(document.querySelector('#status')?.textContent ?? ''), null, { timeout: 600_000 });
    const ms = Date.now() - started;
    await frames(page, 30);
    out.push(`reopen ${path.split('/').pop()}: ${fmt(ms)}; ${tasksLine(await takeTasks(page))}`);
  }
  return out;
}

/** Each export downloaded: ms from the click to the file, and the long tasks; saved under --save. */
const saved: string[] = [];
async function exportsOf(page: Page): Promise<string[]> {
  const out: string[] = [];
  for (const key of ['ply', 'vtk', 'svg', 'json', 'project']) {
    await takeTasks(page);
    console.log(`export ${key}…`);
    const started = Date.now();
    const [file] = await Promise.all([page.waitForEvent('download', { timeout: 300_000 }), page.locator(`[data-export="${key}"]`).click()]);
    const path = await file.path();
    const ms = Date.now() - started;
    await frames(page, 2);
    if (saveDir) writeFileSync(join(saveDir, file.suggestedFilename()), readFileSync(path));
    out.push(`export ${key}: ${fmt(ms)}; ${tasksLine(await takeTasks(page))}`);
    if (saveDir && (key === 'json' || key === 'project')) saved.push(join(saveDir, file.suggestedFilename()));
  }
  return out;
}

const server = await createServer({ server: { port, strictPort: true }, logLevel: 'error' });
await server.listen();
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });

/** Frame intervals (ms) while the 3D view is dragged in a circle for `frames` pointer moves. */
async function orbit(page: Page, frames = 12): Promise<number[]> {
  const box = (await page.locator('#view3d').boundingBox())!;
  const cx = box.x + box.width / 2;
  const cy = box.y + box.height / 2;
  await page.evaluate('window.startFrames()');
  await page.mouse.move(cx, cy);
  await page.mouse.down();
  for (let k = 0; k < frames; k++) await page.mouse.move(cx + 80 * Math.cos(k / 5), cy + 40 * Math.sin(k / 5));
  await page.mouse.up();
  return page.evaluate('window.stopFrames()') as Promise<number[]>;
}

/** ms from a click on the 3D view to the cell panel naming a cell (several points). */
async function picks(page: Page): Promise<number[]> {
  await page.locator('#reset-camera').click();
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(resolve)));
  const box = (await page.locator('#view3d').boundingBox())!;
  const out: number[] = [];
  for (const [fx, fy] of [
    [0.5, 0.5],
    [0.4, 0.45],
    [0.6, 0.55],
    [0.45, 0.6],
    [0.55, 0.4],
  ]) {
    await page.evaluate(() => document.querySelector('#cell-info')!.removeAttribute('data-cell'));
    const started = Date.now();
    await page.mouse.click(box.x + fx * box.width, box.y + fy * box.height);
    await page
      .waitForFunction(() => document.querySelector('#cell-info')!.hasAttribute('data-cell'), null, { timeout: 60_000 })
      .catch(() => console.log(`no cell picked at ${fx}, ${fy}`));
    out.push(Date.now() - started);
  }
  return out;
}

try {
  const page = await browser.newPage({ viewport: { width: 1280, height: 800 } });
  // As a string: tsx would wrap named functions of an evaluated closure in a helper the page lacks.
  await page.addInitScript(`
    let frameTimes = [];
    let frameLoop = false;
    window.startFrames = () => {
      frameTimes = [];
      frameLoop = true;
      let last = performance.now();
      const tick = (now) => { frameTimes.push(now - last); last = now; if (frameLoop) requestAnimationFrame(tick); };
      requestAnimationFrame(tick);
    };
    window.stopFrames = () => { frameLoop = false; return frameTimes.slice(1); };
  `);
  await page.addInitScript(() => {
    const w = window as unknown as { longTasks: number[] };
    w.longTasks = [];
    new PerformanceObserver((list) => list.getEntries().forEach((entry) => w.longTasks.push(entry.duration))).observe({ type: 'longtask' });
  });
  await page.goto(`http://127.0.0.1:${port}/`);
  await page.waitForFunction(() => document.body.dataset.state === 'done', null, { timeout: 180_000 });
  console.log('app ready');
  const small = await orbit(page);
  const smallPicks = await picks(page);
  await page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
  const started = Date.now();
  await page.locator('#open-file').setInputFiles([json, side]);
  await page
    .waitForFunction(() => /^Opened /.test(document.querySelector('#status')?.textContent ?? '') || document.querySelector('.error-main'), null, {
      timeout: 600_000,
    })
    .catch((error: Error) => console.log(`not opened: ${error.message}`));
  const refused = await page.evaluate(() => document.querySelector('.error-main')?.textContent ?? null);
  if (refused) throw new Error(`not opened: ${refused}`);
  await page.evaluate(() => new Promise((resolve) => requestAnimationFrame(() => requestAnimationFrame(resolve))));
  const openMs = Date.now() - started;
  const openTasks = await page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
  const cells = await page.evaluate(() => document.querySelector('#status')?.textContent ?? '');
  console.log(`opened in ${openMs} ms`);
  const big = await orbit(page);
  const orbitTasks = await page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
  const bigPicks = await picks(page);
  const pickTasks = await page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
  const rows = await page.evaluate(() => document.querySelectorAll('#cell-table tbody tr').length);
  const toggled = await toggles(page);
  const exported = await exportsOf(page);
  const reopened = await reopen(page, saved.reverse());
  console.log(`\nissue 27: a big result in the page (headless Chromium, SwiftShader); ${cells.slice(0, 120)}`);
  console.log(
    `open (choose both files -> pictures on screen): ${fmt(openMs)}; longest main-thread task ${fmt(Math.max(0, ...openTasks))} (${openTasks.length} over 50 ms)`,
  );
  console.log(
    `orbit frame interval: big median ${fmt(quantile(big, 0.5))}, p95 ${fmt(quantile(big, 0.95))} | small default (baseline) median ${fmt(quantile(small, 0.5))}, p95 ${fmt(quantile(small, 0.95))}; longest task while orbiting the big one ${fmt(Math.max(0, ...orbitTasks))}`,
  );
  console.log(
    `pick (click -> cell panel): big median ${fmt(quantile(bigPicks, 0.5))}; longest main-thread task while picking ${fmt(Math.max(0, ...pickTasks))} (${pickTasks.length} over 50 ms) | small (baseline) median ${fmt(quantile(smallPicks, 0.5))}`,
  );
  console.log(`cell table rows in the DOM: ${rows}`);
  for (const line of [...toggled, ...exported, ...reopened]) console.log(line);
} finally {
  await browser.close();
  await server.close();
}
