import { bruteForceLabels } from '../tests/oracles/labels';
import type { Grid } from '../src/core/grid';
import { coldSchedule } from '../src/core/jumpSchedule';
import { placeSites } from '../src/core/sites';
import type { GpuContext } from '../src/gpu/context';
import { cpuLloydIterations } from './cpuLloyd';
import { FloorJumpFlood } from './floorJumpFlood';
import { GpuEngine, type EngineOptions } from '../src/gpu/engine';
import { gridLayout } from '../src/gpu/layout';
import { GpuLloydRun, gridSites } from '../src/gpu/lloyd';

export interface BenchCase {
  readonly size: number;
  readonly sites: number;
}

export interface BenchOptions {
  /** Site counts to try at every size (only where each cell gets >= 16 texels). */
  readonly siteCounts: readonly number[];
  readonly centroidPath: EngineOptions['centroidPath'];
  /** Floor/cold flood alternations (default 9 up to 1024², 5 above). */
  readonly rounds?: number;
  /** Lloyd iterations per run (default 12). */
  readonly iterations?: number;
}

export interface BenchRow {
  readonly environment: string;
  readonly renderer: string;
  readonly centroidPath: string;
  readonly size: number;
  readonly sites: number;
  readonly skipped?: string;
  /** Minimal hand-written WebGL2 jump flood, same size and step schedule (the floor). */
  readonly floorJumpFloodMs?: number;
  /** The engine's cold jump flood (jfa+2). */
  readonly coldJumpFloodMs?: number;
  readonly coldPasses?: number;
  /** Floor/cold alternations the two medians above are over. */
  readonly rounds?: number;
  /** Jump flood of a warm-started iteration (after the first few), and its passes. */
  readonly warmJumpFloodMs?: number;
  readonly warmPasses?: number;
  readonly centroidMs?: number;
  /** Whole Lloyd iteration after the first (warm-started), no profiling syncs. */
  readonly lloydIterationMs?: number;
  /** Every iteration of the unprofiled run, and (profiled run) every flood, its passes, every centroid pass. */
  readonly perIteration?: {
    readonly iterationMs: number[];
    readonly jumpFloodMs: number[];
    readonly jumpFloodPasses: number[];
    readonly centroidMs: number[];
  };
  readonly firstIterationMs?: number;
  /** Exact Lloyd iteration on the CPU with d3-delaunay. */
  readonly cpuDelaunayIterationMs?: number;
  /** Fraction of texels mislabeled after the warm iterations (vs brute force; sizes <= 1024). */
  readonly warmMislabeled?: number;
  readonly ratios?: {
    readonly jumpFloodVsFloor: number;
    readonly warmIterationVsColdJumpFlood: number;
    readonly cpuVsGpuIteration: number;
  };
}

// Lloyd iterations timed per case by default, from random sites; the warm-start figures are
// medians over every iteration after the first (sites move by tens of texels in the first few,
// by a texel or two from about the fifth on).
const defaultIterations = 12;

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

/**
 * Times the engine on square open planes. `budgetMs` skips a case whose cost, predicted from the
 * previous size, would exceed it (software renderers are ~1000x slower than a GPU).
 */
export async function measure(
  context: GpuContext,
  environment: string,
  cases: readonly BenchCase[],
  budgetMs: number,
  options: BenchOptions,
  log: (line: string) => void = () => {},
): Promise<BenchRow[]> {
  const { centroidPath } = options;
  const iterations = options.iterations ?? defaultIterations;
  const rows: BenchRow[] = [];
  const { renderer: rendererName, maxTextureSize } = context.capabilities;
  let msPerTexel = 0;
  for (const { size, sites: count } of cases) {
    const base = { environment, renderer: rendererName, centroidPath: '', size, sites: count };
    if (size > maxTextureSize) {
      rows.push({ ...base, skipped: `larger than MAX_TEXTURE_SIZE ${maxTextureSize}` });
      continue;
    }
    // Alternated floor and cold floods, then two Lloyd runs (a cold flood and ~4-pass warm ones).
    const rounds = options.rounds ?? (size <= 1024 ? 9 : 5);
    const steps = coldSchedule(size, size, 'jfa+2');
    const predicted = msPerTexel * size * size * (2 * rounds * steps.length + 2 * (steps.length + 4 * (iterations - 1)));
    if (predicted > budgetMs) {
      rows.push({ ...base, skipped: `predicted ${(predicted / 1000).toFixed(0)} s > budget ${(budgetMs / 1000).toFixed(0)} s` });
      continue;
    }
    log(`${environment}: ${size}² with ${count} sites`);
    const grid: Grid = { width: size, height: size, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const sites = placeSites(grid, count, 42, 1.5);

    const floor = new FloorJumpFlood(context.gl, size, size);
    floor.setSeeds(sites, count);
    floor.flood(steps); // warm-up: compile, first upload
    context.renderer.resetState();
    const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath });
    try {
      engine.setSites(sites);
      engine.floodLabels();
      engine.sync();
      // Floor and engine alternate, so a slow spell of a shared machine hits both alike; 9
      // rounds by default (5 past 1024²), because single floods on SwiftShader vary by +-15%.
      const floorTimes: number[] = [];
      const coldTimes: number[] = [];
      for (let r = 0; r < rounds; r++) {
        let t = performance.now();
        floor.flood(steps);
        floorTimes.push(performance.now() - t);
        context.renderer.resetState();
        t = performance.now();
        engine.floodLabels();
        engine.sync();
        coldTimes.push(performance.now() - t);
      }
      floor.dispose();
      context.renderer.resetState();
      const coldJumpFloodMs = median(coldTimes);

      // Profiled run: jump flood and centroid pass timed apart.
      const profiled = new GpuLloydRun(engine, gridSites(grid, sites.slice()), {
        maxIterations: iterations,
        tolerance: 0,
        overRelaxation: 1,
        warmStart: true,
        profile: true,
      });
      while (!profiled.done) profiled.step();
      const later = profiled.iterations.slice(1);
      const warmJumpFloodMs = median(later.map((r) => r.diagramMs));
      const centroidMs = median(later.map((r) => r.centroidMs));
      const warmPasses = later.reduce((sum, r) => sum + r.jumpFloodPasses, 0) / later.length;
      let warmMislabeled: number | undefined;
      if (size <= 1024) {
        const reference = bruteForceLabels(grid, profiled.sites);
        const labels = engine.readLabels();
        let wrong = 0;
        for (let i = 0; i < reference.length; i++) if (labels[i] !== reference[i]) wrong++;
        warmMislabeled = wrong / reference.length;
      }

      // Unprofiled run: what an iteration really costs.
      const plain = new GpuLloydRun(engine, gridSites(grid, sites.slice()), {
        maxIterations: iterations,
        tolerance: 0,
        overRelaxation: 1,
        warmStart: true,
      });
      const stepTimes: number[] = [];
      while (!plain.done) {
        const t = performance.now();
        plain.step();
        stepTimes.push(performance.now() - t);
      }
      const firstIterationMs = stepTimes[0];
      const lloydIterationMs = median(stepTimes.slice(1));

      const cpuSites = Float64Array.from(sites);
      const cpuDelaunayIterationMs = cpuLloydIterations(cpuSites, size, size, Math.min(iterations, count > 50_000 ? 2 : iterations));

      const floorJumpFloodMs = median(floorTimes);
      rows.push({
        ...base,
        centroidPath: engine.centroidPath,
        floorJumpFloodMs,
        coldJumpFloodMs,
        coldPasses: steps.length,
        rounds,
        warmJumpFloodMs,
        warmPasses,
        centroidMs,
        lloydIterationMs,
        perIteration: {
          iterationMs: stepTimes,
          jumpFloodMs: profiled.iterations.map((r) => r.diagramMs),
          jumpFloodPasses: profiled.iterations.map((r) => r.jumpFloodPasses),
          centroidMs: profiled.iterations.map((r) => r.centroidMs),
        },
        firstIterationMs,
        cpuDelaunayIterationMs,
        warmMislabeled,
        ratios: {
          jumpFloodVsFloor: coldJumpFloodMs / floorJumpFloodMs,
          warmIterationVsColdJumpFlood: lloydIterationMs / coldJumpFloodMs,
          cpuVsGpuIteration: cpuDelaunayIterationMs / lloydIterationMs,
        },
      });
      msPerTexel = Math.max(msPerTexel, coldJumpFloodMs / (size * size * steps.length));
    } finally {
      engine.dispose();
    }
    await new Promise((resolve) => setTimeout(resolve, 0));
  }
  return rows;
}

/** The cases the issue asks for: 200, 10k, 100k sites where each cell gets >= 16 texels. */
export function benchCases(sizes: readonly number[], siteCounts: readonly number[] = [200, 10_000, 100_000]): BenchCase[] {
  const cases: BenchCase[] = [];
  for (const size of sizes) {
    for (const sites of siteCounts) if (size * size >= 16 * sites) cases.push({ size, sites });
  }
  return cases;
}

export function formatTable(rows: readonly BenchRow[]): string {
  const header = [
    'env',
    'size',
    'sites',
    'path',
    'floor JFA',
    'cold JFA',
    'x floor',
    'warm JFA (passes)',
    'centroid',
    'iteration',
    'iter/cold JFA',
    'CPU d3 iter',
    'CPU/GPU',
    'warm err',
  ];
  const lines = [header.join(' | ')];
  const ms = (v?: number) => (v === undefined ? '-' : v < 10 ? v.toFixed(2) : v.toFixed(0));
  for (const r of rows) {
    if (r.skipped) {
      lines.push([r.environment, `${r.size}²`, r.sites, 'skipped: ' + r.skipped].join(' | '));
      continue;
    }
    lines.push(
      [
        r.environment,
        `${r.size}²`,
        r.sites,
        r.centroidPath,
        ms(r.floorJumpFloodMs),
        ms(r.coldJumpFloodMs),
        r.ratios!.jumpFloodVsFloor.toFixed(2),
        `${ms(r.warmJumpFloodMs)} (${r.warmPasses!.toFixed(1)})`,
        ms(r.centroidMs),
        ms(r.lloydIterationMs),
        r.ratios!.warmIterationVsColdJumpFlood.toFixed(2),
        ms(r.cpuDelaunayIterationMs),
        r.ratios!.cpuVsGpuIteration.toFixed(2),
        r.warmMislabeled === undefined ? '-' : r.warmMislabeled.toExponential(1),
      ].join(' | '),
    );
  }
  return lines.join('\n');
}
