// The labels method on closed surfaces against the exact method (the restricted Voronoi
// diagram), run through the real pipeline: `SheetRunner` with sheet.adjacency "both" gives
// both analyses of the same sites on the same surfaces. Per surface and cube-map resolution
// (32, 64, 128, 256 and the default that validation fills in, src/core/config/feasibility.ts
// defaultResolution), over seeds and thicknesses:
//   - cells agreeing: the fraction of cells whose labels-method record equals the exact
//     method's: the same number of sides on the basal and on the apical surface and the same
//     neighbours won and lost between them (the records of analyses[].cells; the neighbour
//     sets themselves are not in the result, and equal sides, won and lost on both surfaces
//     is what every statistic downstream reads);
//   - scutoid flags agreeing: the fraction of cells the two methods classify alike;
//   - |Δ % scutoids|: per run, labels minus exact, mean and largest.
// Both methods apply the same minimum contact length in µm (the lab's 6/102.4 of the mean cell
// diameter); the labels method's contact lengths are the unbiased ones of cubeLabelAdjacency.
//
//   xvfb-run -a npx tsx bench/labelAccuracy.ts [--surfaces sphere,ellipsoid,mesh]
//     [--resolutions 32,64,128,256,default] [--seeds 1,2] [--thickness 5,20] [--iterations 5]
//     [--cells 200] [--json bench/out/labelAccuracy.json]
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import { validateConfig, type ClosedConfig, type ConfigInput } from '../src/core/config';
import { createHeadlessContext } from '../src/node/headless';
import { SheetRunner } from '../src/run/runSheet';
import type { AnalysisRecord } from '../src/core/analysis/record';

function option(name: string, fallback: string): string {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? process.argv[index + 1] : fallback;
}
const list = (name: string, fallback: string) => option(name, fallback).split(',').filter(Boolean);

const surfaces: Record<string, ConfigInput['surface']> = {
  sphere: { kind: 'sphere', radius: 60 },
  ellipsoid: { kind: 'ellipsoid', a: 90, b: 45, c: 45 },
  // 2:1:1 egg chamber, 2 mesh units -> 90 µm (the ellipsoid's size).
  mesh: { kind: 'mesh', src: 'egg-chamber.ply', scale: 45 },
};
const surfaceNames = list('surfaces', 'sphere,ellipsoid,mesh');
const resolutions = list('resolutions', '32,64,128,256,default');
const seeds = list('seeds', '1,2').map(Number);
const thicknesses = list('thickness', '5,20').map(Number);
const iterations = Number(option('iterations', '5'));
const cells = Number(option('cells', '200'));
const jsonPath = option('json', 'bench/out/labelAccuracy.json');

interface Row {
  surface: string;
  resolution: number;
  texelUm: number;
  minContactUm: number;
  runs: number;
  cellsAgreeing: number;
  flagsAgreeing: number;
  meanAbsDeltaScutoids: number;
  maxAbsDeltaScutoids: number;
  meanPercentScutoidsExact: number;
  seconds: number;
}

/** Cells whose labels record matches the exact one (sides on every surface, won, lost), and whose scutoid flags match. */
function agreement(labels: AnalysisRecord, exact: AnalysisRecord): { cells: number; flags: number; total: number } {
  let same = 0,
    flags = 0;
  for (let k = 0; k < exact.cells.length; k++) {
    const l = labels.cells[k],
      e = exact.cells[k];
    if (l.id !== e.id) throw new Error(`cell records out of order at ${k}`);
    if (l.sides.join() === e.sides.join() && l.won === e.won && l.lost === e.lost) same++;
    if (l.scutoid === e.scutoid) flags++;
  }
  return { cells: same, flags, total: exact.cells.length };
}

const context = createHeadlessContext();
const runner = new SheetRunner(context);
const rows: Row[] = [];
const started = performance.now();
try {
  for (const name of surfaceNames) {
    for (const res of resolutions) {
      const t0 = performance.now();
      let agreeCells = 0,
        agreeFlags = 0,
        total = 0,
        runs = 0,
        sumDelta = 0,
        maxDelta = 0,
        sumExact = 0;
      let resolution = 0,
        texelUm = 0,
        minContactUm = 0;
      for (const seed of seeds) {
        for (const thickness of thicknesses) {
          const config = validateConfig({
            surface: surfaces[name],
            cells,
            seed,
            resolution: res === 'default' ? null : Number(res),
            lloyd: { maxIterations: iterations },
            sheet: { thickness, adjacency: 'both' },
          }) as ClosedConfig;
          const { result } = await runner.run(config);
          const labels = result.analyses.find((a) => a.method === 'labels');
          const exact = result.analyses.find((a) => a.method === 'exact');
          if (!labels || !exact) throw new Error(`${name} n ${res}: the result lacks a labels or exact analysis`);
          const a = agreement(labels, exact);
          agreeCells += a.cells;
          agreeFlags += a.flags;
          total += a.total;
          const delta = Math.abs(labels.summary.percentScutoids - exact.summary.percentScutoids);
          sumDelta += delta;
          maxDelta = Math.max(maxDelta, delta);
          sumExact += exact.summary.percentScutoids;
          runs++;
          resolution = config.resolution!;
          const area = result.closed?.area ?? NaN;
          texelUm = Math.sqrt(area / (6 * resolution * resolution));
          minContactUm = exact.minContactLength;
        }
      }
      const row: Row = {
        surface: name,
        resolution,
        texelUm,
        minContactUm,
        runs,
        cellsAgreeing: agreeCells / total,
        flagsAgreeing: agreeFlags / total,
        meanAbsDeltaScutoids: sumDelta / runs,
        maxAbsDeltaScutoids: maxDelta,
        meanPercentScutoidsExact: sumExact / runs,
        seconds: (performance.now() - t0) / 1000,
      };
      rows.push(row);
      console.error(
        `${name} n ${resolution}${res === 'default' ? ' (default)' : ''}: ${(100 * row.cellsAgreeing).toFixed(1)} % cells agree, |Δ % scutoids| ${row.meanAbsDeltaScutoids.toFixed(2)} (max ${row.maxAbsDeltaScutoids.toFixed(2)}), ${row.seconds.toFixed(1)} s`,
      );
    }
  }
} finally {
  context.dispose();
}

const header =
  '| surface | n | texel edge µm | min contact µm | runs | cells agreeing | scutoid flags agreeing | mean abs Δ % scutoids | max abs Δ | % scutoids (exact) |';
console.log(`${cells} cells, Lloyd ${iterations} iterations, seeds ${seeds.join(', ')}, thickness ${thicknesses.join(', ')} µm outward\n`);
console.log(header);
console.log(header.replace(/[^|]/g, '-').replace(/\|-/g, '|-'));
for (const r of rows) {
  console.log(
    `| ${r.surface} | ${r.resolution}${resolutions.includes(String(r.resolution)) ? '' : ' (default)'} | ${r.texelUm.toFixed(2)} | ${r.minContactUm.toFixed(2)} | ${r.runs} | ${(100 * r.cellsAgreeing).toFixed(1)} % | ${(100 * r.flagsAgreeing).toFixed(1)} % | ${r.meanAbsDeltaScutoids.toFixed(2)} | ${r.maxAbsDeltaScutoids.toFixed(2)} | ${r.meanPercentScutoidsExact.toFixed(1)} |`,
  );
}
console.log(`\n${((performance.now() - started) / 1000).toFixed(0)} s in all`);
mkdirSync(dirname(jsonPath), { recursive: true });
writeFileSync(jsonPath, JSON.stringify({ cells, iterations, seeds, thicknesses, rows }, null, 2));
