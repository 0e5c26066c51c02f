/**
 * The shipped reference curves: tissue-sheet's own reproduction of the Voronoi tubular model of
 * Gómez-Gálvez et al. 2018 (Nat. Commun. 9:2960): the published tube (200 cells, 512 × 4096 µm,
 * 5 µm apart), protocol "lab", exact engine, Voronoi k = 1–8 and 10, s = 1 : 0.25 : 4 and
 * 5, 6, 8, 10, 20 realizations. These are our numbers, not the paper's (docs/reference-curves.md).
 *
 * The spec is a sweep spec (docs/sweep.md) and its runs are computed as bench/exactSweep.ts does
 * (one Lloyd run of 9 iterations per realization, Voronoi k read after k − 1 iterations, each k
 * analysed at every ratio in one pass over the layers), which gives the pipeline's numbers for
 * the spec's runs (tests/reference/shipped.test.ts checks some through SheetRunner). The file
 * holds no date: the same version gives the same bytes.
 *
 *   npx tsx scripts/reference-curves.ts          write src/core/reference/tissueSheetVoronoiTube.json
 *   npx tsx scripts/reference-curves.ts --check  exit 1 when the committed file differs
 */
import { readFileSync, writeFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { LAB_PROTOCOL, type LabProtocolSettings } from '../src/core/analysis/protocol';
import { labTubeTable, type SurfaceOf } from '../src/core/analysis/protocolTube';
import { makeGrid, validateConfig, type PlanarConfig } from '../src/core/config';
import { ExactLloydRun } from '../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../src/core/exactEngine/exactSurface';
import { PlanarVoronoi } from '../src/core/exactEngine/planarVoronoi';
import { validateReferenceDocument, REFERENCE_FORMAT, REFERENCE_FORMAT_VERSION, type ReferenceCurve, type ReferenceDocument } from '../src/core/reference';
import { placeSites } from '../src/core/sites';
import { expandSweep } from '../src/core/sweep';
import { version } from '../src/version';

export const OUTPUT = fileURLToPath(new URL('../src/core/reference/tissueSheetVoronoiTube.json', import.meta.url));
const VORONOI_K = [1, 2, 3, 4, 5, 6, 7, 8, 10];
const RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.25, 2.5, 2.75, 3, 3.25, 3.5, 3.75, 4, 5, 6, 8, 10];
const REALIZATIONS = 20;
const SEED = 2018;
/** Decimals kept of each mean and SD (the test recomputes them to this precision). */
export const DECIMALS = 6;

const SOURCE =
  `computed by tissue-sheet ${version} (scripts/reference-curves.ts, protocol lab, exact engine), ` +
  'a reproduction of the Voronoi tubular model of Gómez-Gálvez et al. 2018 (Nat. Commun. 9:2960) — not numbers taken from the paper';

function spec() {
  const base = validateConfig({
    surface: { kind: 'tube', radius: 512 / (2 * Math.PI), length: 4096 },
    resolution: 512,
    cells: 200,
    minSpacing: 5,
    engine: 'exact',
    lloyd: { maxIterations: 0, tolerance: 0 },
    sheet: { seeded: 'apical', direction: 'outward', adjacency: 'exact', protocol: 'lab', surfaceRatio: 1 },
  }) as unknown as Record<string, unknown>;
  delete base.seed;
  return {
    base,
    vary: { 'lloyd.maxIterations': VORONOI_K.map((k) => k - 1), 'sheet.surfaceRatio': RATIOS },
    realizations: REALIZATIONS,
    seed: SEED,
    seedMode: 'per-realization' as const,
  };
}

const round = (v: number) => Number(v.toFixed(DECIMALS));

/** Mean, sample SD and n of values. */
function stats(values: number[]) {
  const n = values.length;
  const mean = values.reduce((a, b) => a + b, 0) / n;
  const sd = n > 1 ? Math.sqrt(values.reduce((a, v) => a + (v - mean) ** 2, 0) / (n - 1)) : 0;
  return { mean, sd, n };
}

/** % scutoids (exact adjacency) per realization, Voronoi k and ratio: [r][k index][ratio index]. */
function compute(sweep: ReturnType<typeof spec>, seeds: number[]): number[][][] {
  // The published tube: a planar (tube) config.
  const config = validateConfig({ ...sweep.base, seed: seeds[0] }) as PlanarConfig;
  const grid = makeGrid(config);
  const sheet = config.sheet;
  const settings: LabProtocolSettings = { ...LAB_PROTOCOL, layerStep: sheet.layerStep ?? LAB_PROTOCOL.layerStep, validityMaxRatio: sheet.validityMaxRatio };
  const last = Math.max(...VORONOI_K);
  return seeds.map((seed) => {
    const sites = placeSites(grid, config.cells, seed, config.minSpacing);
    const reuse = new PlanarVoronoi(grid, config.cells);
    const surfaceOf: SurfaceOf = (g, s, label) => exactSurface(g, s, label, reuse);
    const run = new ExactLloydRun(grid, sites, { ...config.lloyd, maxIterations: last - 1 });
    const byK: number[][] = [];
    for (let k = 1; k <= last; k++) {
      if (k > 1) run.step();
      if (VORONOI_K.includes(k)) byK.push(labTubeTable(grid, sites, RATIOS, settings, surfaceOf).map((row) => row.percentScutoids));
    }
    return byK;
  });
}

export function build(): ReferenceDocument {
  const sweep = spec();
  const runs = expandSweep(sweep);
  const seeds = runs.filter((r) => r.index < REALIZATIONS).map((r) => r.seed);
  const values = compute(sweep, seeds);
  const point = (ki: number, si: number, x: number) => {
    const s = stats(values.map((byK) => byK[ki][si]));
    return { x, percent: round(s.mean), sd: round(s.sd), n: s.n, source: SOURCE };
  };
  const curves: ReferenceCurve[] = [
    ...VORONOI_K.map((k, ki) => ({
      id: `tube-voronoi-${k}`,
      label: `tissue-sheet, Voronoi ${k}`,
      kind: 'model' as const,
      quantity: 'surfaceRatio',
      fixed: { voronoiK: k },
      points: RATIOS.map((s, si) => point(ki, si, s)),
    })),
    ...RATIOS.map((s, si) => ({
      id: `tube-s-${s}`,
      label: `tissue-sheet, s = ${s}`,
      kind: 'model' as const,
      quantity: 'voronoiK',
      fixed: { surfaceRatio: s },
      points: VORONOI_K.map((k, ki) => point(ki, si, k)),
    })),
  ];
  const doc: ReferenceDocument = {
    format: REFERENCE_FORMAT,
    version: REFERENCE_FORMAT_VERSION,
    title: `tissue-sheet ${version}: % scutoids on the published tube (200 cells), protocol lab, exact engine, ${REALIZATIONS} realizations — a reproduction, not the paper's numbers`,
    provenance: {
      software: { name: 'tissue-sheet', version },
      script: 'scripts/reference-curves.ts',
      command: 'npx tsx scripts/reference-curves.ts',
      model:
        'Voronoi tubular model of Gómez-Gálvez et al. 2018 (Nat. Commun. 9:2960), as tissue-sheet implements it (docs/protocols.md); these numbers were computed here, none was taken from the paper',
      spec: sweep,
      seeds,
      method:
        'the runs of `spec` (a sweep spec, docs/sweep.md; the seed of realization r is seeds[r]); per realization one exact Lloyd run, Voronoi k read after k − 1 iterations, every ratio analysed on the layers s = 1 : 0.25 : 10 (labTubeTable), the numbers the pipeline gives for each run',
      statistics: `percent: mean over the realizations of exact.percentScutoids; sd: sample standard deviation (n − 1); n: realizations; both rounded to ${DECIMALS} decimals`,
    },
    curves,
  };
  // The file must pass its own format's validation.
  validateReferenceDocument(JSON.parse(JSON.stringify(doc)));
  return doc;
}

if (process.argv[1] && fileURLToPath(import.meta.url) === process.argv[1]) {
  const start = performance.now();
  const doc = build();
  const seconds = ((performance.now() - start) / 1000).toFixed(1);
  const runs = VORONOI_K.length * RATIOS.length * REALIZATIONS;
  if (process.argv.includes('--check')) {
    // The same document, whatever the layout (the committed file is laid out by Prettier).
    const same = JSON.stringify(JSON.parse(readFileSync(OUTPUT, 'utf8'))) === JSON.stringify(doc);
    console.log(`${same ? 'up to date' : 'DIFFERS'}: ${OUTPUT} (${runs} runs in ${seconds} s)`);
    process.exit(same ? 0 : 1);
  }
  // Laid out as `npm run format` lays it out, so the two never fight over the file.
  const prettier = await import('prettier');
  const options = await prettier.resolveConfig(OUTPUT);
  writeFileSync(OUTPUT, await prettier.format(JSON.stringify(doc, null, 1), { ...options, parser: 'json', filepath: OUTPUT }));
  console.log(`wrote ${OUTPUT}: ${runs} runs in ${seconds} s`);
}
