import { checkFeasible, makeGrid, type Config } from '../core/config';
import { densityField, type GrayImage } from '../core/density';
import type { Grid } from '../core/grid';
import { placeSites } from '../core/sites';
import type { GpuContext } from '../gpu/context';
import { CcvtEngine, type CentroidPath } from '../gpu/engine';
import { LloydRun, type IterationRecord } from '../gpu/lloyd';

export interface RunCallbacks {
  /** Called after each Lloyd iteration. */
  onIteration?(record: IterationRecord, maxIterations: number): void;
  /** Aborting stops the run between iterations with an AbortError; nothing is half-written. */
  signal?: AbortSignal;
  /** A decoded grayscale image for `density.kind = "image"`. */
  densityImage?: GrayImage;
}

/** The converged seeded surface: what every other surface of the sheet is projected from. */
export interface SeededSurface {
  readonly grid: Grid;
  /** Final sites, interleaved x, y in texel units. */
  readonly sites: Float32Array;
  /** Label image of the final sites (site id per texel). */
  readonly labels: Int32Array;
  readonly centroidPath: CentroidPath;
  readonly iterations: IterationRecord[];
  readonly converged: boolean;
  readonly finalEnergy: number;
  readonly emptyCells: number;
  readonly setupMs: number;
  readonly lloydMs: number;
}

/**
 * Places the sites and runs Lloyd's method on the GPU on the seeded surface. Depends only on
 * the config's fields other than `sheet`, so sweeps over the sheet's geometry reuse it.
 */
export async function relaxSeededSurface(config: Config, context: GpuContext, callbacks: RunCallbacks = {}): Promise<SeededSurface> {
  const start = performance.now();
  const grid = makeGrid(config);
  checkFeasible(config, grid);
  const density = densityField(config.density, grid, callbacks.densityImage);
  const sites = placeSites(grid, config.cells, config.seed, config.minSpacing, placementDensity(config, density));
  const engine = new CcvtEngine(context, grid, config.cells, { variant: config.jumpFlood.variant, centroidPath: config.centroidPath });
  try {
    // Planar-family texels all cover the same area, so the weight is the density alone.
    engine.setWeights(density);
    const run = new LloydRun(engine, grid, sites, config.lloyd);
    const setupMs = performance.now() - start;
    while (!run.done) {
      throwIfAborted(callbacks.signal);
      const record = run.step();
      callbacks.onIteration?.(record, config.lloyd.maxIterations);
      await yieldToEventLoop();
    }
    // Label the final sites with a cold flood, as every other surface of the stack is labelled:
    // identical surfaces then get identical labels (no warm-start residue at s = 1).
    engine.floodLabels();
    const final = run.finish();
    return {
      grid,
      sites,
      labels: engine.readLabels(),
      centroidPath: engine.centroidPath,
      iterations: run.iterations,
      converged: run.converged,
      finalEnergy: final.energy,
      emptyCells: final.emptyCells,
      setupMs,
      lloydMs: performance.now() - start - setupMs,
    };
  } finally {
    engine.dispose();
  }
}

/**
 * Initial sites follow the point density a CVT converges to, rho^(d/(d+2)) = sqrt(rho) in 2D
 * (Gersho; Du et al.), not rho itself: Lloyd then has little mass to move across the sheet.
 */
function placementDensity(config: Config, density: Float32Array): Float32Array | undefined {
  if (config.density.kind === 'uniform') return undefined;
  return density.map(Math.sqrt);
}

export function throwIfAborted(signal: AbortSignal | undefined): void {
  if (signal?.aborted) throw new DOMException('The run was cancelled', 'AbortError');
}

export function yieldToEventLoop(): Promise<void> {
  return new Promise((resolve) => setTimeout(resolve, 0));
}
