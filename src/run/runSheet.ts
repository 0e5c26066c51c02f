import { byConstruction, runHeadline } from '../core/analysis';
import { isClosedConfig, type AnyConfig } from '../core/config';
import type { GpuContext } from '../gpu/context';
import { version } from '../version';
import { cubeMapFamily } from './cubeMapFamily';
import { chooseEngine } from './enginePolicy';
import type { RunCallbacks, StackLayer, SurfaceFamily } from './family';
import { planarFamily } from './planarFamily';
import { relaxSeededSurface, type SeededSurface } from './relax';
import type { SheetOutput } from './result';
import { analyzeStack } from './stack';

export type { RunCallbacks } from './family';

/**
 * The whole computation of one sheet, for every surface: validated config -> surface family
 * (planar grid for planes and tubes, cube map for closed surfaces) -> engine policy -> seeded
 * surface and Lloyd -> projection onto layers and the other surface -> labels -> adjacency ->
 * statistics -> the documented result. Same config, same result.
 */
export function runSheet(config: AnyConfig, context: GpuContext, callbacks: RunCallbacks = {}): Promise<SheetOutput> {
  return new SheetRunner(context).run(config, callbacks);
}

/**
 * Runs sheets one after another and reuses the converged seeded surface when only `sheet.*`
 * changed (a sweep over surface ratios or thickness relaxes each realization once).
 */
export class SheetRunner {
  private cached: { key: string; seeded: Promise<SeededSurface<unknown, unknown>> } | null = null;

  constructor(private readonly context: GpuContext) {}

  /** The one place a run's surface family is decided. */
  run(config: AnyConfig, callbacks: RunCallbacks = {}): Promise<SheetOutput> {
    return isClosedConfig(config) ? this.runOn(cubeMapFamily, config, callbacks) : this.runOn(planarFamily, config, callbacks);
  }

  private async runOn<C extends AnyConfig, G, S, L extends StackLayer, P>(
    family: SurfaceFamily<C, G, S, L, P>,
    config: C,
    callbacks: RunCallbacks,
  ): Promise<SheetOutput> {
    const start = performance.now();
    // The engine may depend on sheet.* (auto takes the GPU where labels are asked for): a seeded
    // surface is reused only by runs on the same engine.
    const engine = chooseEngine(config, family.name, this.context.capabilities);
    const key = `${engine.name}/${engine.centroidPath}/${seededKey(config)}`;
    if (this.cached?.key !== key) {
      this.cached = { key, seeded: relaxSeededSurface(family, config, this.context, engine, callbacks) };
    }
    let seeded: SeededSurface<G, S>;
    try {
      // The key holds the surface, so a cached seeded surface is of this family.
      seeded = (await this.cached.seeded) as SeededSurface<G, S>;
    } catch (error) {
      this.cached = null;
      throw error;
    }
    const stack = await analyzeStack(family, config, seeded, this.context, callbacks.signal, callbacks.cellTables === true);
    const { closed, labelImages, tables } = stack;
    return {
      result: {
        software: { name: 'tissue-sheet', version },
        config,
        seed: config.seed,
        grid: family.gridRecord(seeded.geometry),
        gpu:
          seeded.engine.name === 'gpu'
            ? { renderer: this.context.capabilities.renderer, centroidPath: seeded.engine.centroidPath, jumpFloodVariant: config.jumpFlood.variant }
            : null,
        engine: { ...seeded.engine },
        lloyd: {
          iterations: seeded.iterations,
          converged: seeded.converged,
          finalEnergy: seeded.finalEnergy,
          emptyCells: seeded.emptyCells,
        },
        adjacency: { method: seeded.engine.name === 'exact' ? 'exact' : 'labels' },
        timings: { setupMs: seeded.setupMs, lloydMs: seeded.lloydMs, adjacencyMs: stack.adjacencyMs, totalMs: performance.now() - start },
        cells: stack.seededCells,
        surfaces: stack.surfaces,
        analyses: stack.analyses,
        headline: runHeadline(config, stack.analyses, seeded.iterations.length),
        byConstruction: byConstruction(config),
        ...(closed ? { closed } : {}),
      },
      labelImages,
      ...(tables ? { tables } : {}),
    };
  }
}

/** Everything the seeded surface depends on: the config without its `sheet` section. */
export function seededKey(config: AnyConfig): string {
  const { sheet: _sheet, ...rest } = config;
  return JSON.stringify(rest);
}
