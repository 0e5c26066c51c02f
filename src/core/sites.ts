/**
 * Initial site placement: random positions ("Voronoi 1" in the lab's terms), optionally
 * following a density field and keeping a minimum physical distance between sites.
 *
 * - Positions are continuous (not snapped to texel centres), in texel units, interleaved x, y.
 * - With a density field, candidates are accepted with probability density / max(density)
 *   (rejection sampling), so the expected number of sites per area is proportional to density.
 *   The density of a candidate is that of the texel containing it.
 * - With a minimum spacing, a candidate closer than it to any placed site (physical distance,
 *   minimum image across periodic seams) is rejected: dart throwing, which is how the lab
 *   seeded its tubes (5 px apart). A spatial hash with buckets at least one spacing wide makes
 *   each check look at 3 x 3 buckets only, so placement is O(n), not O(n²).
 * - The same (grid, count, seed, spacing, density) always gives the same sites.
 */
import type { Grid } from './grid';
import { distanceSquared } from './grid';
import { Random } from './random';
import { ConfigError } from './config/configError';

/** Candidates that may fail in a row (per unit of max/mean density) before we give up. */
const MAX_CONSECUTIVE_FAILURES = 20000;

/** Coverage at which random sequential adsorption of disks jams (Feder 1980; Hinrichsen et al.). */
export const RSA_JAMMING_COVERAGE = 0.547;

export function placeSites(grid: Grid, count: number, seed: number, minSpacingUm: number, density?: Float32Array): Float32Array {
  const { width, height } = grid;
  if (!(Number.isInteger(count) && count >= 0)) throw new Error(`placeSites: count must be an integer >= 0 (got ${count})`);
  if (!(minSpacingUm >= 0 && Number.isFinite(minSpacingUm))) {
    throw new Error(`placeSites: minSpacing must be a finite number >= 0 µm (got ${minSpacingUm})`);
  }
  const acceptance = density ? acceptanceScale(density, width * height) : null;

  const sites = new Float32Array(2 * count);
  const random = new Random(seed);
  const spacing2 = minSpacingUm * minSpacingUm;
  const hash = minSpacingUm > 0 ? new SpatialHash(grid, count, minSpacingUm) : null;
  // A density with a sharp peak rejects most candidates for a reason other than spacing; give it
  // proportionally more tries (capped, so the loop stays bounded).
  const maxFailures = MAX_CONSECUTIVE_FAILURES * Math.min(1000, Math.ceil(acceptance?.maxOverMean ?? 1));

  let placed = 0;
  let failures = 0;
  while (placed < count) {
    // Store-then-check: the float32 position is what everyone downstream sees.
    let x = Math.fround(random.next() * width);
    let y = Math.fround(random.next() * height);
    // Rounding to float32 can reach the far edge; on a periodic axis that is the near edge.
    if (x >= width && grid.periodicX) x = 0;
    if (y >= height && grid.periodicY) y = 0;
    let ok = true;
    if (acceptance) {
      const i = Math.min(width - 1, Math.floor(x));
      const j = Math.min(height - 1, Math.floor(y));
      // Always draw, so the sequence does not depend on which test failed first.
      ok = random.next() * acceptance.max < density![j * width + i];
    }
    if (ok && hash) ok = !hash.anyWithin(sites, x, y, spacing2);
    if (!ok) {
      if (++failures > maxFailures) throw placementError(grid, count, placed, minSpacingUm, maxFailures);
      continue;
    }
    failures = 0;
    sites[2 * placed] = x;
    sites[2 * placed + 1] = y;
    hash?.insert(placed, x, y);
    placed++;
  }
  return sites;
}

function acceptanceScale(density: Float32Array, texels: number): { max: number; maxOverMean: number } {
  if (density.length !== texels) {
    throw new Error(`placeSites: density has ${density.length} values but the grid has ${texels} texels; compute it with densityField for this grid`);
  }
  let max = 0;
  let sum = 0;
  for (let k = 0; k < density.length; k++) {
    const v = density[k];
    if (!(v > 0 && Number.isFinite(v))) throw new Error(`placeSites: density ${v} at texel ${k} is not positive and finite`);
    if (v > max) max = v;
    sum += v;
  }
  return { max, maxOverMean: max / (sum / density.length) };
}

/** A placement that jammed: the config's fault (exit 2, naming minSpacing or density), not the code's. */
function placementError(grid: Grid, count: number, placed: number, spacing: number, failures: number): ConfigError {
  const area = grid.width * grid.texelX * grid.height * grid.texelY;
  const jam = Math.sqrt((4 * RSA_JAMMING_COVERAGE * area) / (Math.PI * count));
  const why = spacing > 0 ? ` at least ${spacing} µm apart` : '';
  const hint =
    spacing > 0
      ? `lower minSpacing (random placement of ${count} sites on ${round(area)} µm² jams near ${round(jam)} µm; stay well below) or lower cells`
      : 'make the density field less peaked';
  const field = spacing > 0 ? 'minSpacing' : 'density';
  return new ConfigError(field, `${field}: placed ${placed} of ${count} sites${why}, then ${failures} candidates in a row were rejected; ${hint}`);
}

function round(value: number): string {
  return Number(value.toPrecision(4)).toString();
}

/**
 * Uniform buckets at least one spacing wide (physically) along each axis, so any two points
 * closer than the spacing lie in the same or adjacent buckets (adjacency wraps on periodic
 * axes). Placed sites are chained per bucket through `next`; nothing is allocated per query.
 */
class SpatialHash {
  private readonly bucketsX: number;
  private readonly bucketsY: number;
  private readonly bucketWidth: number;
  private readonly bucketHeight: number;
  private readonly head: Int32Array;
  private readonly next: Int32Array;

  constructor(
    private readonly grid: Grid,
    capacity: number,
    spacingUm: number,
  ) {
    let nx = Math.max(1, Math.floor((grid.width * grid.texelX) / spacingUm));
    let ny = Math.max(1, Math.floor((grid.height * grid.texelY) / spacingUm));
    // A tiny spacing would ask for more buckets than sites; larger buckets stay correct.
    const excess = Math.sqrt((nx * ny) / Math.max(1, 4 * capacity));
    if (excess > 1) {
      nx = Math.max(1, Math.floor(nx / excess));
      ny = Math.max(1, Math.floor(ny / excess));
    }
    this.bucketsX = nx;
    this.bucketsY = ny;
    this.bucketWidth = grid.width / nx;
    this.bucketHeight = grid.height / ny;
    this.head = new Int32Array(nx * ny).fill(-1);
    this.next = new Int32Array(capacity);
  }

  insert(id: number, x: number, y: number): void {
    const b = this.bucketOf(x, y);
    this.next[id] = this.head[b];
    this.head[b] = id;
  }

  /** Whether a site in `sites` is closer than sqrt(limit2) µm to (x, y). */
  anyWithin(sites: Float32Array, x: number, y: number, limit2: number): boolean {
    const { bucketsX: nx, bucketsY: ny, grid } = this;
    const bx = Math.min(nx - 1, Math.floor(x / this.bucketWidth));
    const by = Math.min(ny - 1, Math.floor(y / this.bucketHeight));
    // With fewer than 3 buckets on a periodic axis, -1 and +1 would be the same bucket: scan all.
    const [x0, x1] = grid.periodicX && nx < 3 ? [0, nx - 1] : [bx - 1, bx + 1];
    const [y0, y1] = grid.periodicY && ny < 3 ? [0, ny - 1] : [by - 1, by + 1];
    for (let cy = y0; cy <= y1; cy++) {
      const row = wrapIndex(cy, ny, grid.periodicY);
      if (row < 0) continue;
      for (let cx = x0; cx <= x1; cx++) {
        const column = wrapIndex(cx, nx, grid.periodicX);
        if (column < 0) continue;
        for (let id = this.head[row * nx + column]; id >= 0; id = this.next[id]) {
          if (distanceSquared(grid, x, y, sites[2 * id], sites[2 * id + 1]) < limit2) return true;
        }
      }
    }
    return false;
  }

  private bucketOf(x: number, y: number): number {
    const bx = Math.min(this.bucketsX - 1, Math.floor(x / this.bucketWidth));
    const by = Math.min(this.bucketsY - 1, Math.floor(y / this.bucketHeight));
    return by * this.bucketsX + bx;
  }
}

/** Bucket index along an axis: wrapped if periodic, -1 if outside an open axis. */
function wrapIndex(k: number, n: number, periodic: boolean): number {
  if (k >= 0 && k < n) return k;
  if (!periodic) return -1;
  return k < 0 ? k + n : k - n;
}
