/**
 * The adjacency record: what every adjacency method produces and the only input the analysis
 * (analyzeSurfaces, the lab protocol) accepts. Typed arrays in the manner of delaunator, one
 * record per surface of a stack:
 *
 * - the neighbours of cell i are `neighbours[offsets[i] .. offsets[i + 1])` (compressed sparse
 *   rows); `lengths[k]` is the shared boundary length in µm of contact k (symmetric: a -> b
 *   equals b -> a). Producers list each row ascending, once, without the cell itself; the
 *   analysis still deduplicates a row that is not (`neighbourSet`).
 * - `areas[i]` is the cell's area in µm²; `border[i]` the bits of src/core/border.ts (0 for an
 *   interior cell; any bit excludes the cell from the statistics).
 *
 * Producers: `labelAdjacency` (src/core/labels.ts, a planar label image),
 * `cubeLabelAdjacency` (src/core/closed/geometry.ts, a cube-map label image), `exactSurface`
 * (src/core/exactEngine, the exact planar method) and `exactVoronoi` (src/core/exact.ts, the
 * same diagram with per-cell polygons), `restrictedVoronoi` (src/core/closed, closed surfaces),
 * and `measure` (src/core/measure: measured layers, and the volume's surfaces).
 *
 * The contact-length filter: `withMinBoundaryLength(adj, minLength)` drops every contact whose
 * shared boundary is shorter than `minLength` µm (a contact of length exactly `minLength` is
 * kept). The pixel-based method of the lab that published the scutoid model ignores shared
 * edges shorter than about 6 px in a 512 px-around image; `labMinBoundaryLength` carries that
 * rule to any sheet. The exact (Delaunay-based) adjacency needs no threshold; results must say
 * which one was used.
 */

export interface SurfaceAdjacency {
  /** Number of cells, ids 0..count-1 (the same cells on every surface of a stack). */
  readonly count: number;
  /** count + 1 offsets into `neighbours`. */
  readonly offsets: Int32Array;
  /** Neighbour ids, per cell ascending, without the cell itself. */
  readonly neighbours: Int32Array;
  /** Shared boundary length in µm per contact, parallel to `neighbours`. */
  readonly lengths: Float64Array;
  /** Cell areas in µm². */
  readonly areas: Float64Array;
  /** BORDER_* bits per cell (src/core/border.ts); 0 for an interior cell. */
  readonly border: Uint8Array;
  /** Side counts when they differ from the number of distinct neighbours (default: that number). */
  readonly sides?: Int32Array;
  /** The surface's name (e.g. "basal", "apical", "s=1.5"). */
  readonly label?: string;
}

/**
 * The record from one list of neighbour ids per cell and their lengths (parallel lists), for
 * producers that gather contacts per cell.
 */
export function adjacencyFromLists(
  lists: ArrayLike<number>[],
  lengths: ArrayLike<number>[],
  areas: Float64Array,
  border: Uint8Array,
  label?: string,
): SurfaceAdjacency {
  const count = lists.length;
  const offsets = new Int32Array(count + 1);
  for (let i = 0; i < count; i++) offsets[i + 1] = offsets[i] + lists[i].length;
  const neighbours = new Int32Array(offsets[count]);
  const flatLengths = new Float64Array(offsets[count]);
  for (let i = 0; i < count; i++) {
    if (lengths[i].length !== lists[i].length)
      throw new Error(`adjacencyFromLists: cell ${i} has ${lists[i].length} neighbours and ${lengths[i].length} lengths`);
    for (let k = 0; k < lists[i].length; k++) {
      neighbours[offsets[i] + k] = lists[i][k];
      flatLengths[offsets[i] + k] = lengths[i][k];
    }
  }
  return { count, offsets, neighbours, lengths: flatLengths, areas, border, label };
}

/**
 * Sorted, deduplicated neighbour ids of cell i, without i itself (the form the analysis
 * compares).
 */
export function neighbourSet(adj: SurfaceAdjacency, i: number): Int32Array {
  const raw = adj.neighbours.slice(adj.offsets[i], adj.offsets[i + 1]).sort();
  let m = 0;
  for (let k = 0; k < raw.length; k++) {
    const v = raw[k];
    if (v === i || (m > 0 && raw[m - 1] === v)) continue;
    raw[m++] = v;
  }
  return raw.subarray(0, m);
}

/**
 * The record without the contacts shorter than `minLength` µm (the rows keep their order). Side
 * counts follow from the remaining neighbours (an explicit `sides` is dropped).
 */
export function withMinBoundaryLength(adj: SurfaceAdjacency, minLength: number): SurfaceAdjacency {
  const lengths = adj.lengths;
  const count = adj.count;
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
  return { count, offsets, neighbours, lengths: kept, areas: adj.areas, border: adj.border, label: adj.label };
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
export function labMinBoundaryLength(areaUm2: number, cells: number): number {
  return (LAB_MIN_BOUNDARY_PIXELS * Math.sqrt(areaUm2 / cells)) / LAB_MEAN_CELL_DIAMETER_PIXELS;
}
