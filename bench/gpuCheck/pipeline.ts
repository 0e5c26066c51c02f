/**
 * Part 3 of the GPU check: whole runs through the real pipeline (SheetRunner). On a tube, the
 * GPU engine against the exact CPU engine from the same seed (each run's exact analysis: the
 * engines differ only in how Lloyd moved the sites); on closed surfaces, where the GPU is the
 * only engine, its labels method against the exact (restricted Voronoi) method of the same
 * sites (sheet.adjacency "both", as bench/labelAccuracy.ts). Every GPU run's Lloyd energy must
 * not increase.
 */
import { validateConfig, type ConfigInput } from '../../src/core/config';
import type { AnalysisRecord } from '../../src/core/analysis/record';
import type { CentroidPath } from '../../src/gpu/centroidPolicy';
import type { SheetRunner } from '../../src/run/runSheet';
import type { SheetResult } from '../../src/run/result';

/** Two analyses of one sheet compared. */
export interface AnalysisAgreement {
  readonly percentScutoids: [number, number];
  /** Cells whose records agree: the same sides on every surface and the same neighbours won and lost. */
  readonly cellsAgreeing: number;
  /** Largest total-variation distance between the polygon distributions of a surface (0: equal, 1: disjoint). */
  readonly polygonDistance: number;
}

/** A GPU run's Lloyd energies: the largest relative rise from one iteration to the next (0 if none). */
export function largestEnergyRise(result: SheetResult): number {
  const energies = [...result.lloyd.iterations.map((r) => r.energy), result.lloyd.finalEnergy];
  let rise = 0;
  for (let k = 1; k < energies.length; k++) rise = Math.max(rise, (energies[k] - energies[k - 1]) / energies[k - 1]);
  return rise;
}

export function compareAnalyses(a: AnalysisRecord, b: AnalysisRecord): AnalysisAgreement {
  let same = 0;
  for (let k = 0; k < b.cells.length; k++) {
    const x = a.cells[k],
      y = b.cells[k];
    if (x.id !== y.id) throw new Error(`cell records out of order at ${k}`);
    if (x.sides.join() === y.sides.join() && x.won === y.won && x.lost === y.lost && x.valid === y.valid) same++;
  }
  let polygonDistance = 0;
  a.summary.perSurface.forEach((surface, s) => {
    const other = b.summary.perSurface[s].polygonDistribution;
    const tv = surface.polygonDistribution.reduce((sum, p, k) => sum + Math.abs(p - (other[k] ?? 0)), 0) / 2;
    polygonDistance = Math.max(polygonDistance, tv);
  });
  return { percentScutoids: [a.summary.percentScutoids, b.summary.percentScutoids], cellsAgreeing: same / b.cells.length, polygonDistance };
}

function analysis(result: SheetResult, method: 'labels' | 'exact'): AnalysisRecord {
  const found = result.analyses.find((a) => a.method === method);
  if (!found) throw new Error(`the ${result.config.surface.kind} run on the ${result.engine.name} engine has no ${method} analysis`);
  return found;
}

/**
 * A tube of the published circumference (512 µm) and half its length, 100 cells ~100 µm
 * across as published, at 2 µm texels (256 x 1024), surface ratio 1.5, 10 Lloyd iterations.
 */
export function tubeConfig(seed: number, engine: 'gpu' | 'exact', centroidPath: CentroidPath | 'auto'): ConfigInput {
  return {
    surface: { kind: 'tube', radius: 512 / (2 * Math.PI), length: 2048 },
    cells: 100,
    seed,
    resolution: 1024,
    lloyd: { maxIterations: 10 },
    sheet: { surfaceRatio: 1.5, adjacency: 'both' },
    engine,
    centroidPath,
  } as ConfigInput;
}

/** A closed surface with 200 cells at n = 128 (texel edge ~0.7 µm), 5 Lloyd iterations, 10 µm thick. */
export function closedConfig(surface: ConfigInput['surface'], seed: number): ConfigInput {
  return { surface, cells: 200, seed, resolution: 128, lloyd: { maxIterations: 5 }, sheet: { thickness: 10, adjacency: 'both' } } as ConfigInput;
}

/** The tube on the GPU engine (centroid path `path`) against the exact engine, same seed. */
export async function tubeRuns(runner: SheetRunner, seed: number, path: CentroidPath | 'auto') {
  const gpu = (await runner.run(validateConfig(tubeConfig(seed, 'gpu', path)))).result;
  const exact = (await runner.run(validateConfig(tubeConfig(seed, 'exact', 'auto')))).result;
  if (gpu.engine.name !== 'gpu' || exact.engine.name !== 'exact') throw new Error('the tube runs did not take the engines asked for');
  return {
    path: gpu.engine.centroidPath,
    agreement: compareAnalyses(analysis(gpu, 'exact'), analysis(exact, 'exact')),
    energyRise: largestEnergyRise(gpu),
    exactEnergyRise: largestEnergyRise(exact),
    finalEnergyRatio: gpu.lloyd.finalEnergy / exact.lloyd.finalEnergy,
  };
}

/** A closed surface on the GPU engine: labels method against the exact method of the same sites. */
export async function closedRun(runner: SheetRunner, surface: ConfigInput['surface'], seed: number) {
  const result = (await runner.run(validateConfig(closedConfig(surface, seed)))).result;
  return {
    path: result.engine.centroidPath,
    agreement: compareAnalyses(analysis(result, 'labels'), analysis(result, 'exact')),
    energyRise: largestEnergyRise(result),
  };
}
