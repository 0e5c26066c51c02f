/**
 * CPU references for the GPU passes, and the cell adjacency the results are built from.
 *
 * - bruteForceLabels: exact nearest-site labels (what the jump flood approximates).
 * - reduceCentroids: the per-site sums the centroid pass accumulates, from a label image.
 * - centroidSites / cvtEnergy: what Lloyd does with those sums.
 * - labelAdjacency: which cells share a boundary in a label image, and how long it is.
 *
 * All positions are in texel units and all lengths/areas in µm (µm²), per grid.ts.
 */
import { distanceSquared, type Grid, wrapCoordinate, wrapDelta } from './grid';
import { type LloydMove, moveSitesToCentroids } from './lloydUpdate';

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
    const x = wrapCoordinate(sites[2 * id], grid.width, grid.periodicX);
    const y = wrapCoordinate(sites[2 * id + 1], grid.height, grid.periodicY);
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
export function reduceCentroids(
  grid: Grid,
  labels: ArrayLike<number>,
  sites: Float32Array,
  weight: Float32Array | null,
  out?: Float64Array,
): Float64Array {
  const { width, height } = grid;
  const count = Math.floor(sites.length / 2);
  const sums = out ?? new Float64Array(4 * count);
  if (sums.length < 4 * count) throw new Error(`reduceCentroids: out has ${sums.length} entries, ${4 * count} needed`);
  if (labels.length !== width * height) throw new Error(`reduceCentroids: ${labels.length} labels for ${width * height} texels`);
  if (weight && weight.length !== width * height) throw new Error(`reduceCentroids: ${weight.length} weights for ${width * height} texels`);
  sums.fill(0, 0, 4 * count);
  accumulateCentroidRows(grid, labels, 0, height, sites, 2, count, weight, sums);
  return sums;
}

/**
 * The loop of reduceCentroids over a band of rows, added to `sums` (not cleared): `labels`
 * holds the band's rows only (row firstRow at index 0), `sites` positions with `siteStride`
 * floats per site. For callers that read labels back in bands (the GPU engine's readback
 * centroid path); allocates nothing.
 *
 * A row crosses a cell in one run of equal labels, and within a run dy is constant, so a run
 * sums only w, w·dx and w·dx² in local variables; Σw·dy and Σw·d² follow when it ends
 * (d² = (dx·texelX)² + (dy·texelY)²). That keeps the per-texel work to a few additions.
 */
export function accumulateCentroidRows(
  grid: Grid,
  labels: ArrayLike<number>,
  firstRow: number,
  rows: number,
  sites: Float32Array,
  siteStride: number,
  count: number,
  weight: Float32Array | null,
  sums: Float64Array,
): void {
  const { width, periodicX } = grid;
  // Minimum image along x written out (as in wrapDelta): a call here costs twice the loop.
  const halfWidth = periodicX ? width / 2 : Infinity;
  for (let r = 0; r < rows; r++) {
    const j = firstRow + r;
    let run = -1;
    let siteX = 0;
    let sumW = 0;
    let sumWdx = 0;
    let sumWdx2 = 0;
    for (let i = 0; i < width; i++) {
      const id = labels[r * width + i];
      if (id !== run) {
        if (run >= 0) addRun(grid, sums, run, j, sites[siteStride * run + 1], sumW, sumWdx, sumWdx2);
        if (id >= count) throw new Error(`reduceCentroids: label ${id} at texel (${i}, ${j}) but only ${count} sites`);
        run = id;
        siteX = id >= 0 ? sites[siteStride * id] : 0;
        sumW = 0;
        sumWdx = 0;
        sumWdx2 = 0;
      }
      if (id < 0) continue;
      const w = weight ? weight[j * width + i] : 1;
      let dx = i + 0.5 - siteX;
      if (dx > halfWidth) dx -= width;
      else if (dx < -halfWidth) dx += width;
      sumW += w;
      sumWdx += w * dx;
      sumWdx2 += w * dx * dx;
    }
    if (run >= 0) addRun(grid, sums, run, j, sites[siteStride * run + 1], sumW, sumWdx, sumWdx2);
  }
}

/** Adds one run of a cell's texels in row j (its Σw, Σw·dx, Σw·dx²) to the cell's sums. */
function addRun(grid: Grid, sums: Float64Array, id: number, j: number, siteY: number, sumW: number, sumWdx: number, sumWdx2: number): void {
  const dy = wrapDelta(j + 0.5 - siteY, grid.height, grid.periodicY);
  sums[4 * id] += sumWdx;
  sums[4 * id + 1] += sumW * dy;
  sums[4 * id + 2] += sumW;
  sums[4 * id + 3] += grid.texelX * grid.texelX * sumWdx2 + grid.texelY * grid.texelY * dy * dy * sumW;
}

/**
 * The Lloyd move from those sums: each site goes to site + omega·(Σ w·d)/(Σ w), wrapped on
 * periodic axes and clamped on open ones; sites with an empty cell stay put. Returns new
 * positions (in `out` if given; `sites` is not modified) and the move's statistics. This is the
 * same update the GPU loop applies (lloydUpdate.ts), so CPU and GPU runs stay comparable.
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
  const move: LloydMove = { energy: 0, maxDisplacement: 0, maxDisplacementTexels: 0, emptyCells: 0 };
  moveSitesToCentroids(grid, next, sums, Math.floor(sites.length / 2), omega, move);
  return { sites: next, move };
}

/** CVT energy Σ w·d²·texelX·texelY over all texels (µm⁴ x weight), from the sums above. */
export function cvtEnergy(grid: Grid, sums: ArrayLike<number>): number {
  let energy = 0;
  for (let k = 3; k < sums.length; k += 4) energy += sums[k];
  return energy * grid.texelX * grid.texelY;
}

// ---------------------------------------------------------------------------------------------
// Adjacency
// ---------------------------------------------------------------------------------------------

/** Bits of LabelAdjacency.borderSides: which open domain edges a cell owns texels on. */
export const BORDER_X_START = 1; // first column, x axis not periodic
export const BORDER_X_END = 2; // last column
export const BORDER_Y_START = 4; // first row, y axis not periodic (a tube's y = 0 end)
export const BORDER_Y_END = 8; // last row (a tube's far end)

/** Cell adjacency from a label image, in compressed sparse rows. */
export interface LabelAdjacency {
  readonly count: number;
  /** Neighbours of cell c are neighbours[offsets[c] .. offsets[c+1]), ascending ids. */
  readonly offsets: Int32Array;
  readonly neighbours: Int32Array;
  /** Shared boundary length in µm, parallel to `neighbours` (symmetric: a->b equals b->a). */
  readonly lengths: Float64Array;
  /** Texels per cell. */
  readonly texels: Int32Array;
  /** Cell area in µm² (texels x texelX x texelY). */
  readonly area: Float64Array;
  /** 1 if the cell owns a texel on an open edge of the domain (any BORDER_* bit), else 0. */
  readonly touchesBorder: Uint8Array;
  /** BORDER_* bits per cell. */
  readonly borderSides: Uint8Array;
}

/**
 * Every pair of edge-adjacent texels (4-neighbourhood, across periodic seams too) with different
 * labels adds its shared texel edge to the two cells' boundary: texelY for a pair side by side
 * in x, texelX for a pair one above the other. Texels labelled -1 belong to no cell.
 *
 * Pairs are encoded as sortable numbers ((a·count + b)·2 + orientation, a < b), sorted, and
 * run-length summed; two passes size every array first, so the loops over texels allocate
 * nothing. Memory is proportional to the boundary, not to the grid.
 */
export function labelAdjacency(grid: Grid, labels: ArrayLike<number>, count: number): LabelAdjacency {
  const { width, height, texelX, texelY, periodicX, periodicY } = grid;
  if (labels.length !== width * height) throw new Error(`labelAdjacency: ${labels.length} labels for ${width * height} texels`);
  if (2 * count * count > Number.MAX_SAFE_INTEGER) throw new Error(`labelAdjacency: ${count} cells is too many to encode pairs`);

  // Pass 1: texels per cell, border sides, and how many boundary pairs there are.
  const texels = new Int32Array(count);
  const borderSides = new Uint8Array(count);
  let pairs = 0;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const a = labels[j * width + i];
      if (a < 0) continue;
      if (a >= count || !Number.isInteger(a)) throw new Error(`labelAdjacency: label ${a} at texel (${i}, ${j}) is not a cell id 0..${count - 1}`);
      texels[a]++;
      if (!periodicX) {
        if (i === 0) borderSides[a] |= BORDER_X_START;
        if (i === width - 1) borderSides[a] |= BORDER_X_END;
      }
      if (!periodicY) {
        if (j === 0) borderSides[a] |= BORDER_Y_START;
        if (j === height - 1) borderSides[a] |= BORDER_Y_END;
      }
      const right = rightOf(labels, grid, i, j);
      if (right >= 0 && right !== a) pairs++;
      const up = upOf(labels, grid, i, j);
      if (up >= 0 && up !== a) pairs++;
    }
  }

  // Pass 2: encode every boundary pair.
  const keys = new Float64Array(pairs);
  let n = 0;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const a = labels[j * width + i];
      if (a < 0) continue;
      const right = rightOf(labels, grid, i, j);
      if (right >= 0 && right !== a) keys[n++] = (Math.min(a, right) * count + Math.max(a, right)) * 2;
      const up = upOf(labels, grid, i, j);
      if (up >= 0 && up !== a) keys[n++] = (Math.min(a, up) * count + Math.max(a, up)) * 2 + 1;
    }
  }
  keys.sort();

  // Pass 3: degrees of the distinct pairs, then rows. Sorted by (a, b) with a < b, filling
  // rows in this order leaves every row ascending: a row c receives its smaller neighbours
  // (from pairs whose a < c) before its larger ones (pairs whose a = c), each group in order.
  const degree = new Int32Array(count + 1);
  forEachPair(keys, count, (a, b) => {
    degree[a + 1]++;
    degree[b + 1]++;
  });
  const offsets = degree; // prefix sums in place: offsets[c] = start of row c
  for (let c = 0; c < count; c++) offsets[c + 1] += offsets[c];
  const neighbours = new Int32Array(offsets[count]);
  const lengths = new Float64Array(offsets[count]);
  const cursor = offsets.slice(0, count);
  forEachPair(keys, count, (a, b, alongX, alongY) => {
    // alongX pairs sit side by side in x and share a vertical edge of length texelY.
    const length = alongX * texelY + alongY * texelX;
    neighbours[cursor[a]] = b;
    lengths[cursor[a]++] = length;
    neighbours[cursor[b]] = a;
    lengths[cursor[b]++] = length;
  });

  const area = new Float64Array(count);
  const touchesBorder = new Uint8Array(count);
  for (let c = 0; c < count; c++) {
    area[c] = texels[c] * texelX * texelY;
    touchesBorder[c] = borderSides[c] !== 0 ? 1 : 0;
  }
  return { count, offsets, neighbours, lengths, texels, area, touchesBorder, borderSides };
}

/** Label of the texel to the right (wrapping on a periodic x), or -1 past an open edge. */
function rightOf(labels: ArrayLike<number>, grid: Grid, i: number, j: number): number {
  if (i + 1 < grid.width) return labels[j * grid.width + i + 1];
  return grid.periodicX && grid.width > 1 ? labels[j * grid.width] : -1;
}

/** Label of the texel above (wrapping on a periodic y), or -1 past an open edge. */
function upOf(labels: ArrayLike<number>, grid: Grid, i: number, j: number): number {
  if (j + 1 < grid.height) return labels[(j + 1) * grid.width + i];
  return grid.periodicY && grid.height > 1 ? labels[i] : -1;
}

/** Calls `visit(a, b, edgesAlongX, edgesAlongY)` once per distinct pair, in sorted order. */
function forEachPair(keys: Float64Array, count: number, visit: (a: number, b: number, alongX: number, alongY: number) => void): void {
  let k = 0;
  while (k < keys.length) {
    const pair = Math.floor(keys[k] / 2);
    let alongX = 0;
    let alongY = 0;
    while (k < keys.length && Math.floor(keys[k] / 2) === pair) {
      if (keys[k] % 2 === 0) alongX++;
      else alongY++;
      k++;
    }
    visit(Math.floor(pair / count), pair % count, alongX, alongY);
  }
}

/** Shared boundary length (µm) between cells a and b, 0 if they are not neighbours. */
export function sharedLength(adjacency: LabelAdjacency, a: number, b: number): number {
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
