// Benchmark page: driven by bench/run.ts through Playwright.
import { createCanvasContext } from '../../src/gpu/context';
import { benchCases, measure, type BenchOptions } from '../measure';

const log = document.getElementById('log')!;

async function run(sizes: number[], budgetMs: number, options: BenchOptions) {
  const context = createCanvasContext(document.createElement('canvas'));
  const max = context.capabilities.maxTextureSize;
  const allSizes = [...sizes.filter((s) => s < max), max];
  return measure(context, 'chromium', benchCases(allSizes, options.siteCounts), budgetMs, options, (line) => (log.textContent += line + '\n'));
}

Object.assign(window, { runBenchmark: run });
document.title = 'ready';
