import type { ExactVoronoi } from '../exact';
import type { Grid } from '../grid';

/**
 * The label image of an exact Voronoi diagram: each texel gets the id of the cell whose polygon
 * holds its centre (-1 where none does), by filling every convex cell polygon row by row. This is
 * what views draw when the exact engine ran (it makes no label textures); no statistic reads it.
 * Polygons are unwrapped around their site, so rows and columns wrap along periodic axes.
 */
export function rasterizeCells(grid: Grid, voronoi: { readonly cells: readonly Pick<ExactVoronoi['cells'][number], 'id' | 'polygon'>[] }): Int32Array {
  const { width, height, periodicX, periodicY } = grid;
  const out = new Int32Array(width * height).fill(-1);
  for (const cell of voronoi.cells) {
    const p = cell.polygon;
    const n = p.length / 2;
    if (n < 3) continue;
    let yMin = Infinity;
    let yMax = -Infinity;
    for (let k = 0; k < n; k++) {
      yMin = Math.min(yMin, p[2 * k + 1]);
      yMax = Math.max(yMax, p[2 * k + 1]);
    }
    // Rows whose centre j + 0.5 lies in [yMin, yMax).
    for (let j = Math.ceil(yMin - 0.5); j + 0.5 < yMax; j++) {
      const row = wrap(j, height, periodicY);
      if (row < 0) continue;
      const y = j + 0.5;
      let xMin = Infinity;
      let xMax = -Infinity;
      for (let k = 0; k < n; k++) {
        const x0 = p[2 * k],
          y0 = p[2 * k + 1];
        const x1 = p[(2 * k + 2) % (2 * n)],
          y1 = p[(2 * k + 3) % (2 * n)];
        if ((y0 <= y && y < y1) || (y1 <= y && y < y0)) {
          const x = x0 + ((y - y0) * (x1 - x0)) / (y1 - y0);
          xMin = Math.min(xMin, x);
          xMax = Math.max(xMax, x);
        }
      }
      for (let i = Math.ceil(xMin - 0.5); i + 0.5 < xMax; i++) {
        const column = wrap(i, width, periodicX);
        if (column >= 0) out[row * width + column] = cell.id;
      }
    }
  }
  return out;
}

/** Index along an axis of `size` texels: wrapped where periodic, -1 outside where open. */
function wrap(index: number, size: number, periodic: boolean): number {
  if (periodic) return ((index % size) + size) % size;
  return index >= 0 && index < size ? index : -1;
}
