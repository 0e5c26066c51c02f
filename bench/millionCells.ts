// `npx tsx bench/millionCells.ts [--cells 1000000] [--iterations 10] [--workers N] [--dir /tmp/tissue-sheet-million]`:
// issue 27's million cells. Runs `tissue-sheet run` (from the sources, a fresh process under
// /usr/bin/time -v, xvfb-run when there is no display) on a periodic plane of N cells (exact
// engine, 10 Lloyd iterations, a thickness, exact analysis on both surfaces; the headline over
// the default 5 realizations, on `--workers N` threads, default the cores), and prints its wall
// time, CPU time and peak RSS against the targets (60 s, 4 GB), the sizes written, the time to
// read the side file back, and, as the baseline timed in the same run, d3-delaunay's Delaunay +
// Voronoi of as many random points (median of 5: 3 before the run, 2 after). Asserts nothing.
import { spawnSync } from 'node:child_process';
import { mkdirSync, statSync, writeFileSync } from 'node:fs';
import { loadavg } from 'node:os';
import { join } from 'node:path';
import { Delaunay } from 'd3-delaunay';
import { readResultFile } from '../src/node/resultFile';
import { Random } from '../src/core/random';

function option(name: string, fallback: string): string {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? process.argv[index + 1] : fallback;
}

const cells = Number(option('cells', '1000000'));
const iterations = Number(option('iterations', '10'));
const workers = option('workers', '');
const dir = option('dir', '/tmp/tissue-sheet-million');
mkdirSync(dir, { recursive: true });
const side = 10000;
// 16.8 texels per cell (the feasibility check asks for 16).
const resolution = Math.ceil(Math.sqrt(cells * 16.8));
const config = {
  surface: { kind: 'plane', width: side, height: side, periodicX: true, periodicY: true },
  resolution,
  cells,
  engine: 'exact',
  lloyd: { maxIterations: iterations, tolerance: 0 },
  sheet: { thickness: 5, adjacency: 'exact' },
};
const configPath = join(dir, 'config.json');
const out = join(dir, 'result.json');
writeFileSync(configPath, JSON.stringify(config, null, 2));

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

// Baseline: d3-delaunay's Delaunay + Voronoi of as many points, in this process, 3 times before
// the run and 2 times after it (a shared machine's load changes): the median of the 5.
const d3: number[] = [];
function timeD3(rounds: number): void {
  for (let r = 0; r < rounds; r++) {
    const random = new Random(d3.length + 1);
    const points = new Float64Array(2 * cells);
    for (let k = 0; k < points.length; k++) points[k] = random.next() * side;
    const start = performance.now();
    new Delaunay(points).voronoi([0, 0, side, side]);
    d3.push(performance.now() - start);
  }
}
const loadBefore = loadavg()[0].toFixed(1);
timeD3(3);

const command = [process.execPath, 'tests/cli/fromSource.mjs', 'run', configPath, '--out', out, '--force', ...(workers ? ['--workers', workers] : [])];
const wrapped = process.env.DISPLAY ? ['/usr/bin/time', '-v', ...command] : ['/usr/bin/time', '-v', 'xvfb-run', '-a', ...command];
const run = spawnSync(wrapped[0], wrapped.slice(1), { encoding: 'utf8' });
if (run.status !== 0) throw new Error(`tissue-sheet run failed (${run.status}):\n${run.stderr.slice(-2000)}`);
timeD3(2);
const d3Ms = median(d3);
const field = (pattern: RegExp) => Number(pattern.exec(run.stderr)![1]);
const rss = field(/Maximum resident set size \(kbytes\): (\d+)/) * 1024;
const wall = /Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([\d:.]+)/
  .exec(run.stderr)![1]
  .split(':')
  .reduce((a, part) => 60 * a + Number(part), 0);
const cpu = field(/User time \(seconds\): ([\d.]+)/) + field(/System time \(seconds\): ([\d.]+)/);

const readStart = performance.now();
const { result, tables } = readResultFile(out);
const readMs = performance.now() - readStart;
const sideBytes = tables ? statSync(join(dir, result.cellsFile!.path)).size : 0;
const gb = (bytes: number) => (bytes / 1e9).toFixed(2);
const t = result.timings;

console.log(`load average before/after: ${loadBefore} / ${loadavg()[0].toFixed(1)}`);
console.log(
  `tissue-sheet run: ${cells} cells, periodic plane ${resolution}² texels, ${iterations} Lloyd iterations, exact engine, thickness 5, exact analysis on 2 surfaces, ` +
    `headline over ${result.headline?.realizations ?? 1} realizations, --workers ${workers || 'default (the cores)'}`,
);
console.log('| figure | value | against |');
console.log('|---|---|---|');
console.log(
  `| wall time (process) | ${wall.toFixed(1)} s | ${(wall / 60).toFixed(2)}x the 60 s target; ${((wall * 1000) / d3Ms).toFixed(0)}x d3 Delaunay + Voronoi of ${cells} points (${d3Ms.toFixed(0)} ms, same run) |`,
);
console.log(`| CPU time (user + sys) | ${cpu.toFixed(1)} s | ${((cpu * 1000) / d3Ms).toFixed(1)}x d3 (CPU against wall: the load-independent figure) |`);
console.log(`| peak RSS | ${gb(rss)} GB | ${(rss / 4e9).toFixed(2)}x the 4 GB target |`);
console.log(
  `| Lloyd, per iteration | ${(t.lloydMs / iterations / 1000).toFixed(2)} s | ${(t.lloydMs / iterations / d3Ms).toFixed(2)}x d3 Delaunay + Voronoi |`,
);
console.log(`| adjacency + analysis + cell columns | ${(t.adjacencyMs / 1000).toFixed(1)} s | |`);
console.log(`| result JSON | ${(statSync(out).size / 1e3).toFixed(0)} kB | |`);
console.log(`| side file | ${(sideBytes / 1e6).toFixed(0)} MB | ${(sideBytes / cells).toFixed(0)} B per cell (both surfaces and the analysis) |`);
console.log(`| side file read back (readResultFile, columns) | ${readMs.toFixed(0)} ms | |`);
