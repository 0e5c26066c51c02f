/**
 * The grid a planar-family surface (plane, tube) is sampled on: its geometry image.
 *
 * Conventions used everywhere (CPU and GPU):
 * - Positions are in texel units in the unrolled domain: x in [0, width), y in [0, height).
 * - Texel (i, j) covers [i, i+1) x [j, j+1); its centre is (i + 0.5, j + 0.5).
 * - Row-major storage: texel (i, j) is at index j * width + i.
 * - A label texture holds, per texel, the id (0..n-1) of its nearest site, or -1.
 * - Physical distance between two points is sqrt((dx * texelX)^2 + (dy * texelY)^2), where
 *   dx, dy are minimum-image differences along periodic axes (a tube is intrinsically flat,
 *   so this is the true geodesic distance on the cylinder).
 */
export interface Grid {
  /** Texels along x (around a tube). */
  readonly width: number;
  /** Texels along y (along a tube's axis). */
  readonly height: number;
  /** Micrometres per texel along x. */
  readonly texelX: number;
  /** Micrometres per texel along y. */
  readonly texelY: number;
  readonly periodicX: boolean;
  readonly periodicY: boolean;
}

/** Minimum-image difference b - a along an axis of the given length. */
export function wrapDelta(delta: number, length: number, periodic: boolean): number {
  if (!periodic) return delta;
  const half = length / 2;
  if (delta > half) return delta - length;
  if (delta < -half) return delta + length;
  return delta;
}

/** Squared physical distance (µm²) between two points given in texel units. */
export function distanceSquared(grid: Grid, ax: number, ay: number, bx: number, by: number): number {
  const dx = wrapDelta(bx - ax, grid.width, grid.periodicX) * grid.texelX;
  const dy = wrapDelta(by - ay, grid.height, grid.periodicY) * grid.texelY;
  return dx * dx + dy * dy;
}

/** Brings a coordinate back into [0, length) on a periodic axis, or clamps it into [0, length]. */
export function wrapCoordinate(value: number, length: number, periodic: boolean): number {
  if (periodic) {
    const wrapped = value - Math.floor(value / length) * length;
    return wrapped >= length ? 0 : wrapped;
  }
  return Math.min(Math.max(value, 0), length);
}
