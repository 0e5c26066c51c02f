// The GPU engine's correctness on whatever renderer headless-gl gets (llvmpipe here; a real GPU
// on a lent machine, docs/benchmark.md "On a GPU"), against independent CPU references:
//   1. labels: a cold jump flood's label of every texel against the exact nearest site
//      (tests/oracles brute force, float64 over the float32 sites), on planar grids (plane, tube)
//      and cube maps (sphere, ellipsoid, mesh); a differing texel is a tie when the GPU's site is
//      as near as the nearest within float32 rounding (flood.ts tieTolerance), else an error;
//   2. centroids: every centroid path this context has (readback, gather, blend with
//      EXT_float_blend; the cube map has readback and blend) against CPU sums over the GPU's own
//      labels (the pass's arithmetic) and over the exact labels (what Lloyd moves sites by);
//   3. pipeline: whole SheetRunner runs: a tube on the GPU engine against the exact engine,
//      closed surfaces' labels method against their exact method, Lloyd energy non-increasing.
// Prints the renderer, MAX_TEXTURE_SIZE, the extensions and one table; writes JSON; exits 1 if a
// figure is beyond its limit (LIMITS below says why each limit is what it is).
//
//   xvfb-run -a npx tsx bench/gpuCheck.ts [--json bench/out/gpuCheck.json] [--parts labels,centroids,pipeline]
//     [--mesh public/meshes/egg-chamber.ply | none] [--large]
// --large adds 2048² and 4096² grids and an n 512 sphere, 100,000 sites each (for a GPU machine).
import { mkdirSync, writeFileSync } from 'node:fs';
import { dirname } from 'node:path';
import type { JumpFloodVariant } from '../src/core/jumpSchedule';
import type { CentroidPath } from '../src/gpu/centroidPolicy';
import type { GpuContext } from '../src/gpu/context';
import { createHeadlessContext } from '../src/node/headless';
import { SheetRunner } from '../src/run/runSheet';
import { version } from '../src/version';
import { checkCentroids, checkLabels, texelsPerCell, type CentroidErrors } from './gpuCheck/flood';
import { closedRun, tubeRuns, type AnalysisAgreement } from './gpuCheck/pipeline';
import { cubeCase, planarCase, type FloodCase } from './gpuCheck/surfaces';

function option(name: string, fallback: string): string {
  const index = process.argv.indexOf(`--${name}`);
  return index >= 0 ? process.argv[index + 1] : fallback;
}
const jsonPath = option('json', 'bench/out/gpuCheck.json');
const parts = option('parts', 'labels,centroids,pipeline').split(',');
const meshPath = option('mesh', 'public/meshes/egg-chamber.ply');
const large = process.argv.includes('--large');
for (const part of parts)
  if (!['labels', 'centroids', 'pipeline'].includes(part)) throw new Error(`--parts: unknown part "${part}" (labels, centroids, pipeline)`);

/**
 * The limits, and why. Measured on llvmpipe (2026-11-27, docs/benchmark.md "GPU check"):
 * - labels, jfa+2 (the engine's schedule): no texel differs from brute force in any default
 *   case (sites 1.5 texels apart); --large: 1.7e-6 (2048², 100,000 sites) and 6.6e-7 (4096²).
 *   tests/gpu allows 1e-4 (planar), tests/closed 1e-3 (cube map). A GPU runs the same float32
 *   arithmetic (fused multiply-adds may order a tie differently, which counts as a tie): errors
 *   on at most 1e-4 of texels.
 * - labels, plain jfa (not used by the engine; shown to prove the comparison sees flood errors):
 *   at most 1e-2 of texels (the textbook JFA's error rate is ~1e-3 or less).
 * - centroid sums against the GPU's own labels: readback sums in float64 on the CPU (run-length
 *   closed forms on grids): 1e-9. gather and blend sum a cell's n texels in float32 on the GPU:
 *   recursive summation's bound (Higham) is (n − 1)·u·Σ|terms|, u = 2^-24, and each term is at
 *   most the cell's size (offsets), weight or energy share, so n·u of the cell's size, weight and
 *   energy, n the case's largest cell (9e-4 for 15,000 texels; llvmpipe's gather: 1.2e-4 there,
 *   ~1e-6 on cells of ~100 texels). Every cell is held to it ("cells beyond"), except the cells
 *   the flood mislabeled a texel of (the labels part checks those texels).
 * - centroid sums against the exact labels are reported, not checked: they differ from the
 *   own-label sums only on the cells the flood mislabeled a texel of (counted as "touched"), and
 *   the flood's errors are checked in the labels part; one far mislabeled texel moves a small
 *   cell's energy by 20 % (llvmpipe, 2048², 100,000 sites).
 */
const LIMITS = {
  labelErrors: { 'jfa+2': 1e-4, jfa: 1e-2 } as Record<JumpFloodVariant, number>,
  ownSums: { readback: 1e-9, float32PerTexel: 2 ** -24 },
  // Tube, GPU engine against the exact engine from the same seed, each run's exact analysis: the
  // engines' sites part by ~0.5 texel RMS in 5 iterations (tests/exactEngine/gpuCrossCheck.test.ts)
  // and Lloyd amplifies that, which flips a few short contacts. llvmpipe, 3 seeds of 100 cells:
  // 88-100 % of cells agree, |Δ % scutoids| 0-5.6 (one cell is 1.1 points), polygon
  // distributions 0-0.045 apart, final energies 0.9996-1.0003. Limits: twice those gaps.
  tube: { deltaScutoids: 12, cellsAgreeing: 0.75, polygonDistance: 0.1, finalEnergy: 0.002 },
  // Closed surfaces at n 128, labels against the exact method of the same sites. llvmpipe: 96 %
  // (sphere) and 93 % (ellipsoid) of cells agree, |Δ % scutoids| 0 and 2.5, distributions 0.015
  // and 0.03 apart; bench/labelAccuracy over more seeds: 88-96 %, |Δ| up to 6 at n 128.
  closed: { deltaScutoids: 10, cellsAgreeing: 0.8, polygonDistance: 0.1 },
  // Energy non-increasing: relative rise per iteration at most 1e-6 with float64 sums (readback),
  // 1e-5 with float32 sums (gather, blend: ~1e-6 relative error in a total energy).
  energyRise: { readback: 1e-6, gather: 1e-5, blend: 1e-5 } as Record<CentroidPath, number>,
};

interface Row {
  part: 'labels' | 'centroids' | 'pipeline';
  case: string;
  sites: number;
  measure: string;
  value: string;
  limit: string;
  ms: number | null;
  ok: boolean;
  /** The figures behind `value`, for the JSON. */
  data: object;
}

const rows: Row[] = [];
const started = performance.now();
const context = createHeadlessContext();
const info = contextInfo(context);
console.log(`tissue-sheet ${version}, Node ${process.version}`);
for (const [key, value] of Object.entries(info)) console.log(`${key}: ${Array.isArray(value) ? value.join(' ') : value}`);

const planarPaths: CentroidPath[] = context.capabilities.floatBlend ? ['readback', 'gather', 'blend'] : ['readback', 'gather'];
const cubePaths: CentroidPath[] = context.capabilities.floatBlend ? ['readback', 'blend'] : ['readback'];

try {
  if (parts.includes('labels') || parts.includes('centroids')) for (const make of floodCases()) floodCase(make());
  if (parts.includes('pipeline')) await pipelineRuns();
} finally {
  context.dispose();
}

printTable();
const failed = rows.filter((r) => !r.ok);
console.log(`\n${rows.length - failed.length} of ${rows.length} figures within their limits; ${((performance.now() - started) / 1000).toFixed(1)} s in all`);
mkdirSync(dirname(jsonPath), { recursive: true });
writeFileSync(jsonPath, JSON.stringify({ software: { name: 'tissue-sheet', version }, node: process.version, context: info, limits: LIMITS, rows }, null, 2));
if (failed.length > 0) {
  for (const r of failed) console.log(`FAILED: ${r.part} ${r.case} (${r.sites} sites): ${r.measure} ${r.value}, limit ${r.limit}`);
  process.exitCode = 1;
}

/** The cases of parts 1 and 2: 64² to 1024² grids and n 64 to 256 cube maps, 10 to 10,000 sites. */
function floodCases(): (() => FloodCase)[] {
  const cases: (() => FloodCase)[] = [
    () => planarCase('plane', 64, 64, 10, 1, false),
    () => planarCase('plane', 64, 64, 100, 2, true),
    () => planarCase('tube', 256, 256, 100, 1, false),
    () => planarCase('tube', 256, 256, 1000, 2, true),
    () => planarCase('plane', 512, 512, 1000, 3, true),
    () => planarCase('plane', 512, 512, 10000, 1, false),
    () => planarCase('tube', 1024, 1024, 100, 4, false),
    () => planarCase('tube', 1024, 1024, 10000, 2, true),
    // 12 sites on a sphere: cells span several faces.
    () => cubeCase('sphere', 64, 12, 1, meshPath),
    () => cubeCase('sphere', 64, 300, 2, meshPath),
    () => cubeCase('sphere', 256, 10000, 1, meshPath),
    () => cubeCase('ellipsoid', 128, 100, 1, meshPath),
    () => cubeCase('ellipsoid', 128, 2000, 2, meshPath),
  ];
  if (meshPath !== 'none') cases.push(() => cubeCase('mesh', 64, 200, 1, meshPath));
  if (large) {
    cases.push(
      () => planarCase('plane', 2048, 2048, 100000, 1, false),
      () => planarCase('tube', 4096, 4096, 100000, 2, true),
      () => cubeCase('sphere', 512, 100000, 1, meshPath),
    );
  }
  return cases;
}

function floodCase(c: FloodCase): void {
  const reference = c.reference();
  const base = { case: c.name, sites: c.sites };
  if (parts.includes('labels')) {
    for (const variant of ['jfa+2', 'jfa'] as const) {
      const s = checkLabels(context, c, variant, reference);
      const rate = s.errors / s.texels;
      rows.push({
        part: 'labels',
        ...base,
        measure: `${variant} labels (${s.passes} passes)`,
        value: `${s.errors} errors (${rate.toExponential(1)}), ${s.ties} ties of ${s.texels}${s.errors > 0 ? `; worst +${s.worstExcessTexels.toFixed(2)} texel` : ''}`,
        limit: `errors <= ${LIMITS.labelErrors[variant]}`,
        ms: s.floodMs,
        ok: rate <= LIMITS.labelErrors[variant],
        data: s,
      });
    }
  }
  if (parts.includes('centroids')) {
    const exactSums = c.sums(reference);
    const largestCell = texelsPerCell(reference, c.sites).reduce((a, b) => Math.max(a, b), 0);
    for (const path of c.family === 'planar' ? planarPaths : cubePaths) {
      const own = path === 'readback' ? LIMITS.ownSums.readback : largestCell * LIMITS.ownSums.float32PerTexel;
      const s = checkCentroids(context, c, path, reference, exactSums, own);
      rows.push({
        part: 'centroids',
        ...base,
        measure: `${path} sums: own labels; exact labels`,
        value: `${errors(s.own)}${s.own.beyond > 0 ? ` (${s.own.beyond} cells beyond)` : ''}; ${errors(s.exact)}${s.touched > 0 ? ` (${s.touched} cells touched by flood errors)` : ''}`,
        limit: `own <= ${own.toExponential(1)}`,
        ms: s.sumsMs,
        ok: s.own.beyond === 0 && s.exact.emptyCells === 0,
        data: s,
      });
    }
  }
}

function errors(e: CentroidErrors): string {
  return `c ${e.centroid.toExponential(1)} w ${e.mass.toExponential(1)} E ${e.energy.toExponential(1)}${e.emptyCells > 0 ? `, ${e.emptyCells} empty` : ''}`;
}

async function pipelineRuns(): Promise<void> {
  const runner = new SheetRunner(context);
  // Every planar centroid path on seed 1, the default path ("auto") on two more seeds.
  const tubeCases: [number, CentroidPath | 'auto'][] = [...planarPaths.map((p): [number, CentroidPath] => [1, p]), [2, 'auto'], [3, 'auto']];
  for (const [seed, path] of tubeCases) {
    const t0 = performance.now();
    const r = await tubeRuns(runner, seed, path);
    const ms = performance.now() - t0;
    const name = `tube 100 cells seed ${seed}, ${r.path}`;
    const rise = LIMITS.energyRise[r.path!];
    const ok = Math.abs(r.finalEnergyRatio - 1) <= LIMITS.tube.finalEnergy && r.energyRise <= rise && r.exactEnergyRise <= LIMITS.energyRise.readback;
    rows.push(
      agreementRow(name, 100, 'GPU vs exact engine', r.agreement, LIMITS.tube, ms, r),
      energyRow(
        name,
        100,
        'final energy GPU/exact; largest rise',
        `${r.finalEnergyRatio.toFixed(4)}; ${r.energyRise.toExponential(1)} (exact engine ${r.exactEnergyRise.toExponential(1)})`,
        `1 ± ${LIMITS.tube.finalEnergy}; <= ${rise.toExponential(0)}`,
        ok,
        r,
      ),
    );
  }
  const surfaces = [
    ['sphere R 60', { kind: 'sphere', radius: 60 }],
    ['ellipsoid 90:45:45', { kind: 'ellipsoid', a: 90, b: 45, c: 45 }],
  ] as const;
  for (const [label, surface] of surfaces) {
    const t0 = performance.now();
    const r = await closedRun(runner, surface, 1);
    const ms = performance.now() - t0;
    const name = `${label} n 128 seed 1, ${r.path}`;
    const rise = LIMITS.energyRise[r.path!];
    rows.push(
      agreementRow(name, 200, 'labels vs exact method', r.agreement, LIMITS.closed, ms, r),
      energyRow(name, 200, 'largest energy rise', r.energyRise.toExponential(1), `<= ${rise.toExponential(0)}`, r.energyRise <= rise, r),
    );
  }
}

/** One row of a run's Lloyd energies (the run's time is on its agreement row). */
function energyRow(name: string, sites: number, measure: string, value: string, limit: string, ok: boolean, data: object): Row {
  return { part: 'pipeline', case: name, sites, measure, value, limit, ms: null, ok, data };
}

/** One row: % scutoids of the two analyses, the cells whose records agree, the polygon distributions' distance. */
function agreementRow(
  name: string,
  sites: number,
  what: string,
  a: AnalysisAgreement,
  limit: { deltaScutoids: number; cellsAgreeing: number; polygonDistance: number },
  ms: number,
  data: object,
): Row {
  const delta = a.percentScutoids[0] - a.percentScutoids[1];
  return {
    part: 'pipeline',
    case: name,
    sites,
    measure: `${what}: % scutoids; cells agreeing; polygons (TV)`,
    value: `${a.percentScutoids.map((p) => p.toFixed(1)).join(' vs ')} (Δ ${delta.toFixed(1)}); ${pct(a.cellsAgreeing)}; ${a.polygonDistance.toFixed(3)}`,
    limit: `abs Δ <= ${limit.deltaScutoids}; >= ${pct(limit.cellsAgreeing)}; <= ${limit.polygonDistance}`,
    ms,
    ok: Math.abs(delta) <= limit.deltaScutoids && a.cellsAgreeing >= limit.cellsAgreeing && a.polygonDistance <= limit.polygonDistance,
    data,
  };
}

function pct(f: number): string {
  return `${(100 * f).toFixed(1)} %`;
}

/** What the context is: the renderer's strings (headless-gl's own and the driver library mapped in), limits, extensions. */
function contextInfo(c: GpuContext) {
  const gl = c.gl;
  const debug = gl.getExtension('WEBGL_debug_renderer_info');
  return {
    renderer: c.capabilities.renderer,
    'GL renderer': String(gl.getParameter(gl.RENDERER)),
    'GL version': String(gl.getParameter(gl.VERSION)),
    WEBGL_debug_renderer_info: debug ? `${gl.getParameter(debug.UNMASKED_VENDOR_WEBGL)} / ${gl.getParameter(debug.UNMASKED_RENDERER_WEBGL)}` : 'not exposed',
    MAX_TEXTURE_SIZE: c.capabilities.maxTextureSize,
    'software renderer': c.capabilities.softwareRenderer,
    EXT_float_blend: c.capabilities.floatBlend,
    extensions: gl.getSupportedExtensions() ?? [],
  };
}

function printTable(): void {
  console.log('\n| part | case | sites | measure | value | limit | ms | ok |\n|---|---|---|---|---|---|---|---|');
  for (const r of rows) {
    console.log(
      `| ${r.part} | ${r.case} | ${r.sites.toLocaleString('en-US')} | ${r.measure} | ${r.value} | ${r.limit} | ${r.ms === null ? '' : r.ms.toFixed(1)} | ${r.ok ? 'ok' : 'FAIL'} |`,
    );
  }
}
