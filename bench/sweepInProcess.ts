/**
 * The published lab grid through SheetRunner in one thread, in the order a sweep's worker thread
 * takes it (the tasks of one Lloyd run together, fewer iterations first): the per-thread cost of
 * `tissue-sheet sweep` without process start, validation or files.
 *
 *   xvfb-run -a npx tsx bench/sweepInProcess.ts [--realizations 2]
 */
import { readFileSync } from 'node:fs';
import { validateConfig } from '../src/core/config';
import { expandSweep, validateSweepSpec } from '../src/core/sweep';
import { createHeadlessContext } from '../src/node/headless';
import { SheetRunner, sweepSummary } from '../src/run/index';

const args = process.argv.slice(2);
const at = args.indexOf('--realizations');
const realizations = at >= 0 ? Number(args[at + 1]) : 2;
const spec = validateSweepSpec({ ...JSON.parse(readFileSync(new URL('../examples/published-tube-sweep-lab.json', import.meta.url), 'utf8')), realizations });
const runs = expandSweep(spec);
const configs = runs.map((run) => validateConfig(run.config));
const order = runs.map((run, k) => ({ run, k, config: configs[k] }));
order.sort((a, b) => a.run.realization - b.run.realization || a.config.lloyd.maxIterations - b.config.lloyd.maxIterations || a.k - b.k);
const context = createHeadlessContext();
const runner = new SheetRunner(context);
const t = performance.now();
const cpu0 = process.cpuUsage();
let adjacencyMs = 0;
for (const { config } of order) {
  const { result } = await runner.run(config, { views: false });
  sweepSummary(result);
  adjacencyMs += result.timings.adjacencyMs;
}
const ms = performance.now() - t;
const cpu = process.cpuUsage(cpu0);
console.log(
  `SheetRunner, one thread: ${runs.length} runs in ${(ms / 1000).toFixed(2)} s = ${(runs.length / (ms / 1000)).toFixed(0)} runs/s, CPU ${((cpu.user + cpu.system) / 1e6).toFixed(2)} s (stack and analysis ${(adjacencyMs / 1000).toFixed(2)} s)`,
);
context.dispose();
