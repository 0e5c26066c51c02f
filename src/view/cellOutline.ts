/**
 * The exact cell of one site on a plane's or tube's surface, computed alone (issue 27): the
 * picked cell is drawn over the pictures (pickOverlay.ts, unrolled patches) from this polygon,
 * so a pick costs the same whatever the cell count, where repainting every picture cost seconds
 * at 100,000 cells.
 *
 * The Voronoi cell of site s is the intersection of the half-planes closer to s than to each
 * other site; only its Delaunay neighbours bound it. Candidates are the cell's recorded
 * neighbours and theirs (two rings: a label-image result may miss a contact shorter than a
 * texel, whose site is then almost surely a neighbour's neighbour); extra candidates are
 * harmless (their half-planes contain the cell). Distances are physical (µm), as in the exact
 * engine (core/exact.ts); periodic axes use every image of a candidate.
 */
import type { Grid } from '../core/grid';

/** What the outline needs of a surface's cells: site positions (µm) and neighbour ids. */
export interface OutlineCells {
  readonly length: number;
  /** Site of cell `id`, µm on the unrolled surface. */
  site(id: number): readonly [number, number];
  neighbours(id: number): Iterable<number>;
}

/** Cells of a ViewSurface-like list of CellRecords as OutlineCells. */
export function outlineCells(cells: readonly { surface: readonly [number, number]; neighbours: readonly { id: number }[] }[]): OutlineCells {
  return {
    length: cells.length,
    site: (id) => cells[id].surface as readonly [number, number],
    neighbours: (id) => cells[id].neighbours.map((n) => n.id),
  };
}

/** Ids within two rings of `id` (itself excluded). */
export function candidateIds(cells: OutlineCells, id: number): number[] {
  const found = new Set<number>();
  for (const a of cells.neighbours(id)) {
    found.add(a);
    for (const b of cells.neighbours(a)) found.add(b);
  }
  found.delete(id);
  return [...found].filter((k) => k >= 0 && k < cells.length);
}

/**
 * Cell `id`'s polygon in texel units (x, y pairs, counter-clockwise), unwrapped around its site:
 * on a periodic axis it may reach outside [0, width) (draw it again shifted by the width).
 * Empty when the cell is empty (a duplicate site).
 */
export function cellOutline(grid: Grid, cells: OutlineCells, id: number): Float64Array {
  const widthUm = grid.width * grid.texelX;
  const heightUm = grid.height * grid.texelY;
  const [sx, sy] = cells.site(id);
  // The domain around the site: the whole surface, or one period centred on the site.
  const x0 = grid.periodicX ? sx - widthUm / 2 : 0;
  const y0 = grid.periodicY ? sy - heightUm / 2 : 0;
  let polygon = [x0, y0, x0 + widthUm, y0, x0 + widthUm, y0 + heightUm, x0, y0 + heightUm];
  const shiftsX = grid.periodicX ? [-widthUm, 0, widthUm] : [0];
  const shiftsY = grid.periodicY ? [-heightUm, 0, heightUm] : [0];
  for (const other of candidateIds(cells, id)) {
    const [ox, oy] = cells.site(other);
    for (const dx of shiftsX) {
      for (const dy of shiftsY) {
        polygon = clipCloser(polygon, sx, sy, ox + dx, oy + dy);
        if (polygon.length === 0) return new Float64Array(0);
      }
    }
  }
  const out = new Float64Array(polygon.length);
  for (let k = 0; k < polygon.length; k += 2) {
    out[k] = polygon[k] / grid.texelX;
    out[k + 1] = polygon[k + 1] / grid.texelY;
  }
  return out;
}

/** The part of convex `polygon` closer to (sx, sy) than to (ox, oy) (Sutherland-Hodgman). */
export function clipCloser(polygon: number[], sx: number, sy: number, ox: number, oy: number): number[] {
  const nx = ox - sx;
  const ny = oy - sy;
  if (nx === 0 && ny === 0) return polygon;
  // Inside where (p - m) . n <= 0, m the midpoint of the two sites.
  const c = (nx * (sx + ox) + ny * (sy + oy)) / 2;
  const side = (x: number, y: number) => nx * x + ny * y - c;
  const out: number[] = [];
  const count = polygon.length / 2;
  for (let k = 0; k < count; k++) {
    const ax = polygon[2 * k];
    const ay = polygon[2 * k + 1];
    const bx = polygon[(2 * k + 2) % polygon.length];
    const by = polygon[(2 * k + 3) % polygon.length];
    const fa = side(ax, ay);
    const fb = side(bx, by);
    if (fa <= 0) out.push(ax, ay);
    if ((fa < 0 && fb > 0) || (fa > 0 && fb < 0)) {
      const t = fa / (fa - fb);
      out.push(ax + t * (bx - ax), ay + t * (by - ay));
    }
  }
  return out.length >= 6 ? out : [];
}

/** Bounding box of a polygon (x, y pairs): [minX, minY, maxX, maxY]. */
export function polygonBounds(polygon: ArrayLike<number>): [number, number, number, number] {
  let minX = Infinity;
  let minY = Infinity;
  let maxX = -Infinity;
  let maxY = -Infinity;
  for (let k = 0; k < polygon.length; k += 2) {
    minX = Math.min(minX, polygon[k]);
    maxX = Math.max(maxX, polygon[k]);
    minY = Math.min(minY, polygon[k + 1]);
    maxY = Math.max(maxY, polygon[k + 1]);
  }
  return [minX, minY, maxX, maxY];
}
