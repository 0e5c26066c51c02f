/**
 * The exact Voronoi diagram of sites on a planar-family grid (plane, tube, torus), rebuilt in
 * place for every Lloyd iteration: one d3-delaunay triangulation updated with `update()`, cells
 * walked around each site's Delaunay fan into reusable buffers. Same definitions as
 * `exactVoronoi` (src/core/exact.ts), which stays the reference and the source of the full cell
 * records; this class is the allocation-free hot path of the exact engine and of sweeps, and is
 * tested against it cell by cell.
 *
 * - Physical metric: coordinates are scaled to µm (x * texelX, y * texelY) before triangulating.
 * - Periodic axes: every site is copied at -L, 0, +L (copy c of site i is point c * n + i, the
 *   order of exactVoronoi); the cells of the originals are kept.
 * - Open axes: a cell is the Voronoi cell clipped to [0, L]. Cells of sites on the hull of the
 *   copies are unbounded: their two rays are cut at a far distance (1e4 domain sizes) before
 *   clipping, so the far edges are always clipped away.
 * - `cell(i, out)` writes cell i as a labelled polygon relative to its site (µm): the label of an
 *   edge is the point index (c * n + j) across it, or a negative code for a domain edge
 *   (BORDER_CODES). Labels of edges of zero length are kept; callers filter with `epsilon`.
 * - Degenerate input (fewer than 3 points that are not collinear) falls back to exactVoronoi
 *   for polygons (then every edge is labelled FAR: no neighbours are read from it).
 */
import { Delaunay } from 'd3-delaunay';
import { exactVoronoi } from '../exact';
import { wrapCoordinate, type Grid } from '../grid';
import { clipHalfPlane, PolygonBuffer } from './polygon';

/** Edge labels of domain edges and of far (clipped-away) ray edges. */
export const EDGE_Y0 = -1;
export const EDGE_Y1 = -2;
export const EDGE_X0 = -3;
export const EDGE_X1 = -4;
export const EDGE_FAR = -5;

export class PlanarVoronoi {
  readonly count: number;
  /** Physical positions of the originals (µm), wrapped or clamped into the domain. */
  readonly siteX: Float64Array;
  readonly siteY: Float64Array;
  /** Shortest edge length (µm) that counts as a contact: 1e-9 of the domain, as in exactVoronoi. */
  epsilon = 0;
  widthUm = 0;
  heightUm = 0;
  private readonly copies: number;
  private readonly offsetsX = [0, 0, 0];
  private readonly offsetsY = [0, 0, 0];
  private readonly points: Float64Array;
  private delaunay: Delaunay<number> | null = null;
  private circumcenters = new Float64Array(0);
  private fallback: Float64Array[] | null = null;
  private far = 0;
  private readonly ping = new PolygonBuffer();
  private readonly pong = new PolygonBuffer();

  constructor(public grid: Grid, count: number) {
    this.count = count;
    this.copies = (grid.periodicX ? 3 : 1) * (grid.periodicY ? 3 : 1);
    this.points = new Float64Array(2 * count * this.copies);
    this.siteX = new Float64Array(count);
    this.siteY = new Float64Array(count);
    this.setGrid(grid);
  }

  /**
   * Moves to another grid with the same periodic axes (e.g. the next layer of a tube, whose
   * width scales with the ratio), keeping every buffer.
   */
  setGrid(grid: Grid): this {
    if (grid.periodicX !== this.grid.periodicX || grid.periodicY !== this.grid.periodicY) {
      throw new Error('PlanarVoronoi.setGrid: the periodic axes must stay the same');
    }
    this.grid = grid;
    this.widthUm = grid.width * grid.texelX;
    this.heightUm = grid.height * grid.texelY;
    this.offsetsX[1] = -this.widthUm;
    this.offsetsX[2] = this.widthUm;
    this.offsetsY[1] = -this.heightUm;
    this.offsetsY[2] = this.heightUm;
    this.epsilon = 1e-9 * Math.max(this.widthUm, this.heightUm, 1);
    this.far = 1e4 * (this.widthUm + this.heightUm);
    return this;
  }

  /** Triangulates `sites` (interleaved x, y texel units); reuses every buffer after the first call. */
  build(sites: ArrayLike<number>): this {
    const { grid, count: n, points } = this;
    const copiesX = grid.periodicX ? 3 : 1;
    const copiesY = grid.periodicY ? 3 : 1;
    for (let i = 0; i < n; i++) {
      this.siteX[i] = wrapCoordinate(sites[2 * i], grid.width, grid.periodicX) * grid.texelX;
      this.siteY[i] = wrapCoordinate(sites[2 * i + 1], grid.height, grid.periodicY) * grid.texelY;
    }
    let c = 0;
    for (let cy = 0; cy < copiesY; cy++) {
      const oy = this.offsetsY[cy];
      for (let cx = 0; cx < copiesX; cx++) {
        const ox = this.offsetsX[cx];
        for (let i = 0; i < n; i++) {
          points[2 * (c * n + i)] = this.siteX[i] + ox;
          points[2 * (c * n + i) + 1] = this.siteY[i] + oy;
        }
        c++;
      }
    }
    this.fallback = null;
    if (n === 0) return this;
    if (this.delaunay) {
      // d3 jitters its points in place for collinear input: give it fresh coordinates.
      (this.delaunay.points as Float64Array).set(points);
      this.delaunay.update();
    } else {
      this.delaunay = new Delaunay(points.slice());
    }
    const d = this.delaunay;
    // d3-delaunay marks all-collinear input with a `collinear` array its typings do not declare.
    if (Reflect.get(d, 'collinear') || d.hull.length <= 2) {
      this.useFallback(sites);
      return this;
    }
    this.computeCircumcenters();
    return this;
  }

  /** Cell i as a labelled polygon relative to its site (µm), clipped to the domain. */
  cell(i: number, out: PolygonBuffer): PolygonBuffer {
    out.clear();
    if (this.fallback) {
      const poly = this.fallback[i];
      for (let k = 0; k < poly.length / 2; k++) {
        out.push(poly[2 * k] * this.grid.texelX - this.siteX[i], poly[2 * k + 1] * this.grid.texelY - this.siteY[i], EDGE_FAR);
      }
      return out;
    }
    const d = this.delaunay;
    if (!d) return out;
    const raw = this.ping;
    if (!this.walk(d, i, raw)) return out;
    this.clipToDomain(raw, out, this.siteX[i], this.siteY[i]);
    return out;
  }

  /** The fan of site i: circumcenters in order, each labelled with the point across the next edge. */
  private walk(d: Delaunay<number>, i: number, raw: PolygonBuffer): boolean {
    raw.clear();
    const { triangles, halfedges, inedges } = d;
    const cc = this.circumcenters;
    const e0 = inedges[i];
    if (e0 < 0) return false;
    const onHull = halfedges[e0] === -1;
    if (onHull) {
      // Ray across the hull edge (p0, i), outward (away from the triangle's third vertex).
      const t = (e0 / 3) | 0;
      const p0 = triangles[e0];
      const third = triangles[e0 % 3 === 0 ? e0 + 2 : e0 - 1];
      this.pushRayEnd(raw, cc[2 * t], cc[2 * t + 1], p0, i, third, p0);
    }
    let e = e0;
    for (let guard = 0; guard < triangles.length; guard++) {
      const t = (e / 3) | 0;
      const next = e % 3 === 2 ? e - 2 : e + 1;
      if (triangles[next] !== i) return false;
      const across = triangles[e % 3 === 0 ? e + 2 : e - 1];
      raw.push(cc[2 * t], cc[2 * t + 1], across);
      const twin = halfedges[next];
      if (twin === -1) {
        // Last fan triangle on the hull: ray across (i, across), then close far away.
        const third = triangles[e];
        const end = raw.count;
        this.pushRayEnd(raw, cc[2 * t], cc[2 * t + 1], i, across, third, EDGE_FAR);
        // A point on the bisector of both rays keeps the far closure outside the domain.
        const fx = raw.xy[2 * end];
        const fy = raw.xy[2 * end + 1];
        const gx = raw.xy[0];
        const gy = raw.xy[1];
        const cx = cc[2 * t];
        const cy = cc[2 * t + 1];
        let mx = fx - cx + (gx - cx);
        let my = fy - cy + (gy - cy);
        const len = Math.hypot(mx, my);
        if (len > 0) {
          mx = (mx / len) * this.far;
          my = (my / len) * this.far;
          raw.push(cx + mx, cy + my, EDGE_FAR);
        }
        return raw.count >= 3;
      }
      e = twin;
      if (e === e0) return raw.count >= 3;
    }
    return false;
  }

  /** Pushes the far end of the ray from (cx, cy) perpendicular to edge (a, b), away from `third`. */
  private pushRayEnd(raw: PolygonBuffer, cx: number, cy: number, a: number, b: number, third: number, label: number): void {
    const p = this.points;
    const ex = p[2 * b] - p[2 * a];
    const ey = p[2 * b + 1] - p[2 * a + 1];
    let nx = ey;
    let ny = -ex;
    const tx = p[2 * third] - p[2 * a];
    const ty = p[2 * third + 1] - p[2 * a + 1];
    if (nx * tx + ny * ty > 0) {
      nx = -nx;
      ny = -ny;
    }
    const len = Math.hypot(nx, ny);
    raw.push(cx + (nx / len) * this.far, cy + (ny / len) * this.far, label);
  }

  /** Clips a raw cell to the open axes and writes it relative to the site. */
  private clipToDomain(raw: PolygonBuffer, out: PolygonBuffer, sx: number, sy: number): void {
    const { grid } = this;
    let a = raw;
    let b = this.pong;
    if (!grid.periodicY) {
      clipHalfPlane(a, b, 1, 0, 1, EDGE_Y0);
      [a, b] = [b, a];
      clipHalfPlane(a, b, 1, this.heightUm, -1, EDGE_Y1);
      [a, b] = [b, a];
    }
    if (!grid.periodicX) {
      clipHalfPlane(a, b, 0, 0, 1, EDGE_X0);
      [a, b] = [b, a];
      clipHalfPlane(a, b, 0, this.widthUm, -1, EDGE_X1);
      [a, b] = [b, a];
    }
    for (let k = 0; k < a.count; k++) out.push(a.xy[2 * k] - sx, a.xy[2 * k + 1] - sy, a.labels[k]);
  }

  private computeCircumcenters(): void {
    const { triangles } = this.delaunay!;
    const points = this.delaunay!.points;
    const nt = triangles.length / 3;
    if (this.circumcenters.length < 2 * nt) this.circumcenters = new Float64Array(2 * Math.ceil(nt * 1.25));
    const cc = this.circumcenters;
    for (let t = 0; t < nt; t++) {
      const i1 = 2 * triangles[3 * t];
      const i2 = 2 * triangles[3 * t + 1];
      const i3 = 2 * triangles[3 * t + 2];
      const x1 = points[i1];
      const y1 = points[i1 + 1];
      const dx = points[i2] - x1;
      const dy = points[i2 + 1] - y1;
      const ex = points[i3] - x1;
      const ey = points[i3 + 1] - y1;
      const ab = (dx * ey - dy * ex) * 2;
      if (Math.abs(ab) < 1e-12 * (dx * dx + dy * dy + ex * ex + ey * ey)) {
        // Degenerate sliver: its circumcentre is far along the perpendicular (as d3-delaunay does).
        cc[2 * t] = (x1 + points[i3]) / 2 - this.far * ey;
        cc[2 * t + 1] = (y1 + points[i3 + 1]) / 2 + this.far * ex;
        continue;
      }
      const bl = dx * dx + dy * dy;
      const cl = ex * ex + ey * ey;
      cc[2 * t] = x1 + (ey * bl - dy * cl) / ab;
      cc[2 * t + 1] = y1 + (dx * cl - ex * bl) / ab;
    }
  }

  private useFallback(sites: ArrayLike<number>): void {
    const reference = exactVoronoi(this.grid, sites);
    this.fallback = reference.cells.map((cell) => cell.polygon);
  }
}
