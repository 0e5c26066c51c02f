// `npx tsx bench/exactLloyd.ts [--sites 100000] [--iterations 5] [--surfaces plane,periodic,tube]`:
// one exact-engine Lloyd iteration (ExactLloydRun.step: triangulation with the periodic copies
// it needs, every cell integrated, sites moved) against the baseline timed in the same process
// right beside it, alternately: d3-delaunay's Delaunay + Voronoi of the same points
// (`new Delaunay(points).voronoi(bounds)`: the target's baseline), and the same plus every cell's
// polygon read with `cellPolygon` (what an exact Lloyd step needs from d3); no periodic copies.
// Prints the medians and the ratios (issue 27 asks for <= 5x the first at 100,000 sites).
// Asserts nothing: timings depend on the machine.
import { loadavg } from 'node:os';
import { Delaunay } from 'd3-delaunay';
import { ExactLloydRun } from '../src/core/exactEngine';
import type { Grid } from '../src/core/grid';
import { Random } from '../src/core/random';

function option(name: string, fallback: string): string {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? process.argv[index + 1] : fallback;
}

const count = Number(option('sites', '100000'));
const iterations = Number(option('iterations', '5'));
const surfaces = option('surfaces', 'plane,tube,periodic').split(',');

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

/** A square-ish grid with 16+ texels per cell (what the config's feasibility check asks). */
function gridFor(kind: string): Grid {
  const side = Math.ceil(Math.sqrt(count * 64));
  return { width: side, height: side, texelX: 0.5, texelY: 0.5, periodicX: kind !== 'plane', periodicY: kind === 'periodic' };
}

/** d3-delaunay's Delaunay + Voronoi of `points` (µm): [construction ms, + every cell's polygon read ms]. */
function d3Baseline(points: Float64Array, width: number, height: number): [number, number] {
  const start = performance.now();
  const delaunay = new Delaunay(points);
  const voronoi = delaunay.voronoi([0, 0, width, height]);
  const built = performance.now();
  let vertices = 0;
  for (let i = 0; i < points.length / 2; i++) vertices += voronoi.cellPolygon(i)?.length ?? 0;
  const ms = performance.now() - start;
  if (vertices === 0) throw new Error('no cells');
  return [built - start, ms];
}

console.log(`exact Lloyd iteration vs d3-delaunay Delaunay + Voronoi, ${count} sites, median of ${iterations} (ms), load average ${loadavg()[0].toFixed(1)}`);
console.log('| surface | exact Lloyd iteration | d3 Delaunay + Voronoi | ratio | d3 + every cellPolygon | ratio |');
console.log('|---|---|---|---|---|---|');
const ratios: Record<string, number> = {};
for (const kind of surfaces) {
  const grid = gridFor(kind);
  const random = new Random(7);
  const sites = new Float32Array(2 * count);
  for (let i = 0; i < count; i++) {
    sites[2 * i] = random.next() * grid.width;
    sites[2 * i + 1] = random.next() * grid.height;
  }
  const run = new ExactLloydRun(grid, sites, { maxIterations: iterations + 1, tolerance: 0, overRelaxation: 1 });
  run.step(); // first iteration: buffers allocated
  const lloyd: number[] = [];
  const d3: number[] = [];
  const d3Cells: number[] = [];
  const points = new Float64Array(2 * count);
  for (let r = 0; r < iterations; r++) {
    for (let i = 0; i < 2 * count; i += 2) {
      points[i] = sites[i] * grid.texelX;
      points[i + 1] = sites[i + 1] * grid.texelY;
    }
    const [built, withCells] = d3Baseline(points, grid.width * grid.texelX, grid.height * grid.texelY);
    d3.push(built);
    d3Cells.push(withCells);
    const start = performance.now();
    run.step();
    lloyd.push(performance.now() - start);
  }
  const ratio = median(lloyd) / median(d3);
  ratios[kind] = ratio;
  const cellsRatio = median(lloyd) / median(d3Cells);
  console.log(
    `| ${kind} (${grid.width}² texels, ${run.retries} retries) | ${median(lloyd).toFixed(0)} | ${median(d3).toFixed(0)} | ${ratio.toFixed(2)}x | ${median(d3Cells).toFixed(0)} | ${cellsRatio.toFixed(2)}x |`,
  );
}
