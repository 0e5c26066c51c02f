/**
 * The published tube grid with the exact engine and the lab protocol:
 * Voronoi 1–10 × s = 1 … 10 (12 ratios) × 20 realizations = 2,400 runs.
 * One Lloyd run of 9 iterations per realization gives Voronoi 1..10 (Voronoi k = sites after k−1
 * iterations); each Voronoi k is analysed at every ratio in one pass over the layers
 * 1 : 0.25 : 10 (labTubeTable). Then the Flintstones law is fitted per Voronoi k.
 *
 *   npx tsx bench/exactSweep.ts [--realizations 20] [--scaling] [--json out.json]
 */
import type { Grid } from '../src/core/grid';
import { placeSites } from '../src/core/sites';
import { ExactLloydRun } from '../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../src/core/exactEngine/exactSurface';
import { PlanarVoronoi } from '../src/core/exactEngine/planarVoronoi';
import { LAB_PROTOCOL, type LabProtocolSettings } from '../src/core/analysis/protocol';
import { labTubeTable, type LabRatioRow, type SurfaceOf } from '../src/core/analysis/protocolTube';
import { fitFlintstones } from '../src/core/analysis/flintstones';

const RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10];
const VORONOI = 10;
const args = process.argv.slice(2);
const option = (name: string, fallback: number) => {
  const at = args.indexOf(`--${name}`);
  return at >= 0 ? Number(args[at + 1]) : fallback;
};
const realizations = option('realizations', 20);
const tube: Grid = { width: 512, height: 4096, texelX: 1, texelY: 1, periodicX: true, periodicY: false };

let peakRss = 0;
const sampleMemory = () => (peakRss = Math.max(peakRss, process.memoryUsage().rss));

/** One realization: Voronoi 1..10 × every ratio. */
function realization(grid: Grid, cells: number, seed: number, spacing: number, settings: LabProtocolSettings, voronoi = VORONOI) {
  const sites = placeSites(grid, cells, seed, spacing);
  const reuse = new PlanarVoronoi(grid, cells, true);
  // Within one Voronoi k the layers are the same sites: each layer after the first flips the
  // previous layer's triangulation (as the CLI's layers do), a new k triangulates afresh.
  let continues = false;
  const surfaceOf: SurfaceOf = (g, s, label) => {
    const surface = exactSurface(g, s, label, reuse, continues);
    continues = true;
    return surface;
  };
  const run = new ExactLloydRun(grid, sites, { maxIterations: voronoi - 1, tolerance: 0, overRelaxation: 1 });
  const tables: LabRatioRow[][] = [];
  let lloydMs = 0;
  let analysisMs = 0;
  for (let k = 1; k <= voronoi; k++) {
    if (k > 1) {
      const t = performance.now();
      run.step();
      lloydMs += performance.now() - t;
    }
    const t = performance.now();
    continues = false;
    tables.push(labTubeTable(grid, sites, RATIOS, settings, surfaceOf));
    analysisMs += performance.now() - t;
    sampleMemory();
  }
  return { tables, lloydMs, analysisMs };
}

const start = performance.now();
const all: LabRatioRow[][][] = [];
let lloydMs = 0;
let analysisMs = 0;
for (let r = 1; r <= realizations; r++) {
  const result = realization(tube, 200, r, 5, LAB_PROTOCOL);
  all.push(result.tables);
  lloydMs += result.lloydMs;
  analysisMs += result.analysisMs;
}
const totalMs = performance.now() - start;
const runs = realizations * VORONOI * RATIOS.length;

console.log(
  `exact engine, lab protocol: ${runs} runs (${realizations} realizations x Voronoi 1-${VORONOI} x ${RATIOS.length} ratios) in ${(totalMs / 1000).toFixed(2)} s = ${(runs / (totalMs / 1000)).toFixed(0)} runs/s`,
);
console.log(
  `  Lloyd ${(lloydMs / 1000).toFixed(2)} s, layers and analysis ${(analysisMs / 1000).toFixed(2)} s, peak RSS ${(peakRss / 2 ** 20).toFixed(0)} MiB`,
);
console.log('% scutoids (mean over realizations), rows Voronoi k, columns s:');
console.log('  k   ' + RATIOS.map((s) => String(s).padStart(6)).join(''));
for (let k = 0; k < VORONOI; k++) {
  const cells = RATIOS.map((_, t) => all.reduce((sum, tables) => sum + tables[k][t].percentScutoids, 0) / all.length);
  console.log(`  ${String(k + 1).padStart(2)}  ` + cells.map((v) => v.toFixed(1).padStart(6)).join(''));
}
console.log('Flintstones law n3D(s) = Nmax (b + e^{s/c}) / (d + e^{s/c}), n3D(1) = 6, fitted per Voronoi k on every realization:');
for (const k of [0, 4, 9]) {
  const points = all.flatMap((tables) => tables[k].map((row) => ({ s: row.ratio, n: row.meanNeighbours3D })));
  try {
    const fit = fitFlintstones(points);
    const p = fit.parameters;
    const se = fit.standardErrors;
    console.log(
      `  Voronoi ${k + 1}: Nmax ${p.nMax.toFixed(3)} ± ${se.nMax.toFixed(3)}, c ${p.c.toFixed(3)} ± ${se.c.toFixed(3)}, d ${p.d.toFixed(3)} ± ${se.d.toFixed(3)}, R² ${fit.rSquared.toFixed(3)}`,
    );
  } catch (error) {
    console.log(`  Voronoi ${k + 1}: ${(error as Error).message}`);
  }
}

if (args.includes('--scaling')) {
  console.log('scaling (one realization, Voronoi 1 and 2, all 12 ratios, lab protocol):');
  for (const cells of [200, 2000, 20000]) {
    const spacing = 5 * Math.sqrt(200 / cells);
    const t = performance.now();
    const result = realization(tube, cells, 1, spacing, LAB_PROTOCOL, 2);
    const ms = performance.now() - t;
    console.log(
      `  ${cells} cells: ${(ms / (2 * RATIOS.length)).toFixed(1)} ms per run (Lloyd iteration ${result.lloydMs.toFixed(1)} ms, 37 layers ${(result.analysisMs / 2).toFixed(1)} ms per Voronoi k), peak RSS ${(peakRss / 2 ** 20).toFixed(0)} MiB`,
    );
  }
  for (const step of [0.25, 0.125, 0.0625]) {
    const t = performance.now();
    realization(tube, 200, 1, 5, { ...LAB_PROTOCOL, layerStep: step }, 2);
    const layers = Math.round(9 / step) + 1;
    console.log(`  layer step ${step} (${layers} layers): ${((performance.now() - t) / (2 * RATIOS.length)).toFixed(2)} ms per run`);
  }
}
