// `npm run bench`: times the engine in Node (headless-gl) and in headless Chromium, with the
// hand-written WebGL2 floor and exact CPU Lloyd (d3-delaunay) in the same run. Prints a table
// and writes bench/out/bench.json. Options: --sizes 512,1024,2048  --sites 200,10000,100000
// --budget-s 120  --only node|chromium  --centroid-path auto|blend|gather|readback
// --rounds N (floor/cold alternations)  --iterations N (Lloyd iterations per run)
// --no-max-size (time only the sizes given; by default the context's largest size is added)
import { mkdirSync, writeFileSync } from 'node:fs';
import { createHeadlessContext } from '../src/node/headless';
import { version } from '../src/version';
import { benchCases, formatTable, measure, type BenchOptions, type BenchRow } from './measure';

function option(name: string, fallback: string): string {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? process.argv[index + 1] : fallback;
}

const sizes = option('sizes', '512,1024,2048').split(',').map(Number);
const budgetMs = Number(option('budget-s', '120')) * 1000;
const only = option('only', 'all');
const benchOptions: BenchOptions = {
  siteCounts: option('sites', '200,10000,100000').split(',').map(Number),
  centroidPath: option('centroid-path', 'auto') as BenchOptions['centroidPath'],
  rounds: process.argv.includes('--rounds') ? Number(option('rounds', '')) : undefined,
  iterations: process.argv.includes('--iterations') ? Number(option('iterations', '')) : undefined,
};
const rows: BenchRow[] = [];

if (only !== 'chromium') {
  const context = createHeadlessContext();
  const max = context.capabilities.maxTextureSize;
  const nodeSizes = process.argv.includes('--no-max-size') ? sizes.filter((s) => s <= max) : [...sizes.filter((s) => s < max), max];
  const cases = benchCases(nodeSizes, benchOptions.siteCounts);
  rows.push(...(await measure(context, 'node', cases, budgetMs, benchOptions, (line) => console.error(line))));
  context.dispose();
}

if (only !== 'node') {
  // Loaded here, not at the top: a Node-only run (a GPU machine without Chromium) needs neither.
  const { chromium } = await import('@playwright/test');
  const { createServer } = await import('vite');
  const { chromiumArgs } = await import('../playwright.config');
  const server = await createServer({ server: { port: 5175, strictPort: true }, logLevel: 'error' });
  await server.listen();
  const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
  try {
    const page = await browser.newPage();
    page.on('console', (message) => console.error(`chromium: ${message.text()}`));
    await page.goto('http://127.0.0.1:5175/bench/page/index.html');
    await page.waitForFunction(() => document.title === 'ready');
    page.setDefaultTimeout(0);
    const browserRows = await page.evaluate(
      ([s, b, o]) => (window as unknown as { runBenchmark(s: number[], b: number, o: BenchOptions): Promise<BenchRow[]> }).runBenchmark(s, b, o),
      [sizes, budgetMs, benchOptions] as const,
    );
    rows.push(...browserRows);
  } finally {
    await browser.close();
    await server.close();
  }
}

console.log(formatTable(rows));
mkdirSync('bench/out', { recursive: true });
writeFileSync('bench/out/bench.json', JSON.stringify({ version, date: new Date().toISOString(), rows }, null, 2) + '\n');
console.log('\nwrote bench/out/bench.json');
