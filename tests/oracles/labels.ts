/**
 * CPU references (test oracles) for the GPU passes, from their definitions:
 *
 * - bruteForceLabels: exact nearest-site labels (what the jump flood approximates).
 * - reduceCentroids: the per-site sums the centroid pass accumulates, from a label image.
 * - centroidSites / cvtEnergy: what Lloyd does with those sums.
 * - sharedLength: one entry of a label adjacency.
 *
 * All positions are in texel units and all lengths/areas in µm (µm²), per src/core/grid.ts.
 */
import type { SurfaceAdjacency } from '../../src/core/analysis/adjacency';
import type { Grid } from '../../src/core/grid';
import type { LloydMove } from '../../src/core/lloydUpdate';

// The metric, written here from its definition (src/core/grid.ts has its own): offsets take the
// nearest periodic image, positions wrap into [0, L) on a periodic axis and clamp to [0, L] on
// an open one.
const nearestImage = (d: number, length: number, periodic: boolean) => (periodic ? d - length * Math.round(d / length) : d);
const placed = (v: number, length: number, periodic: boolean) => {
  if (!periodic) return Math.min(length, Math.max(0, v));
  const w = ((v % length) + length) % length;
  return w >= length ? 0 : w;
};
function distanceSquared(grid: Grid, ax: number, ay: number, bx: number, by: number): number {
  const dx = nearestImage(bx - ax, grid.width, grid.periodicX) * grid.texelX;
  const dy = nearestImage(by - ay, grid.height, grid.periodicY) * grid.texelY;
  return dx * dx + dy * dy;
}

// ---------------------------------------------------------------------------------------------
// Nearest-site labels
// ---------------------------------------------------------------------------------------------

/**
 * For every texel centre, the id of the nearest site by physical distance (minimum image on
 * periodic axes); ties go to the smaller id; -1 everywhere if there are no sites.
 *
 * Sites are sorted into a uniform grid of buckets (about 2 sites each, physically square), and
 * each texel searches rings of buckets outwards until no unvisited bucket can hold a closer
 * site: O(texels) for evenly spread sites. Sites must lie inside the domain.
 */
export function bruteForceLabels(grid: Grid, sites: Float32Array, out?: Int32Array): Int32Array {
  const { width, height, texelX, texelY, periodicX, periodicY } = grid;
  const labels = out ?? new Int32Array(width * height);
  if (labels.length !== width * height) throw new Error(`bruteForceLabels: out has ${labels.length} entries, the grid ${width * height}`);
  const count = Math.floor(sites.length / 2);
  if (count === 0) return labels.fill(-1);

  // Bucket grid, about two sites per bucket, buckets about square in µm.
  const lengthX = width * texelX;
  const lengthY = height * texelY;
  const side = Math.sqrt((2 * lengthX * lengthY) / count);
  const nx = Math.min(width, Math.max(1, Math.round(lengthX / side)));
  const ny = Math.min(height, Math.max(1, Math.round(lengthY / side)));
  const bucketW = width / nx;
  const bucketH = height / ny;
  const { start, ids } = bucketSites(sites, count, nx, ny, bucketW, bucketH, grid);

  // Ring offsets along each axis are limited so that, on a periodic axis, every bucket is
  // visited exactly once (offsets -floor((n-1)/2) .. floor(n/2)).
  const periodicLoX = -Math.floor((nx - 1) / 2);
  const periodicHiX = Math.floor(nx / 2);
  const periodicLoY = -Math.floor((ny - 1) / 2);
  const periodicHiY = Math.floor(ny / 2);
  const stepX = bucketW * texelX;
  const stepY = bucketH * texelY;

  for (let j = 0; j < height; j++) {
    const py = j + 0.5;
    const by = Math.min(ny - 1, Math.floor(py / bucketH));
    const loY = periodicY ? periodicLoY : -by;
    const hiY = periodicY ? periodicHiY : ny - 1 - by;
    const extentY = Math.max(-loY, hiY);
    for (let i = 0; i < width; i++) {
      const px = i + 0.5;
      const bx = Math.min(nx - 1, Math.floor(px / bucketW));
      const loX = periodicX ? periodicLoX : -bx;
      const hiX = periodicX ? periodicHiX : nx - 1 - bx;
      const extentX = Math.max(-loX, hiX);
      let best = Infinity;
      let bestId = -1;
      for (let r = 0; ; r++) {
        const dyLo = Math.max(-r, loY);
        const dyHi = Math.min(r, hiY);
        for (let dy = dyLo; dy <= dyHi; dy++) {
          const row = wrapBucket(by + dy, ny) * nx;
          const fullRow = dy === -r || dy === r;
          const dxLo = Math.max(-r, loX);
          const dxHi = Math.min(r, hiX);
          // On a ring's top and bottom rows, every column; in between, only its two ends.
          const dxStep = fullRow ? 1 : Math.max(1, 2 * r);
          for (let dx = fullRow ? dxLo : -r; dx <= dxHi; dx += dxStep) {
            if (dx < dxLo) continue;
            const bucket = row + wrapBucket(bx + dx, nx);
            for (let k = start[bucket]; k < start[bucket + 1]; k++) {
              const id = ids[k];
              const d = distanceSquared(grid, px, py, sites[2 * id], sites[2 * id + 1]);
              if (d < best || (d === best && id < bestId)) {
                best = d;
                bestId = id;
              }
            }
          }
        }
        // Every site outside the searched block is at least r bucket widths away along an axis
        // that still has unvisited buckets. Stop once the best is strictly closer than that.
        const boundX = r >= extentX ? Infinity : r * stepX;
        const boundY = r >= extentY ? Infinity : r * stepY;
        const bound = Math.min(boundX, boundY);
        if (bound === Infinity || best < bound * bound) break;
      }
      labels[j * width + i] = bestId;
    }
  }
  return labels;
}

function wrapBucket(k: number, n: number): number {
  return k < 0 ? k + n : k >= n ? k - n : k;
}

/** Counting sort of site ids by bucket: ids[start[b] .. start[b+1]) are in bucket b. */
function bucketSites(sites: Float32Array, count: number, nx: number, ny: number, bucketW: number, bucketH: number, grid: Grid) {
  const bucketOf = new Int32Array(count);
  const start = new Int32Array(nx * ny + 1);
  for (let id = 0; id < count; id++) {
    const x = placed(sites[2 * id], grid.width, grid.periodicX);
    const y = placed(sites[2 * id + 1], grid.height, grid.periodicY);
    const bx = Math.min(nx - 1, Math.max(0, Math.floor(x / bucketW)));
    const by = Math.min(ny - 1, Math.max(0, Math.floor(y / bucketH)));
    bucketOf[id] = by * nx + bx;
    start[bucketOf[id] + 1]++;
  }
  for (let b = 0; b < nx * ny; b++) start[b + 1] += start[b];
  const fill = start.slice(0, nx * ny);
  const ids = new Int32Array(count);
  for (let id = 0; id < count; id++) ids[fill[bucketOf[id]]++] = id;
  return { start, ids };
}

// ---------------------------------------------------------------------------------------------
// Centroids
// ---------------------------------------------------------------------------------------------

/**
 * Per site, 4 sums over the texels labelled with it: [Σ w·dx, Σ w·dy, Σ w, Σ w·d²], where
 * (dx, dy) is the minimum-image offset in texel units from the SITE to the texel centre and d²
 * the squared physical distance (µm²). This is exactly what the GPU centroid pass accumulates:
 * offsets relative to the site stay small and unwrap a cell that straddles a periodic seam.
 * `weight` (per texel, e.g. density) may be null for 1. Texels labelled -1 are skipped.
 */
export function reduceCentroids(grid: Grid, labels: ArrayLike<number>, sites: Float32Array, weight: Float32Array | null, out?: Float64Array): Float64Array {
  const { width, height } = grid;
  const count = Math.floor(sites.length / 2);
  const sums = out ?? new Float64Array(4 * count);
  if (sums.length < 4 * count) throw new Error(`reduceCentroids: out has ${sums.length} entries, ${4 * count} needed`);
  if (labels.length !== width * height) throw new Error(`reduceCentroids: ${labels.length} labels for ${width * height} texels`);
  if (weight && weight.length !== width * height) throw new Error(`reduceCentroids: ${weight.length} weights for ${width * height} texels`);
  sums.fill(0, 0, 4 * count);
  // From the definition, texel by texel (independent of the production run-length sums in
  // src/core/labels.ts accumulateCentroidRows, which it checks): the minimum-image offset from
  // the site to the texel centre, in texel units, and the squared physical distance.
  const { texelX, texelY, periodicX, periodicY } = grid;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const id = labels[j * width + i];
      if (id < 0) continue;
      if (id >= count) throw new Error(`reduceCentroids: label ${id} at texel (${i}, ${j}) but only ${count} sites`);
      const w = weight ? weight[j * width + i] : 1;
      let dx = i + 0.5 - sites[2 * id];
      let dy = j + 0.5 - sites[2 * id + 1];
      if (periodicX) dx -= width * Math.round(dx / width);
      if (periodicY) dy -= height * Math.round(dy / height);
      sums[4 * id] += w * dx;
      sums[4 * id + 1] += w * dy;
      sums[4 * id + 2] += w;
      sums[4 * id + 3] += w * ((dx * texelX) ** 2 + (dy * texelY) ** 2);
    }
  }
  return sums;
}

/**
 * The Lloyd move from those sums: each site goes to site + omega·(Σ w·d)/(Σ w), wrapped on
 * periodic axes and clamped on open ones; sites with an empty cell stay put. Returns new
 * positions (in `out` if given; `sites` is not modified) and the move's statistics: the oracle
 * of the update the GPU loop applies (moveSitesToCentroids, src/core/lloydUpdate.ts).
 */
export function centroidSites(
  grid: Grid,
  sites: Float32Array,
  sums: ArrayLike<number>,
  omega = 1,
  out?: Float32Array,
): { sites: Float32Array; move: LloydMove } {
  const next = out ?? new Float32Array(sites.length);
  if (next !== sites) next.set(sites);
  const { width, height, texelX, texelY, periodicX, periodicY } = grid;
  let energy = 0;
  let largest = 0;
  let largestTexels = 0;
  let emptyCells = 0;
  for (let i = 0; i < Math.floor(sites.length / 2); i++) {
    const w = sums[4 * i + 2];
    energy += sums[4 * i + 3];
    if (!(w > 0)) {
      emptyCells++;
      continue;
    }
    const x = sites[2 * i];
    const y = sites[2 * i + 1];
    next[2 * i] = placed(x + (omega * sums[4 * i]) / w, width, periodicX);
    next[2 * i + 1] = placed(y + (omega * sums[4 * i + 1]) / w, height, periodicY);
    // Measured from the stored (float32) position, the one the next iteration starts from.
    const dx = Math.abs(nearestImage(next[2 * i] - x, width, periodicX));
    const dy = Math.abs(nearestImage(next[2 * i + 1] - y, height, periodicY));
    largestTexels = Math.max(largestTexels, dx, dy);
    largest = Math.max(largest, Math.hypot(dx * texelX, dy * texelY));
  }
  const move: LloydMove = { energy: energy * texelX * texelY, maxDisplacement: largest, maxDisplacementTexels: largestTexels, emptyCells };
  return { sites: next, move };
}

/** CVT energy Σ w·d²·texelX·texelY over all texels (µm⁴ x weight), from the sums above. */
export function cvtEnergy(grid: Grid, sums: ArrayLike<number>): number {
  let energy = 0;
  for (let k = 3; k < sums.length; k += 4) energy += sums[k];
  return energy * grid.texelX * grid.texelY;
}

/** Shared boundary length (µm) between cells a and b, 0 if they are not neighbours. */
export function sharedLength(adjacency: Pick<SurfaceAdjacency, 'offsets' | 'neighbours' | 'lengths'>, a: number, b: number): number {
  let lo = adjacency.offsets[a];
  let hi = adjacency.offsets[a + 1] - 1;
  while (lo <= hi) {
    const mid = (lo + hi) >> 1;
    const id = adjacency.neighbours[mid];
    if (id === b) return adjacency.lengths[mid];
    if (id < b) lo = mid + 1;
    else hi = mid - 1;
  }
  return 0;
}
