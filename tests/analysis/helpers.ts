/** Test helpers: a small seeded PRNG, random sites with a minimum spacing, brute-force pixel Voronoi. */
import type { Grid } from '../../src/core/grid';
import { distanceSquared } from '../../src/core/grid';

/** mulberry32: deterministic uniform numbers in [0, 1). */
export function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

/** Uniform random sites (texel units) with a minimum physical spacing (dart throwing). */
export function randomSites(grid: Grid, count: number, seed: number, minSpacing = 0): Float32Array {
  const rng = mulberry32(seed);
  const sites = new Float32Array(2 * count);
  let placed = 0;
  let attempts = 0;
  const min2 = minSpacing * minSpacing;
  while (placed < count) {
    if (++attempts > 1_000_000) throw new Error('could not place sites');
    const x = rng() * grid.width;
    const y = rng() * grid.height;
    let ok = true;
    for (let k = 0; k < placed && ok; k++) {
      if (distanceSquared(grid, x, y, sites[2 * k], sites[2 * k + 1]) < min2) ok = false;
    }
    if (!ok) continue;
    sites[2 * placed] = x;
    sites[2 * placed + 1] = y;
    placed++;
  }
  return sites;
}

/** Brute-force nearest-site label of every texel centre (row-major), plus the squared gap to the runner-up. */
export function bruteForceLabels(grid: Grid, sites: Float32Array): { labels: Int32Array; gap: Float64Array } {
  const n = sites.length / 2;
  const labels = new Int32Array(grid.width * grid.height);
  const gap = new Float64Array(grid.width * grid.height);
  for (let j = 0; j < grid.height; j++) {
    for (let i = 0; i < grid.width; i++) {
      let best = -1;
      let d1 = Infinity;
      let d2 = Infinity;
      for (let s = 0; s < n; s++) {
        const d = distanceSquared(grid, i + 0.5, j + 0.5, sites[2 * s], sites[2 * s + 1]);
        if (d < d1) {
          d2 = d1;
          d1 = d;
          best = s;
        } else if (d < d2) d2 = d;
      }
      labels[j * grid.width + i] = best;
      gap[j * grid.width + i] = d2 - d1;
    }
  }
  return { labels, gap };
}
