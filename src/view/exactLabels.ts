/**
 * The label image of the exact Voronoi diagram of sites on a plane's or tube's grid, for the
 * views of a result opened from a file (issue 27: a 100,000-cell result). The exact engine's
 * PlanarVoronoi builds the diagram (0.1-0.3 s at 100,000 sites, where core/exact.ts's
 * exactVoronoi took 7 s: it also builds every cell's record), and rasterizeCells fills it.
 */
import type { Grid } from '../core/grid';
import { PlanarVoronoi, PolygonBuffer, rasterizeCells } from '../core/exactEngine';

/** Each site's exact cell polygon, in texel units, unwrapped around its site (id = index). */
function exactCellPolygons(grid: Grid, sites: ArrayLike<number>): { id: number; polygon: Float64Array }[] {
  const n = Math.floor(sites.length / 2);
  const voronoi = new PlanarVoronoi(grid, n).build(sites);
  const cell = new PolygonBuffer();
  const cells: { id: number; polygon: Float64Array }[] = new Array(n);
  // Again (rarely) when a cell near a periodic seam was not certified (planarVoronoi.ts).
  do {
    for (let k = 0; k < n; k++) {
      const id = voronoi.siteAt(k);
      // Relative to the site (µm): back to texel units around the site's own position.
      voronoi.cellAt(k, cell);
      const x = voronoi.xAt(k);
      const y = voronoi.yAt(k);
      const polygon = new Float64Array(2 * cell.count);
      for (let v = 0; v < cell.count; v++) {
        polygon[2 * v] = (cell.xy[2 * v] + x) / grid.texelX;
        polygon[2 * v + 1] = (cell.xy[2 * v + 1] + y) / grid.texelY;
      }
      cells[id] = { id, polygon };
    }
  } while (voronoi.retry());
  return cells;
}

/** The label image (site id per texel, -1 where no cell is) of the exact cells of `sites` (texel units). */
export function exactLabelImage(grid: Grid, sites: ArrayLike<number>): Int32Array {
  return rasterizeCells(grid, { cells: exactCellPolygons(grid, sites) });
}
