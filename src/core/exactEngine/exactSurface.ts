/**
 * The adjacency record of one surface (neighbours with shared lengths, areas, open-edge bits)
 * straight from the exact engine's cell walk: the same numbers as
 * `exactVoronoi(grid, sites).adjacency` (tested cell by cell), without building the per-cell
 * records. Sweeps call it tens of thousands of times; the pipeline may use either.
 */
import type { SurfaceAdjacency } from '../analysis/adjacency';
import { BORDER_X_END, BORDER_X_START, BORDER_Y_END, BORDER_Y_START } from '../border';
import type { Grid } from '../grid';
import { EDGE_FAR, EDGE_X0, EDGE_X1, EDGE_Y0, EDGE_Y1, PlanarVoronoi } from './planarVoronoi';
import { PolygonBuffer, polygonMoments } from './polygon';

/**
 * Exact adjacency, areas (µm²) and open-edge bits of the sites (texel units) on `grid`.
 * `continues`: the sites are those `voronoi` last built, moved a little (PlanarVoronoi.build).
 */
export function exactSurface(grid: Grid, sites: ArrayLike<number>, label?: string, voronoi?: PlanarVoronoi, continues = false): SurfaceAdjacency {
  const n = Math.floor(sites.length / 2);
  const v = voronoi ? voronoi.setGrid(grid) : new PlanarVoronoi(grid, n);
  if (v.count !== n) throw new Error(`exactSurface: the PlanarVoronoi holds ${v.count} sites, not ${n}`);
  v.build(sites, continues);
  // Areas and border bits in scratch during the walk (it may run again), copied into the record.
  if (scratch.areas.length < n) {
    scratch.areas = new Float64Array(n);
    scratch.border = new Uint8Array(n);
  }
  const { areas, border } = scratch;
  // Cells are walked in the diagram's spatial order (cache) into a scratch list in that order
  // (start[k] .. start[k + 1] for the k-th cell), then laid out in id order. The scratch is kept
  // between calls (a sweep makes tens of thousands of these records).
  if (scratch.start.length < n + 1) scratch.start = new Int32Array(n + 1);
  if (scratch.ids.length < 8 * n) {
    scratch.ids = new Int32Array(8 * n);
    scratch.lengths = new Float64Array(8 * n);
  }
  const { start, cell, moments } = scratch;
  start[0] = 0;
  let scratchIds = scratch.ids;
  let scratchLengths = scratch.lengths;
  const eps = v.epsilon;
  // Again (rarely) when a cell of a site near a periodic seam was not certified (planarVoronoi.ts).
  do {
    areas.fill(0, 0, n);
    border.fill(0, 0, n);
    for (let k = 0; k < n; k++) {
      const i = v.siteAt(k);
      v.cellAt(k, cell);
      const from = start[k];
      let m = 0;
      if (from + cell.count > scratchIds.length) {
        const grownIds = new Int32Array(2 * (from + cell.count));
        grownIds.set(scratchIds);
        scratchIds = grownIds;
        const grownLengths = new Float64Array(grownIds.length);
        grownLengths.set(scratchLengths);
        scratchLengths = grownLengths;
        scratch.ids = scratchIds;
        scratch.lengths = scratchLengths;
      }
      if (cell.count >= 3) {
        areas[i] = polygonMoments(cell.xy, cell.count, moments)[0];
        for (let e = 0; e < cell.count; e++) {
          const label = cell.labels[e];
          if (label === EDGE_FAR) continue;
          const l = e + 1 === cell.count ? 0 : e + 1;
          const dx = cell.xy[2 * l] - cell.xy[2 * e];
          const dy = cell.xy[2 * l + 1] - cell.xy[2 * e + 1];
          const length = Math.sqrt(dx * dx + dy * dy);
          if (length <= eps) continue;
          if (label < 0) {
            border[i] |= borderBit(label);
            continue;
          }
          const id = label % n;
          if (id === i) continue; // contact with its own periodic copy (tiny domains)
          // Summed per neighbour (several edges with one site: tiny periodic domains), kept
          // ascending by id as exactVoronoi lists them (insertion: a handful of neighbours).
          let at = from;
          while (at < from + m && scratchIds[at] < id) at++;
          if (at < from + m && scratchIds[at] === id) {
            scratchLengths[at] += length;
            continue;
          }
          for (let b = from + m; b > at; b--) {
            scratchIds[b] = scratchIds[b - 1];
            scratchLengths[b] = scratchLengths[b - 1];
          }
          scratchIds[at] = id;
          scratchLengths[at] = length;
          m++;
        }
      }
      start[k + 1] = from + m;
    }
  } while (v.retry());
  // The cells' lists lie end to end in the scratch: start[n] entries in all.
  const record = recordArrays(n, start[n]);
  const { offsets, neighbours, lengths } = record;
  record.areas.set(areas.subarray(0, n));
  record.border.set(border.subarray(0, n));
  for (let k = 0; k < n; k++) {
    const i = v.siteAt(k);
    offsets[i + 1] = start[k + 1] - start[k];
  }
  for (let i = 0; i < n; i++) offsets[i + 1] += offsets[i];
  // Copied by hand: two subarray views per cell were a good part of this function's time.
  for (let k = 0; k < n; k++) {
    const i = v.siteAt(k);
    for (let from = start[k], to = offsets[i]; from < start[k + 1]; from++, to++) {
      neighbours[to] = scratchIds[from];
      lengths[to] = scratchLengths[from];
    }
  }
  return { count: n, offsets, neighbours, lengths, areas: record.areas, border: record.border, label };
}

/**
 * The record's five arrays as views of one buffer: one allocation instead of five (a typed
 * array's own buffer is allocated outside the heap, and five of them per layer were a tenth of
 * this function's time in a sweep). Float64 first, then Int32, then bytes: each view aligned.
 */
function recordArrays(n: number, total: number) {
  const doubles = 8 * (total + n);
  const ints = 4 * (n + 1 + total);
  const buffer = new ArrayBuffer(doubles + ints + n);
  return {
    lengths: new Float64Array(buffer, 0, total),
    areas: new Float64Array(buffer, 8 * total, n),
    offsets: new Int32Array(buffer, doubles, n + 1),
    neighbours: new Int32Array(buffer, doubles + 4 * (n + 1), total),
    border: new Uint8Array(buffer, doubles + ints, n),
  };
}

/** Buffers of exactSurface's walk, grown as needed (one call at a time: JavaScript is single-threaded per realm). */
const scratch = {
  start: new Int32Array(0),
  areas: new Float64Array(0),
  border: new Uint8Array(0),
  ids: new Int32Array(0),
  lengths: new Float64Array(0),
  cell: new PolygonBuffer(),
  moments: new Float64Array(4),
};

/** The BORDER_* bit of a domain-edge label of the diagram (EDGE_FAR edges are skipped before). */
function borderBit(label: number): number {
  if (label === EDGE_Y0) return BORDER_Y_START;
  if (label === EDGE_Y1) return BORDER_Y_END;
  if (label === EDGE_X0) return BORDER_X_START;
  if (label === EDGE_X1) return BORDER_X_END;
  throw new Error(`exactSurface: unknown edge label ${label}`);
}
