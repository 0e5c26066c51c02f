/**
 * The published tube sweep with the lab protocol (examples/published-tube-sweep-lab.json:
 * Voronoi 1–10 × 12 ratios × R realizations), three ways in one run, so the figures compare:
 *
 *   1. baseline: bench/exactSweep.ts in process (one Lloyd run per realization, every Voronoi k
 *      analysed at all ratios in one pass over the 37 layers: the cost of the computation);
 *   2. pipeline: SheetRunner over the sweep's runs in the CLI's order, summaries only, no files
 *      (what each run costs in src/run: per-run stack, protocol and result);
 *   3. CLI: `tissue-sheet sweep` in a child process (startup, validation, CSV, aggregates,
 *      Flintstones fits), then with --shard 1/S..S/S run side by side, and `merge`.
 *
 *   xvfb-run -a npx tsx bench/sweepCli.ts [--realizations 1] [--shards 2] [--cli "node bin/tissue-sheet.mjs"]
 *
 * Peak memory of the children from /usr/bin/time when present. Keep R small on shared machines:
 * R = 1 is 120 runs.
 */
import { spawn, spawnSync } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { validateAnyConfig } from '../src/core/config';
import { expandSweep, orderForReuse, validateSweepSpec } from '../src/core/sweep';
import { createHeadlessContext } from '../src/node/headless';
import { seededKey, SheetRunner, sweepSummary } from '../src/run/index';

const args = process.argv.slice(2);
const option = (name: string, fallback: string) => {
  const at = args.indexOf(`--${name}`);
  return at >= 0 ? args[at + 1] : fallback;
};
const realizations = Number(option('realizations', '1'));
const shards = Number(option('shards', '2'));
const cliCommand = option('cli', `${process.execPath} tests/cli/fromSource.mjs`).split(' ');
const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const work = mkdtempSync(join(tmpdir(), 'tissue-sheet-bench-sweep-'));

const published = JSON.parse(readFileSync(join(root, 'examples/published-tube-sweep-lab.json'), 'utf8'));
const specPath = join(work, 'spec.json');
writeFileSync(specPath, JSON.stringify({ ...published, realizations }));
const spec = validateSweepSpec(JSON.parse(readFileSync(specPath, 'utf8')));
const runs = expandSweep(spec);
const rate = (n: number, ms: number) => `${n} runs in ${(ms / 1000).toFixed(2)} s = ${(n / (ms / 1000)).toFixed(1)} runs/s`;
const hasTime = existsSync('/usr/bin/time');

/** Runs a command; wall time and (with /usr/bin/time) peak RSS in MiB. */
function timed(command: string[]): Promise<{ ms: number; peakMiB: number | null; stderr: string; status: number | null }> {
  const full = hasTime ? ['/usr/bin/time', '-f', 'PEAK_KB %M', ...command] : command;
  const t = performance.now();
  return new Promise((done) => {
    const child = spawn(full[0], full.slice(1), { cwd: root, stdio: ['ignore', 'ignore', 'pipe'] });
    let stderr = '';
    child.stderr.on('data', (d) => (stderr += d));
    child.on('close', (status) => {
      const peak = /PEAK_KB (\d+)/.exec(stderr);
      done({ ms: performance.now() - t, peakMiB: peak ? Number(peak[1]) / 1024 : null, stderr, status });
    });
  });
}
const mib = (x: number | null) => (x === null ? '' : `, peak RSS ${x.toFixed(0)} MiB`);

async function main() {
  console.log(`published tube sweep, lab protocol, engine auto: ${runs.length} runs (Voronoi 1-10 x 12 ratios x ${realizations} realizations)`);

  // 1. Baseline: the in-process exact sweep of the same grid.
  const base = spawnSync(process.execPath, ['--import', 'tsx', 'bench/exactSweep.ts', '--realizations', String(realizations)], { cwd: root, encoding: 'utf8' });
  const baseLine = base.stdout.split('\n').find((l) => l.startsWith('exact engine'));
  console.log(`1. baseline (bench/exactSweep.ts): ${baseLine?.replace(/^exact engine, lab protocol: /, '') ?? `failed: ${base.stderr.slice(-300)}`}`);

  // 2. The pipeline, in the CLI's order (runs sharing a seeded surface together), no files.
  const context = createHeadlessContext();
  const runner = new SheetRunner(context);
  const ordered = orderForReuse(runs, (run) => seededKey(validateAnyConfig(run.config)));
  const engines = new Set<string>();
  let adjacencyMs = 0;
  // A seeded surface is relaxed when the key changes from one run to the next (SheetRunner keeps one).
  let relaxed = 0;
  let previous = '';
  let t = performance.now();
  for (const run of ordered) {
    const config = validateAnyConfig(run.config);
    const key = seededKey(config);
    if (key !== previous) relaxed++;
    previous = key;
    const { result } = await runner.run(config);
    sweepSummary(result);
    engines.add(result.engine.name);
    adjacencyMs += result.timings.adjacencyMs;
  }
  const pipelineMs = performance.now() - t;
  context.dispose();
  console.log(`2. pipeline (SheetRunner, summaries only): ${rate(runs.length, pipelineMs)}; engine ${[...engines].join(', ')}`);
  console.log(
    `   per run: ${(pipelineMs / runs.length).toFixed(1)} ms, of which stack, exact adjacency and lab validity ${(adjacencyMs / runs.length).toFixed(1)} ms; seeded surfaces relaxed ${relaxed} times for ${runs.length} runs (one per Voronoi k and realization)`,
  );

  // 3. The CLI: one process, then S shards side by side and a merge.
  const whole = join(work, 'whole');
  const one = await timed([...cliCommand, 'sweep', specPath, '--out', whole]);
  if (one.status !== 0) throw new Error(`CLI sweep failed: ${one.stderr.slice(-500)}`);
  console.log(`3. CLI sweep, 1 process: ${rate(runs.length, one.ms)}${mib(one.peakMiB)}`);
  t = performance.now();
  const parts = await Promise.all(Array.from({ length: shards }, (_, i) => timed([...cliCommand, 'sweep', specPath, '--out', join(work, `shard${i + 1}`), '--shard', `${i + 1}/${shards}`])));
  const shardMs = performance.now() - t;
  if (parts.some((p) => p.status !== 0)) throw new Error(`CLI shard failed: ${parts.find((p) => p.status !== 0)!.stderr.slice(-500)}`);
  console.log(`   ${shards} shards side by side: ${rate(runs.length, shardMs)}${mib(Math.max(...parts.map((p) => p.peakMiB ?? 0)) || null)} (per shard)`);
  const merged = join(work, 'merged');
  const merge = await timed([...cliCommand, 'merge', ...parts.map((_, i) => join(work, `shard${i + 1}`)), '--out', merged]);
  const same = ['runs.csv', 'aggregate.csv', 'aggregate.json'].every((f) => readFileSync(join(whole, f), 'utf8') === readFileSync(join(merged, f), 'utf8'));
  console.log(`   merge: ${(merge.ms / 1000).toFixed(2)} s (process included); merged files ${same ? 'identical to' : 'DIFFER from'} the 1-process sweep's`);
  console.log(`CLI overhead over the pipeline: ${((one.ms - pipelineMs) / runs.length).toFixed(1)} ms per run (startup, validation, CSV, aggregates amortized)`);
  const flintstones = readFileSync(join(whole, 'flintstones.csv'), 'utf8').trim().split(/\r?\n/);
  console.log(`flintstones.csv (${flintstones.length - 1} fits):`);
  for (const line of flintstones.slice(0, 4)) console.log(`   ${line.split(',').slice(0, 12).join(',')}`);
  rmSync(work, { recursive: true, force: true });
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
