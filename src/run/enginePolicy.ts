import type { AnyConfig } from '../core/config';
import { chooseCentroidPath, type CentroidPath, type SurfaceFamilyName } from '../gpu/centroidPolicy';
import type { GpuCapabilities } from '../gpu/context';

/** Which engine runs Lloyd and labels the surfaces of a run, and why (recorded in the result). */
export interface EngineChoice {
  /** "gpu": jump flood and centroid passes in WebGL2 render targets. */
  readonly name: 'gpu';
  readonly family: SurfaceFamilyName;
  readonly centroidPath: CentroidPath;
  /** One line: why this engine and this centroid path. */
  readonly reason: string;
}

/**
 * The engine policy: the one place a run's engine and centroid path are chosen. Today every
 * surface family runs on the GPU engine of its layout (planar grid or cube map); an engine of
 * another kind (an exact CPU engine for planes and tubes) is one more branch here and one more
 * `relax` in the family, not another pipeline.
 */
export function chooseEngine(config: AnyConfig, family: SurfaceFamilyName, capabilities: GpuCapabilities): EngineChoice {
  const path = chooseCentroidPath(family, config.centroidPath, capabilities);
  return {
    name: 'gpu',
    family,
    centroidPath: path.path,
    reason: `the ${family} GPU engine, the only engine for this surface; centroid path ${path.path} (${path.reason})`,
  };
}
