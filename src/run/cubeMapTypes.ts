/** The cube-map family's data: its prepared surface, its stack's layers and projected sites. */
import type { CubeSurfaceSample } from '../core/closed/geometry';
import type { ClosedSurface } from './closedSurface';
import type { StackLayer } from './family';

/** A closed surface on its cube map, with the texel neighbour table every surface of its stack shares. */
export interface CubeMapGeometry extends ClosedSurface {
  /** Four edge-neighbour texels per texel, across face edges. */
  readonly neighbours: Int32Array;
}

/** A surface of a closed sheet's stack, sampled on the seeded surface's cube map. */
export interface CubeMapLayer extends StackLayer {
  readonly sample: CubeSurfaceSample;
  /**
   * `sheet.offset = "axes"`: this layer is the ellipsoid with these semi-axes (a + t, b + t,
   * c + t) and sites move to their closest points on it; absent: the parallel surface.
   */
  readonly axes?: readonly [number, number, number];
}

/** Sites moved onto a layer: their 3D positions, and the texels they were seeded in. */
export interface CubeMapProjected {
  readonly positions: Float64Array;
  readonly texels: Int32Array;
}
