/**
 * Cell adjacency as a compressed sparse row (CSR) structure, and the contact-length filter.
 *
 * - `CsrAdjacency`: the neighbours of cell i are `neighbours[offsets[i] .. offsets[i + 1])`;
 *   `lengths` (optional) holds the shared boundary length in µm of each contact, parallel to
 *   `neighbours`. `exactVoronoi` (src/core/exact.ts) and the label-texture adjacency produce it.
 * - `filterShortContacts(adj, minLength)`: drops every contact whose shared boundary is shorter
 *   than `minLength` µm (a contact of length exactly `minLength` is kept). The pixel-based method
 *   of the lab that published the scutoid model ignores shared edges shorter than about 6 px in
 *   a 512 px-around image; `labMinBoundaryLength` converts that to µm for a grid:
 *   `pixels * (grid.width * grid.texelX) / referenceWidth` with pixels = 6, referenceWidth = 512,
 *   i.e. 6 px of an image 512 px around the same circumference (= 6 * texelX when the grid is
 *   512 texels wide). The exact (Delaunay) adjacency needs no threshold; results must say which
 *   one was used.
 */

export interface CsrAdjacency {
  /** count + 1 offsets into `neighbours`. */
  offsets: Int32Array;
  /** Neighbour ids. */
  neighbours: Int32Array;
  /** Shared boundary length in µm per contact, parallel to `neighbours` (optional). */
  lengths?: Float64Array;
}

/** Either a CSR adjacency or one array of neighbour ids per cell. */
export type AdjacencyInput = CsrAdjacency | ArrayLike<number>[];

export function isCsr(input: AdjacencyInput): input is CsrAdjacency {
  return !Array.isArray(input) && (input as CsrAdjacency).offsets instanceof Int32Array;
}

/** Builds a CSR adjacency from one list of neighbour ids per cell (and optional parallel lengths). */
export function csrFromLists(lists: ArrayLike<number>[], lengths?: ArrayLike<number>[]): CsrAdjacency {
  const offsets = new Int32Array(lists.length + 1);
  for (let i = 0; i < lists.length; i++) offsets[i + 1] = offsets[i] + lists[i].length;
  const neighbours = new Int32Array(offsets[lists.length]);
  const flatLengths = lengths ? new Float64Array(offsets[lists.length]) : undefined;
  for (let i = 0; i < lists.length; i++) {
    for (let k = 0; k < lists[i].length; k++) {
      neighbours[offsets[i] + k] = lists[i][k];
      if (flatLengths) flatLengths[offsets[i] + k] = lengths![i][k];
    }
  }
  return flatLengths ? { offsets, neighbours, lengths: flatLengths } : { offsets, neighbours };
}

/** Normalizes an adjacency input to CSR (lists are copied, CSR is returned as is). */
export function toCsr(input: AdjacencyInput): CsrAdjacency {
  return isCsr(input) ? input : csrFromLists(input);
}

/** Number of cells described by an adjacency. */
export function adjacencyCount(input: AdjacencyInput): number {
  return isCsr(input) ? input.offsets.length - 1 : input.length;
}

/**
 * Sorted, deduplicated neighbour ids of cell i, without i itself (the form the analysis
 * compares).
 */
export function neighbourSet(adj: CsrAdjacency, i: number): Int32Array {
  const raw = adj.neighbours.slice(adj.offsets[i], adj.offsets[i + 1]).sort();
  let m = 0;
  for (let k = 0; k < raw.length; k++) {
    const v = raw[k];
    if (v === i || (m > 0 && raw[m - 1] === v)) continue;
    raw[m++] = v;
  }
  return raw.subarray(0, m);
}

/** Drops contacts shorter than `minLength` µm. Requires `lengths`. Keeps the CSR layout. */
export function filterShortContacts(adj: CsrAdjacency, minLength: number): CsrAdjacency {
  const lengths = adj.lengths;
  if (!lengths) throw new Error('filterShortContacts needs shared boundary lengths');
  const count = adj.offsets.length - 1;
  const offsets = new Int32Array(count + 1);
  let total = 0;
  for (let k = 0; k < adj.neighbours.length; k++) if (lengths[k] >= minLength) total++;
  const neighbours = new Int32Array(total);
  const kept = new Float64Array(total);
  let m = 0;
  for (let i = 0; i < count; i++) {
    for (let k = adj.offsets[i]; k < adj.offsets[i + 1]; k++) {
      if (lengths[k] >= minLength) {
        neighbours[m] = adj.neighbours[k];
        kept[m] = lengths[k];
        m++;
      }
    }
    offsets[i + 1] = m;
  }
  return { offsets, neighbours, lengths: kept };
}

/**
 * The lab's pixel-based adjacency ignores contacts shorter than 6 px, on 512 x 4096 px tubes with
 * 200 cells, i.e. cells whose mean diameter sqrt(area / cells) is 102.4 px.
 */
export const LAB_MIN_BOUNDARY_PIXELS = 6;
export const LAB_MEAN_CELL_DIAMETER_PIXELS = Math.sqrt((512 * 4096) / 200);

/**
 * The lab's short-contact threshold carried over to any sheet: the same fraction (6 / 102.4) of
 * the mean cell diameter sqrt(area / cells). On the lab's tube (1 µm per px) that is exactly
 * 6 µm; on other sizes and densities it keeps ignoring the same relative contact length,
 * whatever the grid's resolution.
 */
export function labMinBoundaryLength(areaUm2: number, cells: number, pixels = LAB_MIN_BOUNDARY_PIXELS): number {
  return (pixels * Math.sqrt(areaUm2 / cells)) / LAB_MEAN_CELL_DIAMETER_PIXELS;
}

/** True when j is in i's list exactly when i is in j's list (with equal lengths when present, within tol). */
export function isSymmetric(adj: CsrAdjacency, tol = 1e-9): boolean {
  const count = adj.offsets.length - 1;
  for (let i = 0; i < count; i++) {
    for (let k = adj.offsets[i]; k < adj.offsets[i + 1]; k++) {
      const j = adj.neighbours[k];
      let found = -1;
      for (let q = adj.offsets[j]; q < adj.offsets[j + 1]; q++) if (adj.neighbours[q] === i) found = q;
      if (found < 0) return false;
      if (adj.lengths && Math.abs(adj.lengths[found] - adj.lengths[k]) > tol * Math.max(1, adj.lengths[k])) return false;
    }
  }
  return true;
}
