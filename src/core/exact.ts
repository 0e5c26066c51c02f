/**
 * Exact Voronoi diagram of sites on a planar-family grid (plane or tube), computed with
 * d3-delaunay, with every cell's polygon: what the views draw (cell polygons, exact label
 * images), the measure comparison and the lab protocol's default surfaces use. The exact
 * engine (src/core/exactEngine) computes the same adjacency record without the polygons and is
 * tested against this independent implementation cell by cell; the test oracles proper live in
 * tests/oracles.
 *
 * Definitions and conventions:
 * - Sites are given in texel units (see `grid.ts`): interleaved x, y; x in [0, width),
 *   y in [0, height). Sites outside the domain are wrapped (periodic axis) or clamped (open axis).
 * - Distance is physical: coordinates are scaled to micrometres (x * texelX, y * texelY) before
 *   the triangulation and scaled back afterwards, so anisotropic texels give the true Voronoi
 *   diagram of the physical metric.
 * - Periodic axes: every site is copied at offsets -L, 0, +L along each periodic axis (3 copies
 *   for a tube, 3x3 = 9 when both axes are periodic). The diagram of the copies is computed and
 *   the cells of the originals (offset 0) are kept. A cell of an original lies within half a
 *   period of its site along a periodic axis, so these copies are enough.
 * - Clip box: along an open axis [0, L]; along a periodic axis [-L, 2L] (never reached by an
 *   original's cell).
 * - `polygon`: the cell's vertices in texel units, unwrapped around its site (they may lie
 *   outside [0, width) across a periodic seam), counter-clockwise in the (x right, y up)
 *   sense, not closed (the first vertex is not repeated).
 * - `area`: physical area in µm² (texel-unit area times texelX * texelY).
 * - `centroid`: area centroid in texel units, wrapped back into the domain along periodic axes.
 * - Neighbours: ids of original sites whose cells share an edge of positive length with this
 *   cell (through any periodic copy), deduplicated; `lengths` is the total shared edge length in
 *   µm (summed over every copy it is shared with). A cell is never listed as its own neighbour:
 *   when the domain is so small that a cell touches its own periodic copy, the shared length is
 *   reported in `selfContact` instead (0 otherwise).
 * - `border`: bit mask of the open domain edges the cell touches with an edge of positive
 *   length, in core/border.ts's convention: BORDER_Y_START (y = 0), BORDER_Y_END (y = height),
 *   BORDER_X_START (x = 0), BORDER_X_END (x = width); x bits only when x is open, y bits only
 *   when y is open. For a tube (periodic x, open y) a non-zero mask is "touches an open end of
 *   the tube".
 * - `edgeCount`: number of polygon edges of positive length shared with other cells (copies
 *   included, self-copies included); equal to the neighbour count except in tiny periodic
 *   domains where a cell shares several edges with the same site.
 * - Duplicate sites: d3-delaunay gives the later duplicate no cell; it gets an empty polygon,
 *   area 0 and no neighbours.
 */
import { BORDER_X_END, BORDER_X_START, BORDER_Y_END, BORDER_Y_START } from './border';
import { Delaunay } from 'd3-delaunay';
import type { Grid } from './grid';
import { wrapCoordinate } from './grid';
import type { SurfaceAdjacency } from './analysis/adjacency';

interface ExactCell {
  /** Site id. */
  readonly id: number;
  /** Vertices in texel units, interleaved x, y, unwrapped around the site, counter-clockwise. */
  readonly polygon: Float64Array;
  /** Physical area in µm². */
  readonly area: number;
  /** Centroid x in texel units, wrapped into the domain. */
  readonly centroidX: number;
  /** Centroid y in texel units, wrapped into the domain. */
  readonly centroidY: number;
  /** Neighbour site ids, ascending, never the cell itself. */
  readonly neighbours: Int32Array;
  /** Shared edge length in µm per neighbour. */
  readonly lengths: Float64Array;
  /** Length in µm of edges shared with the cell's own periodic copies (tiny domains only). */
  readonly selfContact: number;
  /** Number of positive-length edges shared with other cells (including copies). */
  readonly edgeCount: number;
  /** BORDER_* bits of the open edges the cell touches (src/core/border.ts). */
  readonly border: number;
}

export interface ExactVoronoi {
  readonly grid: Grid;
  readonly count: number;
  readonly cells: ExactCell[];
  /** The cells' neighbours, contact lengths, areas and border bits: the analysis input. */
  readonly adjacency: SurfaceAdjacency;
  /** Centroids in texel units, interleaved x, y, wrapped into the domain. */
  readonly centroids: Float64Array;
}

/** Exact Voronoi diagram of `sites` (interleaved x, y in texel units) on `grid`. */
export function exactVoronoi(grid: Grid, sites: Float32Array | Float64Array | ArrayLike<number>): ExactVoronoi {
  const copies = periodicCopies(grid, sites);
  const { n, px, py, box } = copies;
  const delaunay = new Delaunay(copies.points);
  const voronoi = delaunay.voronoi([box.x0, box.y0, box.x1, box.y1]);

  const cells: ExactCell[] = [];
  for (let i = 0; i < n; i++) {
    const ring = n > 0 ? cellRing(voronoi.cellPolygon(i)) : null;
    cells.push(ring ? measuredCell(grid, copies, delaunay, i, ring) : emptyCell(grid, i, px[i], py[i]));
  }

  const centroids = new Float64Array(2 * n);
  for (const cell of cells) {
    centroids[2 * cell.id] = cell.centroidX;
    centroids[2 * cell.id + 1] = cell.centroidY;
  }
  return { grid, count: n, cells, adjacency: adjacencyOf(cells), centroids };
}

/** The sites in µm and their periodic copies, ready for the triangulation. */
interface PeriodicCopies {
  /** Number of original sites. */
  readonly n: number;
  /** Physical coordinates of the originals (wrapped / clamped into the domain). */
  readonly px: Float64Array;
  readonly py: Float64Array;
  /** Copy c of site i is point c * n + i (interleaved x, y); copy 0 is the original. */
  readonly points: Float64Array;
  /** Clip box: [0, L] along an open axis, [-L, 2L] along a periodic one. */
  readonly box: { readonly x0: number; readonly x1: number; readonly y0: number; readonly y1: number };
  /** Lengths below this are rounding (edges of zero length, vertices on the clip box). */
  readonly eps: number;
}

/** Step 1: physical coordinates of the sites and their copies at -L, 0, +L along periodic axes. */
function periodicCopies(grid: Grid, sites: Float32Array | Float64Array | ArrayLike<number>): PeriodicCopies {
  const n = Math.floor(sites.length / 2);
  const sx = grid.texelX;
  const sy = grid.texelY;
  const W = grid.width * sx;
  const H = grid.height * sy;
  const offsetsX = grid.periodicX ? [0, -W, W] : [0];
  const offsetsY = grid.periodicY ? [0, -H, H] : [0];
  const copies = offsetsX.length * offsetsY.length;

  const px = new Float64Array(n);
  const py = new Float64Array(n);
  for (let i = 0; i < n; i++) {
    px[i] = wrapCoordinate(sites[2 * i], grid.width, grid.periodicX) * sx;
    py[i] = wrapCoordinate(sites[2 * i + 1], grid.height, grid.periodicY) * sy;
  }
  const points = new Float64Array(2 * n * copies);
  let c = 0;
  for (const oy of offsetsY) {
    for (const ox of offsetsX) {
      for (let i = 0; i < n; i++) {
        points[2 * (c * n + i)] = px[i] + ox;
        points[2 * (c * n + i) + 1] = py[i] + oy;
      }
      c++;
    }
  }
  const box = {
    x0: grid.periodicX ? -W : 0,
    x1: grid.periodicX ? 2 * W : W,
    y0: grid.periodicY ? -H : 0,
    y1: grid.periodicY ? 2 * H : H,
  };
  return { n, px, py, points, box, eps: 1e-9 * Math.max(W, H, 1) };
}

/** A cell's vertices in µm, not closed. */
interface Ring {
  vx: Float64Array;
  vy: Float64Array;
  m: number;
}

/** Step 2: d3's clipped cell polygon as a ring (d3 repeats the first vertex last: dropped); null for no cell. */
function cellRing(raw: ArrayLike<ArrayLike<number>> | null): Ring | null {
  if (!raw || raw.length < 4) return null;
  const m = raw.length - 1;
  const vx = new Float64Array(m);
  const vy = new Float64Array(m);
  for (let k = 0; k < m; k++) {
    vx[k] = raw[k][0];
    vy[k] = raw[k][1];
  }
  return { vx, vy, m };
}

/** A site that has no cell (a later duplicate): empty polygon, area 0, centroid at the site. */
function emptyCell(grid: Grid, i: number, xi: number, yi: number): ExactCell {
  return {
    id: i,
    polygon: new Float64Array(0),
    area: 0,
    centroidX: xi / grid.texelX,
    centroidY: yi / grid.texelY,
    neighbours: new Int32Array(0),
    lengths: new Float64Array(0),
    selfContact: 0,
    edgeCount: 0,
    border: 0,
  };
}

/** Steps 3 and 4: orient and measure the cell of site i, then sum its contacts. */
function measuredCell(grid: Grid, copies: PeriodicCopies, delaunay: Delaunay<unknown>, i: number, ring: Ring): ExactCell {
  const sx = grid.texelX;
  const sy = grid.texelY;
  const { area, centroidPhysX, centroidPhysY } = orientAndMeasure(ring, copies.px[i], copies.py[i]);
  const contacts = contactLengths(grid, copies, Array.from(delaunay.neighbors(i)), i, ring);
  const ids = [...contacts.lengthById.keys()].sort((p, q) => p - q);
  const { vx, vy, m } = ring;
  const polygon = new Float64Array(2 * m);
  for (let k = 0; k < m; k++) {
    polygon[2 * k] = vx[k] / sx;
    polygon[2 * k + 1] = vy[k] / sy;
  }
  return {
    id: i,
    polygon,
    area,
    centroidX: wrapCoordinate(centroidPhysX / sx, grid.width, grid.periodicX),
    centroidY: wrapCoordinate(centroidPhysY / sy, grid.height, grid.periodicY),
    neighbours: Int32Array.from(ids),
    lengths: Float64Array.from(ids.map((id) => contacts.lengthById.get(id)!)),
    selfContact: contacts.selfContact,
    edgeCount: contacts.edgeCount,
    border: contacts.border,
  };
}

/**
 * Step 3: turns the ring counter-clockwise (in place) and gives its area and centroid in µm
 * (shoelace, relative to the site (xi, yi) for precision).
 */
function orientAndMeasure(ring: Ring, xi: number, yi: number): { area: number; centroidPhysX: number; centroidPhysY: number } {
  const { vx, vy, m } = ring;
  let a2 = 0;
  let cx = 0;
  let cy = 0;
  for (let k = 0; k < m; k++) {
    const ax = vx[k] - xi;
    const ay = vy[k] - yi;
    const bx = vx[(k + 1) % m] - xi;
    const by = vy[(k + 1) % m] - yi;
    const cross = ax * by - bx * ay;
    a2 += cross;
    cx += (ax + bx) * cross;
    cy += (ay + by) * cross;
  }
  if (a2 < 0) {
    vx.reverse();
    vy.reverse();
    a2 = -a2;
    cx = -cx;
    cy = -cy;
  }
  const area = a2 / 2;
  return {
    area,
    centroidPhysX: area > 0 ? xi + cx / (3 * a2) : xi,
    centroidPhysY: area > 0 ? yi + cy / (3 * a2) : yi,
  };
}

/** What the edges of one cell touch. */
interface Contacts {
  /** µm shared with each other original site (summed over its copies). */
  lengthById: Map<number, number>;
  selfContact: number;
  edgeCount: number;
  border: number;
}

/**
 * Step 4: walks the cell's edges: an edge on the clip box marks an open domain edge (bits of
 * border), any other edge is shared with the site across it, whose length is added to that
 * site's contact (or to selfContact when it is a copy of the cell's own site).
 */
function contactLengths(grid: Grid, copies: PeriodicCopies, candidates: number[], i: number, ring: Ring): Contacts {
  const { box, eps, n } = copies;
  const { vx, vy, m } = ring;
  const contacts: Contacts = { lengthById: new Map<number, number>(), selfContact: 0, edgeCount: 0, border: 0 };
  for (let k = 0; k < m; k++) {
    const ax = vx[k];
    const ay = vy[k];
    const bx = vx[(k + 1) % m];
    const by = vy[(k + 1) % m];
    const len = Math.hypot(bx - ax, by - ay);
    if (len <= eps) continue;
    const border = clipBoxSide(grid, box, eps, ax, ay, bx, by);
    if (border !== null) {
      contacts.border |= border;
      continue;
    }
    const best = siteAcrossEdge(copies, candidates, i, (ax + bx) / 2, (ay + by) / 2);
    if (best < 0) continue;
    contacts.edgeCount++;
    const id = best % n;
    if (id === i) contacts.selfContact += len;
    else contacts.lengthById.set(id, (contacts.lengthById.get(id) ?? 0) + len);
  }
  return contacts;
}

/**
 * For an edge lying on the clip box: the border bit of that side (0 along a periodic axis,
 * whose box side no original's cell reaches); null for an edge inside the box.
 */
function clipBoxSide(grid: Grid, box: PeriodicCopies['box'], eps: number, ax: number, ay: number, bx: number, by: number): number | null {
  if (Math.abs(ay - box.y0) <= eps && Math.abs(by - box.y0) <= eps) return grid.periodicY ? 0 : BORDER_Y_START;
  if (Math.abs(ay - box.y1) <= eps && Math.abs(by - box.y1) <= eps) return grid.periodicY ? 0 : BORDER_Y_END;
  if (Math.abs(ax - box.x0) <= eps && Math.abs(bx - box.x0) <= eps) return grid.periodicX ? 0 : BORDER_X_START;
  if (Math.abs(ax - box.x1) <= eps && Math.abs(bx - box.x1) <= eps) return grid.periodicX ? 0 : BORDER_X_END;
  return null;
}

/**
 * The point (copy) across the edge with midpoint (mx, my) from site i: among i's Delaunay
 * neighbours, the one whose bisector with i passes closest to the midpoint; -1 if none.
 */
function siteAcrossEdge(copies: PeriodicCopies, candidates: number[], i: number, mx: number, my: number): number {
  const { points } = copies;
  const xi = copies.px[i];
  const yi = copies.py[i];
  let best = -1;
  let bestDist = Infinity;
  for (const j of candidates) {
    const qx = points[2 * j];
    const qy = points[2 * j + 1];
    const dx = qx - xi;
    const dy = qy - yi;
    const dl = Math.hypot(dx, dy);
    if (dl === 0) continue;
    const dist = Math.abs(dx * (mx - (xi + qx) / 2) + dy * (my - (yi + qy) / 2)) / dl;
    if (dist < bestDist) {
      bestDist = dist;
      best = j;
    }
  }
  return best;
}

/** Step 5: every cell's neighbours, contact lengths, area and border bits in one adjacency record. */
function adjacencyOf(cells: readonly ExactCell[]): SurfaceAdjacency {
  const n = cells.length;
  const areas = new Float64Array(n);
  const border = new Uint8Array(n);
  for (const cell of cells) {
    areas[cell.id] = cell.area;
    border[cell.id] = cell.border;
  }
  const offsets = new Int32Array(n + 1);
  for (let i = 0; i < n; i++) offsets[i + 1] = offsets[i] + cells[i].neighbours.length;
  const neighbours = new Int32Array(offsets[n]);
  const lengths = new Float64Array(offsets[n]);
  for (let i = 0; i < n; i++) {
    neighbours.set(cells[i].neighbours, offsets[i]);
    lengths.set(cells[i].lengths, offsets[i]);
  }
  return { count: n, offsets, neighbours, lengths, areas, border };
}
