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
  return exactCell(grid, cells, id).polygon;
}

/**
 * cellOutline's polygon and the cell's neighbours: the ids whose bisector bounds it along an
 * edge of positive length (ascending), as the exact cells of the whole surface give them.
 */
export function exactCell(grid: Grid, cells: OutlineCells, id: number): { polygon: Float64Array; neighbours: number[] } {
  const widthUm = grid.width * grid.texelX;
  const heightUm = grid.height * grid.texelY;
  const [sx, sy] = cells.site(id);
  // The domain around the site: the whole surface, or one period centred on the site.
  const x0 = grid.periodicX ? sx - widthUm / 2 : 0;
  const y0 = grid.periodicY ? sy - heightUm / 2 : 0;
  // Each edge k (vertex k to k + 1) carries the site that made it; -1: the domain's edge.
  let clipped: Clipped = { points: [x0, y0, x0 + widthUm, y0, x0 + widthUm, y0 + heightUm, x0, y0 + heightUm], edges: [-1, -1, -1, -1] };
  const shiftsX = grid.periodicX ? [-widthUm, 0, widthUm] : [0];
  const shiftsY = grid.periodicY ? [-heightUm, 0, heightUm] : [0];
  for (const other of candidateIds(cells, id)) {
    const [ox, oy] = cells.site(other);
    for (const dx of shiftsX) {
      for (const dy of shiftsY) {
        clipped = clipCloser(clipped, sx, sy, ox + dx, oy + dy, other);
        if (clipped.points.length === 0) return { polygon: new Float64Array(0), neighbours: [] };
      }
    }
  }
  const { points, edges } = clipped;
  const polygon = new Float64Array(points.length);
  const neighbours = new Set<number>();
  // Edges shorter than this (µm) are where three cells meet at a point, not a contact.
  const tiny = 1e-9 * Math.max(widthUm, heightUm);
  for (let k = 0; k < points.length; k += 2) {
    polygon[k] = points[k] / grid.texelX;
    polygon[k + 1] = points[k + 1] / grid.texelY;
    const next = (k + 2) % points.length;
    if (edges[k / 2] >= 0 && Math.hypot(points[next] - points[k], points[next + 1] - points[k + 1]) > tiny) neighbours.add(edges[k / 2]);
  }
  return { polygon, neighbours: [...neighbours].sort((a, b) => a - b) };
}

/** A convex polygon (x, y pairs) and, per edge, the site that made it. */
interface Clipped {
  points: number[];
  edges: number[];
}

/** The part of convex `polygon` closer to (sx, sy) than to (ox, oy) (Sutherland-Hodgman); new edges carry `label`. */
function clipCloser(polygon: Clipped, sx: number, sy: number, ox: number, oy: number, label = -1): Clipped {
  const nx = ox - sx;
  const ny = oy - sy;
  if (nx === 0 && ny === 0) return polygon;
  // Inside where (p - m) . n <= 0, m the midpoint of the two sites.
  const c = (nx * (sx + ox) + ny * (sy + oy)) / 2;
  const side = (x: number, y: number) => nx * x + ny * y - c;
  const points: number[] = [];
  const edges: number[] = [];
  const { points: p, edges: e } = polygon;
  const count = p.length / 2;
  for (let k = 0; k < count; k++) {
    const ax = p[2 * k];
    const ay = p[2 * k + 1];
    const bx = p[(2 * k + 2) % p.length];
    const by = p[(2 * k + 3) % p.length];
    const fa = side(ax, ay);
    const fb = side(bx, by);
    const t = fa / (fa - fb);
    if (fa <= 0) {
      points.push(ax, ay);
      edges.push(e[k]);
      // Leaving: the edge from the crossing runs along the bisector.
      if (fb > 0 && fa < 0) {
        points.push(ax + t * (bx - ax), ay + t * (by - ay));
        edges.push(label);
      } else if (fb > 0) edges[edges.length - 1] = label;
    } else if (fb <= 0) {
      // Entering: the edge from the crossing is the rest of edge k.
      if (fb < 0) {
        points.push(ax + t * (bx - ax), ay + t * (by - ay));
        edges.push(e[k]);
      }
    }
  }
  return points.length >= 6 ? { points, edges } : { points: [], edges: [] };
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
