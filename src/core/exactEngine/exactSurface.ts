/**
 * The analysis input of one surface (neighbours with shared lengths, areas, open-end contacts)
 * straight from the exact engine's cell walk: the same numbers as
 * `surfaceFromExact(exactVoronoi(grid, sites))` (tested cell by cell), without building the
 * per-cell records. Sweeps call it tens of thousands of times; the pipeline may use either.
 */
import type { SurfaceAdjacency } from '../analysis/scutoids';
import type { Grid } from '../grid';
import { EDGE_FAR, EDGE_X0, EDGE_X1, EDGE_Y0, EDGE_Y1, PlanarVoronoi } from './planarVoronoi';
import { PolygonBuffer, polygonMoments } from './polygon';

/** Exact adjacency, areas (µm²) and open-end contacts of the sites (texel units) on `grid`. */
export function exactSurface(grid: Grid, sites: ArrayLike<number>, label?: string, voronoi?: PlanarVoronoi): SurfaceAdjacency {
  const n = Math.floor(sites.length / 2);
  const v = voronoi ? voronoi.setGrid(grid) : new PlanarVoronoi(grid, n);
  if (v.count !== n) throw new Error(`exactSurface: the PlanarVoronoi holds ${v.count} sites, not ${n}`);
  v.build(sites);
  const cell = new PolygonBuffer();
  const moments = new Float64Array(4);
  const areas = new Float64Array(n);
  const touchesBorder = new Uint8Array(n);
  const offsets = new Int32Array(n + 1);
  let neighbours = new Int32Array(8 * n);
  let lengths = new Float64Array(8 * n);
  const ids: number[] = [];
  const lens: number[] = [];
  const eps = v.epsilon;
  // Again (rarely) when a cell of a site near a periodic seam was not certified (planarVoronoi.ts).
  do {
    areas.fill(0);
    touchesBorder.fill(0);
    for (let i = 0; i < n; i++) {
      v.cell(i, cell);
      ids.length = 0;
      lens.length = 0;
      if (cell.count >= 3) {
        areas[i] = polygonMoments(cell.xy, cell.count, moments)[0];
        for (let k = 0; k < cell.count; k++) {
          const label = cell.labels[k];
          if (label === EDGE_FAR) continue;
          const l = k + 1 === cell.count ? 0 : k + 1;
          const dx = cell.xy[2 * l] - cell.xy[2 * k];
          const dy = cell.xy[2 * l + 1] - cell.xy[2 * k + 1];
          const length = Math.sqrt(dx * dx + dy * dy);
          if (length <= eps) continue;
          if (label === EDGE_Y0 || label === EDGE_Y1 || label === EDGE_X0 || label === EDGE_X1) {
            touchesBorder[i] = 1;
            continue;
          }
          const id = label % n;
          if (id === i) continue; // contact with its own periodic copy (tiny domains)
          const at = ids.indexOf(id);
          if (at >= 0) lens[at] += length;
          else {
            ids.push(id);
            lens.push(length);
          }
        }
      }
      const start = offsets[i];
      if (start + ids.length > neighbours.length) {
        const grown = new Int32Array(2 * (start + ids.length));
        grown.set(neighbours);
        neighbours = grown;
        const grownLengths = new Float64Array(grown.length);
        grownLengths.set(lengths);
        lengths = grownLengths;
      }
      // Ascending ids, as exactVoronoi lists them (insertion sort: a handful of neighbours).
      for (let a = 0; a < ids.length; a++) {
        let b = a;
        const id = ids[a];
        const len = lens[a];
        while (b > 0 && neighbours[start + b - 1] > id) {
          neighbours[start + b] = neighbours[start + b - 1];
          lengths[start + b] = lengths[start + b - 1];
          b--;
        }
        neighbours[start + b] = id;
        lengths[start + b] = len;
      }
      offsets[i + 1] = start + ids.length;
    }
  } while (v.retry());
  const total = offsets[n];
  return {
    count: n,
    adjacency: { offsets, neighbours: neighbours.slice(0, total), lengths: lengths.slice(0, total) },
    areas,
    touchesBorder,
    label,
  };
}
