import { type Grid, wrapCoordinate, wrapDelta } from './grid';

/** What one Lloyd move did. */
export interface LloydMove {
  /** CVT energy of the sites before the move: sum over texels of w * d² * texel area (µm⁴ x density). */
  energy: number;
  /** Largest distance a site moved, in µm. */
  maxDisplacement: number;
  /** Largest distance a site moved along either axis, in texels (bounds a warm-start flood). */
  maxDisplacementTexels: number;
  /** Sites whose cell holds no texel (they stay put): a sign the grid is too coarse. */
  emptyCells: number;
}

/**
 * Moves every site to (site + omega * centroid offset), given the per-site sums
 * [w*dx, w*dy, ..., w, w*d²] (`stride` values a site: 4 from the exact engine, 5 from the GPU
 * engine, whose third is w*dz) that the centroid pass computes (offsets from the site, texel
 * units; d² in µm²). omega = 1 is plain Lloyd; 1 < omega < 2 is over-relaxation. Periodic axes wrap,
 * open axes clamp (a centroid of a convex cell is inside the domain; over-relaxation may not be).
 * Writes into `sites` in place and allocates nothing.
 */
export function moveSitesToCentroids(
  grid: Grid,
  sites: Float32Array,
  sums: ArrayLike<number>,
  count: number,
  omega: number,
  move: LloydMove,
  stride = 4,
): LloydMove {
  let energy = 0;
  let maxDisplacementSquared = 0;
  let maxTexels = 0;
  let emptyCells = 0;
  for (let i = 0; i < count; i++) {
    const weight = sums[stride * i + stride - 2];
    energy += sums[stride * i + stride - 1];
    if (!(weight > 0)) {
      emptyCells++;
      continue;
    }
    const x = sites[2 * i];
    const y = sites[2 * i + 1];
    const nextX = wrapCoordinate(x + (omega * sums[stride * i]) / weight, grid.width, grid.periodicX);
    const nextY = wrapCoordinate(y + (omega * sums[stride * i + 1]) / weight, grid.height, grid.periodicY);
    sites[2 * i] = nextX;
    sites[2 * i + 1] = nextY;
    // The stored float32 value is what the GPU sees next; measure the move from it.
    const dx = Math.abs(wrapDelta(sites[2 * i] - x, grid.width, grid.periodicX));
    const dy = Math.abs(wrapDelta(sites[2 * i + 1] - y, grid.height, grid.periodicY));
    maxTexels = Math.max(maxTexels, dx, dy);
    const squared = (dx * grid.texelX) ** 2 + (dy * grid.texelY) ** 2;
    if (squared > maxDisplacementSquared) maxDisplacementSquared = squared;
  }
  move.energy = energy * grid.texelX * grid.texelY;
  move.maxDisplacement = Math.sqrt(maxDisplacementSquared);
  move.maxDisplacementTexels = maxTexels;
  move.emptyCells = emptyCells;
  return move;
}
