// `npx tsx bench/elementRatio.ts`: issue 27's element figure in headless Chromium (SwiftShader,
// the project's flags): a converged 100-cell <tissue-sheet> tube gets `surface-ratio` (then
// `thickness`) attribute changes; time from the change to its `result` event (median) and the
// longest main-thread task, beside the app's slider path (LatestRunner.live on the same page's
// shared runner) on the same configuration in the same run.
// Options: --changes N (default 9), --port P (default 5186).
import { chromium } from '@playwright/test';
import { createServer } from 'vite';
import { chromiumArgs } from '../playwright.config';

function option(name: string, fallback: number): number {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? Number(process.argv[index + 1]) : fallback;
}
const changes = option('changes', 9);
const port = option('port', 5186);
/** A converged 100-cell tube (the element's attributes and the same config for the app path). */
const ATTRIBUTES = { surface: 'tube', cells: '100', seed: '1', iterations: '10', 'surface-ratio': '1.5' };
const ratios = Array.from({ length: changes }, (_, k) => Number((1.75 + (k % 6) * 0.5).toFixed(2)));
const thicknesses = Array.from({ length: changes }, (_, k) => 5 + (k % 6) * 4);
const fmt = (ms: number) => `${ms.toFixed(0)} ms`;

const server = await createServer({ server: { port, strictPort: true }, logLevel: 'error' });
await server.listen();
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
try {
  const page = await browser.newPage();
  page.on('pageerror', (error) => console.error('page error:', error.message));
  page.on('console', (message) => (message.type() === 'error' || message.text().startsWith('TIMING')) && console.error('page console:', message.text()));
  await page.goto(`http://127.0.0.1:${port}/bench/page/elementRatio.html`);
  await page.waitForFunction(() => document.title === 'ready', null, { timeout: 120_000 });
  type Changes = { ms: number[]; median: number; longestTask: number };
  const call = <T>(name: string, input: unknown) =>
    page.evaluate(
      ([name, input]) => (window as unknown as { benchElement: Record<string, (i: unknown) => Promise<unknown>> }).benchElement[name as string](input),
      [name, input] as const,
    ) as Promise<T>;
  const element = await call<Changes>('elementChanges', { attributes: ATTRIBUTES, attribute: 'surface-ratio', values: ratios });
  const config = await call<Record<string, unknown>>('config', null);
  const app = await call<Changes>('appChanges', { config, field: 'surfaceRatio', values: ratios });
  const thicknessAttributes = { ...ATTRIBUTES, 'surface-ratio': '', thickness: '3' };
  const elementT = await call<Changes>('elementChanges', { attributes: thicknessAttributes, attribute: 'thickness', values: thicknesses });
  const configT = await call<Record<string, unknown>>('config', null);
  const appT = await call<Changes>('appChanges', { config: configT, field: 'thickness', values: thicknesses });
  console.log(`\nissue 27: <tissue-sheet> attribute change -> result event (headless Chromium, SwiftShader; 100-cell tube, Voronoi 11)`);
  for (const [what, e, a] of [
    ['surface-ratio', element, app],
    ['thickness', elementT, appT],
  ] as const) {
    console.log(
      `${what}: element median ${fmt(e.median)} (longest task ${fmt(e.longestTask)}) | app slider path median ${fmt(a.median)} (longest task ${fmt(a.longestTask)}); element/app x${(e.median / a.median).toFixed(2)}  [element ${e.ms.map((m) => m.toFixed(0)).join(' ')}]`,
    );
  }
} finally {
  await browser.close();
  await server.close();
}
