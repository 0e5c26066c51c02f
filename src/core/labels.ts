/**
 * What the engine computes from a label image on the CPU:
 *
 * - accumulateCentroidRows: the per-site centroid sums over a band of label rows (the GPU
 *   engine's readback centroid path);
 * - labelAdjacency: which cells share a boundary in a label image, and how long it is.
 *
 * All positions are in texel units and all lengths/areas in µm (µm²), per grid.ts. The CPU
 * references the tests check the GPU passes against live in tests/oracles/labels.ts.
 */
import type { SurfaceAdjacency } from './analysis/adjacency';
import { BORDER_X_END, BORDER_X_START, BORDER_Y_END, BORDER_Y_START } from './border';
import { type Grid, wrapDelta } from './grid';

// ---------------------------------------------------------------------------------------------
// Centroid sums
// ---------------------------------------------------------------------------------------------

/**
 * Per site, 4 sums over the texels labelled with it in a band of rows, added to `sums` (not
 * cleared): [Σ w·dx, Σ w·dy, Σ w, Σ w·d²], where (dx, dy) is the minimum-image offset in texel
 * units from the SITE to the texel centre and d² the squared physical distance (µm²); the
 * GPU centroid passes accumulate the same. Texels labelled -1 are skipped. `labels`
 * holds the band's rows only (row firstRow at index 0), `sites` 4 floats per site, its
 * position first (the GPU engine's site layout). For callers that read labels back in bands
 * (the GPU engine's readback centroid path); allocates nothing.
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
        if (run >= 0) addRun(grid, sums, run, j, sites[4 * run + 1], sumW, sumWdx, sumWdx2);
        if (id >= count) throw new Error(`reduceCentroids: label ${id} at texel (${i}, ${j}) but only ${count} sites`);
        run = id;
        siteX = id >= 0 ? sites[4 * id] : 0;
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
    if (run >= 0) addRun(grid, sums, run, j, sites[4 * run + 1], sumW, sumWdx, sumWdx2);
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

// ---------------------------------------------------------------------------------------------
// Adjacency
// ---------------------------------------------------------------------------------------------

/**
 * Which contact length a label adjacency reports:
 * - 'true': without the staircase bias (see labelAdjacency); apply thresholds in µm to these.
 * - 'staircase': the plain sum of the shared texel edges in µm, 1 to 1.41 (on average 4/π)
 *   times the true length of a straight contact. Only for rules defined in counted pixel edges
 *   (the lab's 6 px); never compare it with a length in µm.
 */
export type ContactLength = 'true' | 'staircase';

/**
 * Every pair of edge-adjacent texels (4-neighbourhood, across periodic seams too) with different
 * labels adds its shared texel edge to the two cells' boundary: texelY for a pair side by side
 * in x, texelX for a pair one above the other. Texels labelled -1 belong to no cell.
 *
 * Contact length: the texel edges between two cells form a staircase, and summing them
 * (the 'staircase' length) measures a straight contact at angle φ to the x axis as
 * L (|cos φ| + |sin φ|), 1 to 1.41 times too long (4/π on average). The edges are summed per
 * direction instead: Lx (the horizontal edges, between texels one above the other) and Ly (the
 * vertical ones), and the length is sqrt(Lx² + Ly²). A digitized straight segment is a
 * monotone staircase whose horizontal edges add up to its x extent and vertical ones to its y
 * extent (each within one texel edge at its ends), so this is its true length up to about one
 * texel edge, for every angle and for anisotropic texels. A Voronoi contact on a plane or an
 * unrolled tube is a straight segment, so this is the right model here. Chosen over the
 * signed vector sum of the edges (the chord) because a pair that touches twice (two parallel
 * contacts across a periodic seam, tiny domains only) keeps the sum of both lengths instead of
 * cancelling to 0, and over a sub-texel polyline because it needs nothing but the labels
 * (measured label images have no sites). Curved or broken boundaries come out at most their
 * true length and at least 1/sqrt(2) of their staircase. Measured against exact contact
 * lengths: tests/core/labelLengths.test.ts.
 *
 * The record (src/core/analysis/adjacency.ts): rows ascending; areas = texels x texelX x texelY;
 * border = the BORDER_* bits of the open edges a cell owns texels on (src/core/border.ts).
 *
 * Pairs are encoded as sortable numbers ((a·count + b)·2 + orientation, a < b), sorted, and
 * run-length summed; two passes size every array first, so the loops over texels allocate
 * nothing. Memory is proportional to the boundary, not to the grid.
 */
export function labelAdjacency(grid: Grid, labels: ArrayLike<number>, count: number, length: ContactLength = 'true', label?: string): SurfaceAdjacency {
  const { width, height, texelX, texelY, periodicX, periodicY } = grid;
  if (labels.length !== width * height) throw new Error(`labelAdjacency: ${labels.length} labels for ${width * height} texels`);
  if (2 * count * count > Number.MAX_SAFE_INTEGER) throw new Error(`labelAdjacency: ${count} cells is too many to encode pairs`);

  // Pass 1: texels per cell and border sides.
  const texels = new Int32Array(count);
  const border = new Uint8Array(count);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const a = labels[j * width + i];
      if (a < 0) continue;
      if (a >= count || !Number.isInteger(a)) throw new Error(`labelAdjacency: label ${a} at texel (${i}, ${j}) is not a cell id 0..${count - 1}`);
      texels[a]++;
      if (!periodicX) {
        if (i === 0) border[a] |= BORDER_X_START;
        if (i === width - 1) border[a] |= BORDER_X_END;
      }
      if (!periodicY) {
        if (j === 0) border[a] |= BORDER_Y_START;
        if (j === height - 1) border[a] |= BORDER_Y_END;
      }
    }
  }

  // Pass 2: count the boundary pairs, then encode every one (orientation 0: side by side in x).
  let pairs = 0;
  forEachLabelEdge(labels, grid, () => pairs++);
  const keys = new Float64Array(pairs);
  let n = 0;
  forEachLabelEdge(labels, grid, (a, b, orientation) => (keys[n++] = (Math.min(a, b) * count + Math.max(a, b)) * 2 + orientation));
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
  const rows = new ContactRows(offsets, count);
  forEachPair(keys, count, (a, b, alongX, alongY) => {
    // alongX pairs sit side by side in x and share a vertical edge of length texelY.
    const vertical = alongX * texelY;
    const horizontal = alongY * texelX;
    rows.add(a, b, Math.sqrt(vertical * vertical + horizontal * horizontal), vertical + horizontal);
  });
  const areas = Float64Array.from(texels, (t) => t * texelX * texelY);
  return { count, offsets, neighbours: rows.neighbours, lengths: length === 'true' ? rows.lengths : rows.staircaseLengths, areas, border, label };
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

/**
 * Calls `visit(a, b, orientation)` for every pair of edge-adjacent texels with different cell
 * labels (none -1): each texel with its right neighbour (orientation 0) and the one above it
 * (orientation 1), across periodic seams.
 */
function forEachLabelEdge(labels: ArrayLike<number>, grid: Grid, visit: (a: number, b: number, orientation: 0 | 1) => void): void {
  const { width, height } = grid;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const a = labels[j * width + i];
      if (a < 0) continue;
      const right = rightOf(labels, grid, i, j);
      if (right >= 0 && right !== a) visit(a, right, 0);
      const up = upOf(labels, grid, i, j);
      if (up >= 0 && up !== a) visit(a, up, 1);
    }
  }
}

/**
 * The rows of a CSR adjacency being filled from contacts a-b, both directions at once, with
 * the contact's true length and its staircase length. Adding the contacts in (a, b) order with
 * a < b leaves every row ascending (a row receives its smaller neighbours first).
 */
export class ContactRows {
  readonly neighbours: Int32Array;
  readonly lengths: Float64Array;
  readonly staircaseLengths: Float64Array;
  private readonly cursor: Int32Array;

  /** `offsets`: the row starts (count + 1 entries, the last the number of entries). */
  constructor(offsets: Int32Array, count: number) {
    const size = offsets[count];
    this.neighbours = new Int32Array(size);
    this.lengths = new Float64Array(size);
    this.staircaseLengths = new Float64Array(size);
    this.cursor = offsets.slice(0, count);
  }

  add(a: number, b: number, length: number, staircase: number): void {
    this.put(a, b, length, staircase);
    this.put(b, a, length, staircase);
  }

  private put(row: number, neighbour: number, length: number, staircase: number): void {
    const k = this.cursor[row]++;
    this.neighbours[k] = neighbour;
    this.lengths[k] = length;
    this.staircaseLengths[k] = staircase;
  }
}
