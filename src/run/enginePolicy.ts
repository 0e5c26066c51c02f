import { engineNameFor, type Config } from '../core/config';
import { LAYOUTS, type SurfaceLayoutName } from '../core/config/surfaceLayout';
import { chooseCentroidPath, type CentroidPath } from '../gpu/centroidPolicy';
import type { GpuCapabilities } from '../gpu/context';

/** Which engine runs Lloyd and finds the neighbours of a run, and why (recorded in the result). */
export type EngineChoice = GpuEngineChoice | ExactEngineChoice;

/** Jump flood and centroid passes in WebGL2 render targets. */
interface GpuEngineChoice {
  readonly name: 'gpu';
  readonly family: SurfaceLayoutName;
  /** How the GPU sums centroids. */
  readonly centroidPath: CentroidPath;
  /** One line: why this engine and centroid path. */
  readonly reason: string;
}

/** Lloyd on the exact Voronoi diagram on the CPU (planes and tubes): every analysis exact, no label textures. */
interface ExactEngineChoice {
  readonly name: 'exact';
  readonly family: SurfaceLayoutName;
  readonly centroidPath: null;
  readonly reason: string;
}

/**
 * The engine policy: the one place a run's engine and centroid path are chosen. Which engine
 * is core/config/analysisMethods.ts's engineNameFor (the sweep's columns read the same rule):
 * - Closed surfaces: the cube-map GPU engine (the only one).
 * - Planes and tubes: `engine: "exact"` or `"gpu"` as asked; `"auto"` takes the exact engine on a
 *   software renderer (there the "GPU" is the CPU, and the exact computation costs a fraction of
 *   a jump flood), unless the labels method is asked for, and the GPU engine otherwise.
 */
export function chooseEngine(config: Config, family: SurfaceLayoutName, capabilities: GpuCapabilities): EngineChoice {
  if (engineNameFor(config, capabilities) === 'exact') {
    return exact(
      family,
      config.engine === 'exact'
        ? 'requested (engine "exact")'
        : `auto: the renderer is software (${capabilities.renderer}), where the exact CPU engine is faster than a jump flood and exact`,
    );
  }
  const path = chooseCentroidPath(family, config.centroidPath, capabilities);
  const why = !LAYOUTS[family].exactEngine
    ? `the GPU engine on the ${family}, the only engine for a ${config.surface.kind}`
    : config.engine === 'gpu'
      ? 'requested (engine "gpu")'
      : config.sheet.adjacency === 'labels'
        ? 'auto: the labels method needs label textures'
        : 'auto: a hardware GPU';
  return { name: 'gpu', family, centroidPath: path.path, reason: `${why}; centroid path ${path.path} (${path.reason})` };
}

function exact(family: SurfaceLayoutName, reason: string): ExactEngineChoice {
  return { name: 'exact', family, centroidPath: null, reason };
}

/** The engine in a few words, for logs and the page: "exact engine" or "GPU, centroid path readback". */
export function describeEngine(engine: EngineChoice): string {
  return engine.name === 'exact' ? 'exact engine' : `GPU, centroid path ${engine.centroidPath}`;
}
