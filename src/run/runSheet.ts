import { isClosedConfig, type AnyConfig } from '../core/config';
import type { GpuContext } from '../gpu/context';
import { version } from '../version';
import type { SheetOutput } from './result';
import { relaxSeededSurface, type RunCallbacks, type SeededSurface } from './seededSurface';
import { analyzeStack } from './sheetStack';
import { runClosedSheet, type ClosedRunCallbacks } from './closedSheet';

export type { RunCallbacks } from './seededSurface';

/**
 * The whole computation of one sheet: validated config -> grid -> density -> sites -> Lloyd on
 * the GPU (seeded surface) -> projection onto layers and the other surface -> labels ->
 * adjacency -> statistics -> the documented result. Same config, same result.
 */
export async function runSheet(
  config: AnyConfig,
  context: GpuContext,
  callbacks: RunCallbacks & { seeded?: SeededSurface } & Pick<ClosedRunCallbacks, 'meshFile'> = {},
): Promise<SheetOutput> {
  // Closed surfaces (sphere, ellipsoid, mesh) run on a cube-map geometry image: src/run/closedSheet.ts.
  // A static import (not import()): the library build stays one self-contained module.
  if (isClosedConfig(config)) return runClosedSheet(config, context, callbacks);
  const start = performance.now();
  // A seeded surface relaxed earlier for the same config (see SheetRunner) is reused as is.
  const seeded = callbacks.seeded ?? (await relaxSeededSurface(config, context, callbacks));
  const stack = await analyzeStack(config, seeded, context, callbacks.signal);
  return {
    result: {
      software: { name: 'tissue-sheet', version },
      config,
      seed: config.seed,
      grid: { ...seeded.grid },
      gpu: {
        renderer: context.capabilities.renderer,
        centroidPath: seeded.centroidPath,
        jumpFloodVariant: config.jumpFlood.variant,
      },
      lloyd: {
        iterations: seeded.iterations,
        converged: seeded.converged,
        finalEnergy: seeded.finalEnergy,
        emptyCells: seeded.emptyCells,
      },
      adjacency: { method: 'labels' },
      timings: {
        setupMs: seeded.setupMs,
        lloydMs: seeded.lloydMs,
        adjacencyMs: stack.adjacencyMs,
        totalMs: performance.now() - start,
      },
      cells: stack.seededCells,
      surfaces: stack.surfaces,
      analyses: stack.analyses,
    },
    labelImages: stack.labelImages,
  };
}
