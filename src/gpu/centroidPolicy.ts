import type { SurfaceLayoutName } from '../core/config/surfaceLayout';
import { GpuCapabilityError, type GpuCapabilities } from './context';

/**
 * How centroids are summed: additive blending into float targets (needs EXT_float_blend), a
 * gather pass on the GPU, or the ids read back and reduced on the CPU in float64.
 */
export type CentroidPath = 'blend' | 'gather' | 'readback';
export type RequestedCentroidPath = CentroidPath | 'auto';

export interface CentroidPathChoice {
  readonly path: CentroidPath;
  /** One sentence: why this path (recorded in the result). */
  readonly reason: string;
}

/**
 * The one place the centroid path is decided, for both engines. "auto" picks:
 * - planar grid: readback on software rasterizers (SwiftShader, llvmpipe), where "GPU" memory is
 *   CPU memory and one pass over packed ids beats both a point per texel for the blend and
 *   per-site windows for the gather (docs/benchmark.md); else blend where EXT_float_blend
 *   exists, else gather;
 * - cube map: blend where EXT_float_blend exists, else readback (the cube map has no gather
 *   pass: a requested "gather" runs the readback).
 * A requested "blend" without EXT_float_blend is refused with what to do instead.
 */
export function chooseCentroidPath(family: SurfaceLayoutName, requested: RequestedCentroidPath, capabilities: GpuCapabilities): CentroidPathChoice {
  if (requested === 'blend' && !capabilities.floatBlend) {
    throw new GpuCapabilityError('centroidPath: "blend" needs EXT_float_blend, which this WebGL2 context lacks; use "auto" or "gather"');
  }
  if (family === 'cube map') {
    if (requested === 'blend') return { path: 'blend', reason: 'requested' };
    if (requested === 'auto' && capabilities.floatBlend) return { path: 'blend', reason: 'auto: EXT_float_blend is available' };
    if (requested === 'auto') return { path: 'readback', reason: 'auto: EXT_float_blend is missing, so the labels are read back and summed on the CPU' };
    return { path: 'readback', reason: requested === 'gather' ? 'requested "gather": the cube map sums by readback instead' : 'requested' };
  }
  if (requested !== 'auto') return { path: requested, reason: 'requested' };
  if (capabilities.softwareRenderer) return { path: 'readback', reason: 'auto: a software renderer, where reading the ids back is fastest' };
  if (capabilities.floatBlend) return { path: 'blend', reason: 'auto: a GPU with EXT_float_blend' };
  return { path: 'gather', reason: 'auto: a GPU without EXT_float_blend' };
}
