import { byConstruction, runHeadline } from '../core/analysis';
import { validateConfig, type Config, type ClosedConfig, type PlanarConfig } from '../core/config';
import { checkScale } from '../core/config/limits';
import { surfaceLayout } from '../core/config/surfaceLayout';
import type { GpuContext } from '../gpu/context';
import { version } from '../version';
import { cubeMapFamily } from './cubeMapFamily';
import { chooseEngine } from './enginePolicy';
import type { IterationRecord } from '../gpu/lloyd';
import type { EngineChoice } from './enginePolicy';
import type { Relaxation, RunOptions, StackLayer, SurfaceFamily } from './family';
import { planarFamily } from './planarFamily';
import { relaxSeededSurface, throwIfAborted, yieldToEventLoop, type SeededSurface } from './relax';
import type { SheetOutput } from './result';
import { SeededCache } from './seededCache';
import { analyzeStack } from './stack';

export type { RunInputs, RunOptions } from './family';

/**
 * The whole computation of one sheet, for every surface: validated config -> surface family
 * (planar grid for planes and tubes, cube map for closed surfaces) -> engine policy -> seeded
 * surface and Lloyd -> projection onto layers and the other surface -> labels -> adjacency ->
 * statistics -> the documented result. Same config, same result.
 */
export async function runSheet(config: Config, context: GpuContext, options: RunOptions = {}): Promise<SheetOutput> {
  // A library caller's config, checked here as the CLI and the page check theirs: validated again
  // (an object changed since it was validated, `maxIterations = 1e9`, a radius of NaN, is refused
  // naming the field) and held to the scale guards and this GPU's texture size (a sphere at
  // resolution 16384 failed deep inside with "Invalid typed array length"). The work and memory
  // budget stays the caller's: a library may run what a page may not.
  const checked = validateConfig(config);
  checkScale(checked, context.capabilities.maxTextureSize);
  return new SheetRunner(context).run(checked, options);
}

/**
 * Runs sheets one after another and reuses what the previous runs computed, wherever the result
 * is the same as computing the run alone:
 * - the converged seeded surface when only `sheet.*` changed (a sweep over surface ratios or
 *   thickness relaxes each realization once; the layers and lab validity computed from its sites
 *   are kept with them, see planarFamily's memo);
 * - on the exact engine, the Lloyd run itself when only `lloyd.maxIterations` grows: Voronoi k is
 *   the sites after k − 1 iterations, so one run serves every k on its way (the sites are copied
 *   at each k; continuing a paused ExactLloydRun gives bit for bit the iterations a fresh run with
 *   the larger maxIterations does, tested in tests/cli/sweepReuse.test.ts). A run asking for fewer
 *   iterations than the kept run has done starts a new one.
 */
export class SheetRunner {
  private readonly seededSurfaces: SeededCache;
  private chain: { key: string; lloyd: Promise<LloydChain<unknown, unknown>> } | null = null;

  /** `keepSeeded`: how many seeded surfaces are kept (default 1; see SeededCache). */
  constructor(
    private readonly context: GpuContext,
    options: { keepSeeded?: number } = {},
  ) {
    this.seededSurfaces = new SeededCache(options.keepSeeded ?? 1);
  }

  /** The one place a run's surface family is chosen: the family of the config's layout (core/config/surfaceLayout.ts). */
  run(config: Config, options: RunOptions = {}): Promise<SheetOutput> {
    return surfaceLayout(config).name === 'cube map'
      ? this.runOn(cubeMapFamily, config as ClosedConfig, options)
      : this.runOn(planarFamily, config as PlanarConfig, options);
  }

  private async runOn<C extends Config, G, S, L extends StackLayer, P>(
    family: SurfaceFamily<C, G, S, L, P>,
    config: C,
    callbacks: RunOptions,
  ): Promise<SheetOutput> {
    const start = performance.now();
    // The engine may depend on sheet.* (auto takes the GPU where labels are asked for): a seeded
    // surface is reused only by runs on the same engine.
    const engine = chooseEngine(config, family.name, this.context.capabilities);
    const key = `${engine.name}/${engine.centroidPath}/${seededKey(config)}`;
    const kept = this.seededSurfaces.get(key, () =>
      engine.name === 'exact' ? this.fromChain(family, config, engine, callbacks) : relaxSeededSurface(family, config, this.context, engine, callbacks),
    );
    let seeded: SeededSurface<G, S>;
    try {
      // The key holds the surface, so a cached seeded surface is of this family.
      seeded = (await kept) as SeededSurface<G, S>;
    } catch (error) {
      this.seededSurfaces.drop(key, kept);
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
        // Read from the stack on first use (see analyzeStack), in its place in the result's order.
        get cells() {
          return stack.seededCells;
        },
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

  /**
   * The exact engine's seeded surface after `config.lloyd.maxIterations` iterations, from the kept
   * Lloyd run when it is the same run (same config but for `sheet` and `lloyd.maxIterations`) and
   * has not gone past that many iterations; else from a new one.
   */
  private async fromChain<C extends Config, G, S, L extends StackLayer, P>(
    family: SurfaceFamily<C, G, S, L, P>,
    config: C,
    engine: EngineChoice,
    callbacks: RunOptions,
  ): Promise<SeededSurface<G, S>> {
    const key = `${engine.name}/${chainKey(config)}`;
    const target = config.lloyd.maxIterations;
    if (this.chain?.key === key) {
      const kept = this.chain.lloyd;
      try {
        const chain = (await kept) as LloydChain<G, S>;
        if (chain.iterations.length <= target) return await chain.advance(target, callbacks);
      } catch {
        // A failed or cancelled chain is not reused.
      }
      if (this.chain?.lloyd === kept) this.chain = null;
    }
    const lloyd = LloydChain.start(family, config, this.context, engine, callbacks);
    this.chain = { key, lloyd: lloyd as Promise<LloydChain<unknown, unknown>> };
    try {
      return await (await lloyd).advance(target, callbacks);
    } catch (error) {
      if (this.chain?.lloyd === lloyd) this.chain = null;
      throw error;
    }
  }
}

/**
 * One Lloyd run on the exact engine, advanced on demand: `advance(m)` steps it to m iterations
 * (or until it converges, as a fresh run with maxIterations m would stop) and returns the seeded
 * surface a fresh run with maxIterations m gives: a copy of the sites, the iteration records so
 * far, and the final energy from `finish()`, which only reads the sites (the next step rebuilds
 * the diagram from them).
 */
class LloydChain<G, S> {
  private busy: Promise<unknown> = Promise.resolve();

  private constructor(
    private readonly geometry: G,
    private readonly sites: S,
    private readonly relaxation: Relaxation,
    private readonly engine: EngineChoice,
    private readonly setupMs: number,
    private lloydMs: number,
  ) {}

  get iterations(): readonly IterationRecord[] {
    return this.relaxation.iterations;
  }

  static async start<C extends Config, G, S, L extends StackLayer, P>(
    family: SurfaceFamily<C, G, S, L, P>,
    config: C,
    context: GpuContext,
    engine: EngineChoice,
    callbacks: RunOptions,
  ): Promise<LloydChain<G, S>> {
    const start = performance.now();
    const geometry = await family.prepare(config, callbacks);
    family.checkSheet(config, geometry);
    // No iteration limit: advance() decides how far it goes. Tolerance, over-relaxation and the
    // rest are the config's, so every step is the step a fresh run takes.
    const open = { ...config, lloyd: { ...config.lloyd, maxIterations: Number.MAX_SAFE_INTEGER } };
    const { sites, relaxation } = family.relax(context, open, geometry, engine);
    if (!(sites instanceof Float32Array)) {
      relaxation.dispose();
      throw new Error('LloydChain: the exact engine keeps its sites in a Float32Array');
    }
    return new LloydChain(geometry, sites, relaxation, engine, performance.now() - start, 0);
  }

  /** Serialized: two runs of one SheetRunner never step the same Lloyd run at once. */
  advance(target: number, callbacks: RunOptions): Promise<SeededSurface<G, S>> {
    const next = this.busy.then(() => this.advanceNow(target, callbacks));
    this.busy = next.catch(() => {});
    return next;
  }

  private async advanceNow(target: number, callbacks: RunOptions): Promise<SeededSurface<G, S>> {
    const { relaxation } = this;
    if (relaxation.iterations.length > target) throw new Error(`LloydChain: already past ${target} iterations`);
    const start = performance.now();
    while (relaxation.iterations.length < target && !relaxation.converged) {
      throwIfAborted(callbacks.signal);
      const record = relaxation.step();
      callbacks.onIteration?.(record, target);
      await yieldToEventLoop();
    }
    const final = relaxation.finish();
    this.lloydMs += performance.now() - start;
    return {
      geometry: this.geometry,
      sites: (this.sites as unknown as Float32Array).slice() as unknown as S,
      labels: final.labels,
      engine: this.engine,
      iterations: relaxation.iterations.slice(),
      converged: relaxation.converged,
      finalEnergy: final.energy,
      emptyCells: final.emptyCells,
      setupMs: this.setupMs,
      lloydMs: this.lloydMs,
    };
  }
}

/** What a Lloyd run depends on: the config without its `sheet` section and `lloyd.maxIterations`. */
export function chainKey(config: Config): string {
  const { sheet: _sheet, lloyd, ...rest } = config;
  const { maxIterations: _max, ...lloydRest } = lloyd;
  return JSON.stringify({ ...rest, lloyd: lloydRest });
}

/** Everything the seeded surface depends on: the config without its `sheet` section. */
export function seededKey(config: Config): string {
  const { sheet: _sheet, ...rest } = config;
  return JSON.stringify(rest);
}
