import { SIDE_CLASSES } from '../core/analysis';
import { isClosedConfig, type AnyConfig, type Config } from '../core/config';
import type { GpuContext } from '../gpu/context';
import type { SheetResult } from './result';
import { runSheet, type RunCallbacks } from './runSheet';
import { relaxSeededSurface, type SeededSurface } from './seededSurface';

/**
 * Runs sheets one after another and reuses the converged seeded surface when only `sheet.*`
 * changed (a sweep over surface ratios or thickness relaxes each realization once).
 */
export class SheetRunner {
  private cached: { key: string; seeded: Promise<SeededSurface> } | null = null;

  constructor(private readonly context: GpuContext) {}

  async run(config: AnyConfig, callbacks: RunCallbacks = {}) {
    // Closed surfaces have their own pipeline (no reuse yet): run them whole.
    if (isClosedConfig(config)) return runSheet(config, this.context, callbacks);
    const key = seededKey(config);
    if (this.cached?.key !== key) {
      this.cached = { key, seeded: relaxSeededSurface(config, this.context, callbacks) };
    }
    let seeded: SeededSurface;
    try {
      seeded = await this.cached.seeded;
    } catch (error) {
      this.cached = null;
      throw error;
    }
    return runSheet(config, this.context, { ...callbacks, seeded });
  }
}

/** Everything the seeded surface depends on: the config without its `sheet` section. */
export function seededKey(config: AnyConfig): string {
  const { sheet: _sheet, ...rest } = config;
  return JSON.stringify(rest);
}

/** The numbers a sweep writes per run (flattened into CSV columns). */
export function sweepSummary(result: SheetResult): Record<string, unknown> {
  const summary: Record<string, unknown> = {
    iterations: result.lloyd.iterations.length,
    finalEnergy: result.lloyd.finalEnergy,
    centroidPath: result.gpu.centroidPath,
  };
  for (const analysis of result.analyses) {
    const s = analysis.summary;
    const perSurface: Record<string, unknown> = {};
    s.perSurface.forEach((surface, k) => {
      const name = (surface.label ?? `surface${k}`).replace(/\s+/g, '');
      const polygons: Record<string, number> = {};
      SIDE_CLASSES.forEach((sides, c) => (polygons[sides] = surface.polygonDistribution[c]));
      perSurface[name] = { meanSides: surface.meanSides, polygons };
    });
    summary[analysis.method] = {
      percentScutoids: s.percentScutoids,
      meanTransitions: s.meanTransitions,
      meanNeighbours3D: s.meanNeighbours3D,
      validCells: s.validCells,
      excludedCells: s.excludedCells,
      ...perSurface,
    };
  }
  return summary;
}
