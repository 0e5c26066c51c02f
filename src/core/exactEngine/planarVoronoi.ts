/**
 * The exact Voronoi diagram of sites on a planar-family grid (plane, tube, torus), rebuilt in
 * place for every Lloyd iteration: one Delaunay triangulation (Triangulation, a port of the
 * Delaunator that d3-delaunay uses, into kept buffers), cells walked around each site's Delaunay
 * fan into reusable buffers. Same definitions as `exactVoronoi` (src/core/exact.ts, d3-delaunay),
 * the source of the full cell records; this class is the allocation-free hot path of the exact
 * engine and of sweeps, and is tested against that independent implementation cell by cell.
 *
 * - Physical metric: coordinates are scaled to µm (x * texelX, y * texelY) before triangulating.
 * - Periodic axes: the sites (points 0 .. n-1) and their periodic copies that lie within a margin
 *   of the domain along each periodic axis (the "ghost band": a site within `margin` of x = 0 is
 *   copied at x + L, one within `margin` of x = L at x - L, and both ways in the corners of a
 *   torus). The triangulation then holds every point of the infinite periodic set inside the box
 *   [-margin, L + margin) (along open axes: everything), and nothing outside it.
 *   Every cell of an original is certified as it is walked: for each of its vertices v, no point
 *   outside the box is closer to v than its site (the disk around v through the site stays in
 *   the box), so no missing copy can cut the cell (a cell is convex: a half-plane that misses
 *   every vertex misses the cell). A pass over the cells that finds an uncertified one doubles
 *   the margin and rebuilds (`retry()`); at a margin of L the band is the three copies per axis
 *   (-L, 0, +L) that exactVoronoi triangulates, and cells are taken as they are, as there.
 *   The margin starts at 4 mean site spacings: about 1.6 % extra points at 1,000,000 sites on a
 *   periodic plane where the full copies were 800 %.
 * - Open axes: a cell is the Voronoi cell clipped to [0, L]. Cells of sites on the hull of the
 *   points are unbounded: their two rays are cut at a far distance (1e4 domain sizes) before
 *   clipping, so the far edges are always clipped away.
 * - `cellAt(k, out)` writes the cell of the k-th site in the spatial order (site siteAt(k)) as a
 *   labelled polygon relative to its site (µm): the label of an edge is the site across it (j for
 *   an original, n + j for a copy of site j: label % n is the site id), or a negative code for a
 *   domain edge (the EDGE_* constants). Labels of edges of zero length are kept; callers filter with
 *   `epsilon`.
 * - Degenerate input (no triangle that is not flat, as d3-delaunay's collinear test) falls back
 *   to exactVoronoi for polygons (then every edge is labelled FAR: no neighbours are read from it).
 */
import { exactVoronoi } from '../exact';
import { wrapCoordinate, type Grid } from '../grid';
import { Triangulation } from './delaunay';
import { restoreDelaunay } from './delaunayFlip';
import { clipHalfPlane, PolygonBuffer } from './polygon';

/** Edge labels of domain edges and of far (clipped-away) ray edges. */
export const EDGE_Y0 = -1;
export const EDGE_Y1 = -2;
export const EDGE_X0 = -3;
export const EDGE_X1 = -4;
export const EDGE_FAR = -5;

/** First margin of the ghost band, in mean site spacings (sqrt(area / sites)). */
const MARGIN_SPACINGS = 4;

/**
 * The first band of a diagram that serves a chain of layers (`layers` in the constructor): its
 * later layers keep the first one's copies (build with `continues`), and on a tube widened layer
 * after layer a band's share of the circumference that certifies one layer certifies the wider
 * ones, so the first band can be narrower (a sweep's layers: about 30 % fewer points, a band
 * widened in about 0.3 % of the layers).
 */
const LAYER_MARGIN_SPACINGS = 2;

/** Which periodic copies of a site the band holds, one bit each: at +L (site near 0) and -L (near L) per axis. */
const COPY = { xPlus: 1, xMinus: 2, yPlus: 4, yMinus: 8 } as const;

export class PlanarVoronoi {
  readonly count: number;
  /** Physical positions of the originals (µm), wrapped or clamped into the domain. */
  readonly siteX: Float64Array;
  readonly siteY: Float64Array;
  /** Shortest edge length (µm) that counts as a contact: 1e-9 of the domain, as in exactVoronoi. */
  epsilon = 0;
  widthUm = 0;
  heightUm = 0;
  /** Ghost band along each periodic axis (µm; see the module comment); L means all copies. */
  marginX = 0;
  marginY = 0;
  /** The band every build starts from (so a diagram depends on the grid and the sites only). */
  private baseMarginX = 0;
  private baseMarginY = 0;
  /** Points of the last triangulation: the n sites, then their copies in the band. */
  pointCount = 0;
  /** Rebuilds forced by an uncertified cell since construction (for tests and benchmarks). */
  retries = 0;
  /**
   * Site of original point p (points are the sites in a spatial order: by distance from the
   * domain's centre, in rings of about one site, the order the triangulation inserts them, so
   * the triangulation and a walk over the cells in this order read recent memory).
   */
  private readonly order: Int32Array;
  /** Each site's ring (sortSpatially's scratch). */
  private readonly bucketOf: Int32Array;
  private bucketStart = new Int32Array(0);
  /** A diagram of siteX, siteY on this grid is built. */
  private built = false;
  private points = new Float64Array(0);
  /** Site of copy k (point n + k), and its shift in domain sizes along x and y (-1, 0, 1). */
  private source = new Int32Array(0);
  private shiftX = new Int8Array(0);
  private shiftY = new Int8Array(0);
  /** Per site, which copies the band holds: COPY_* bits. */
  private readonly copies: Uint8Array;
  /** The triangulation is one of the current points (no fallback): a next build may move it. */
  private movable = false;
  /** Builds that moved the previous triangulation instead of triangulating (for tests and benchmarks). */
  moved = 0;
  private readonly triangulation = new Triangulation();
  private ccx = 0;
  private ccy = 0;
  private fallback: Float64Array[] | null = null;
  private far = 0;
  private uncertified = false;
  private sites: ArrayLike<number> | null = null;
  private readonly ping = new PolygonBuffer();
  private readonly pong = new PolygonBuffer();

  /** `layers`: the diagram will serve a chain of layers (LAYER_MARGIN_SPACINGS). */
  constructor(
    public grid: Grid,
    count: number,
    private readonly layers = false,
  ) {
    this.count = count;
    this.siteX = new Float64Array(count);
    this.siteY = new Float64Array(count);
    this.order = new Int32Array(count);
    this.bucketOf = new Int32Array(count);
    this.copies = new Uint8Array(count);
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
    const old = this.grid;
    if (grid.width !== old.width || grid.height !== old.height || grid.texelX !== old.texelX || grid.texelY !== old.texelY) this.built = false;
    this.grid = grid;
    this.widthUm = grid.width * grid.texelX;
    this.heightUm = grid.height * grid.texelY;
    this.epsilon = 1e-9 * Math.max(this.widthUm, this.heightUm, 1);
    this.far = 1e4 * (this.widthUm + this.heightUm);
    const spacing = Math.sqrt((this.widthUm * this.heightUm) / Math.max(this.count, 1));
    const spacings = this.layers ? LAYER_MARGIN_SPACINGS : MARGIN_SPACINGS;
    this.baseMarginX = Math.min(this.widthUm, spacings * spacing);
    this.baseMarginY = Math.min(this.heightUm, spacings * spacing);
    return this;
  }

  /**
   * Triangulates `sites` (interleaved x, y texel units); reuses every buffer after the first call.
   * Sites equal to the last build's on the same grid keep the diagram as it is (nothing is
   * recomputed: e.g. the final Lloyd sites, then the seeded surface's adjacency of the same sites).
   *
   * `continues`: the sites are the last build's moved a little (the next layer of a tube: the
   * same sites, the circumference scaled), so the last triangulation, its points moved, is made
   * Delaunay again by edge flips (delaunayFlip.ts) where it is still a valid triangulation, with
   * the same periodic copies; else, and without `continues`, the sites are triangulated afresh.
   * Either way the diagram is the exact one of the sites on the grid: the same cells and
   * neighbours, contact lengths and areas equal to rounding (tested).
   */
  build(sites: ArrayLike<number>, continues = false): this {
    const { grid, count: n, siteX, siteY } = this;
    let same = this.built;
    for (let i = 0; i < n; i++) {
      const x = wrapCoordinate(sites[2 * i], grid.width, grid.periodicX) * grid.texelX;
      const y = wrapCoordinate(sites[2 * i + 1], grid.height, grid.periodicY) * grid.texelY;
      if (x !== siteX[i] || y !== siteY[i]) {
        same = false;
        siteX[i] = x;
        siteY[i] = y;
      }
    }
    this.sites = sites;
    if (same) return this;
    this.built = true;
    if (continues && this.movable && this.move()) return this;
    this.sortSpatially();
    this.marginX = this.baseMarginX;
    this.marginY = this.baseMarginY;
    return this.triangulate();
  }

  /**
   * After a pass over every cell: false when every cell was certified (the diagram is exact);
   * else widens the band, triangulates again and returns true (the caller walks the cells again).
   */
  retry(): boolean {
    if (!this.uncertified) return false;
    // (After a move the band can be narrow: widen it to at least the first band.)
    this.marginX = Math.min(this.widthUm, Math.max(2 * this.marginX, this.baseMarginX));
    this.marginY = Math.min(this.heightUm, Math.max(2 * this.marginY, this.baseMarginY));
    this.retries++;
    this.triangulate();
    return true;
  }

  private triangulate(): this {
    const n = this.count;
    this.fallback = null;
    this.uncertified = false;
    this.pointCount = this.placePoints();
    this.movable = false;
    if (n === 0) return this;
    this.triangulation.triangulate(this.points, this.pointCount);
    this.movable = !this.isCollinear();
    if (!this.movable) this.useFallback(this.sites!);
    return this;
  }

  /**
   * The points of the last triangulation moved to the new sites (same order, same copies), and
   * the triangulation flipped to Delaunay; false where it cannot be (then build triangulates).
   * The band is then whatever the copies cover on this grid: the widest margin such that every
   * copy inside the box [-margin, L + margin) is a point (certification checks against it).
   */
  private move(): boolean {
    const { count: n, siteX, siteY, order, source, shiftX, shiftY, copies, points, widthUm: W, heightUm: H } = this;
    for (let k = 0; k < n; k++) {
      points[2 * k] = siteX[order[k]];
      points[2 * k + 1] = siteY[order[k]];
    }
    for (let p = n; p < this.pointCount; p++) {
      const i = source[p - n];
      points[2 * p] = siteX[i] + shiftX[p - n] * W;
      points[2 * p + 1] = siteY[i] + shiftY[p - n] * H;
    }
    let marginX = W;
    let marginY = H;
    for (let i = 0; i < n; i++) {
      const c = copies[i];
      if (!(c & COPY.xPlus)) marginX = Math.min(marginX, siteX[i]);
      if (!(c & COPY.xMinus)) marginX = Math.min(marginX, W - siteX[i]);
      if (!(c & COPY.yPlus)) marginY = Math.min(marginY, siteY[i]);
      if (!(c & COPY.yMinus)) marginY = Math.min(marginY, H - siteY[i]);
    }
    this.marginX = marginX;
    this.marginY = marginY;
    this.fallback = null;
    this.uncertified = false;
    this.movable = restoreDelaunay(this.triangulation, points);
    if (this.movable) this.moved++;
    return this.movable;
  }

  /**
   * The site of the k-th cell in the spatial order (k = 0 .. count - 1): walking the cells in this
   * order is several times faster on large diagrams than in id order (cache; 1M sites: 0.55 s
   * against 2.4 s, and 0.9 s in rows of buckets).
   */
  siteAt(k: number): number {
    return this.order[k];
  }

  /** Counting sort of the sites into rings around the centre, stable in id: order. */
  private sortSpatially(): void {
    const { count: n, siteX, siteY, order, bucketOf, widthUm: W, heightUm: H } = this;
    // Rings around the domain's centre, about one site per bucket: the order in which the
    // triangulation inserts points (by distance from a centre), so the triangles of nearby rings
    // are made together, and walking the cells in this order reads recent memory.
    const buckets = Math.max(1, n);
    if (this.bucketStart.length < buckets + 1) this.bucketStart = new Int32Array(buckets + 1);
    const start = this.bucketStart;
    start.fill(0, 0, buckets + 1);
    const cx = W / 2;
    const cy = H / 2;
    const scale = buckets / (cx * cx + cy * cy || 1);
    // The bucket of each site, kept for the second pass.
    for (let i = 0; i < n; i++) {
      const dx = siteX[i] - cx;
      const dy = siteY[i] - cy;
      const bucket = Math.min(buckets - 1, Math.floor((dx * dx + dy * dy) * scale));
      bucketOf[i] = bucket;
      start[bucket + 1]++;
    }
    for (let b = 0; b < buckets; b++) start[b + 1] += start[b];
    for (let i = 0; i < n; i++) {
      order[start[bucketOf[i]]++] = i;
    }
  }

  /** Writes the sites (in spatial order) and their copies in the band to `points`; returns the point count. */
  private placePoints(): number {
    const { grid, count: n, siteX, siteY, widthUm: W, heightUm: H, marginX, marginY } = this;
    const px = grid.periodicX;
    const py = grid.periodicY;
    let total = n;
    if (px || py) {
      for (let i = 0; i < n; i++) {
        const cx = px ? (siteX[i] < marginX ? 1 : 0) + (siteX[i] >= W - marginX ? 1 : 0) : 0;
        const cy = py ? (siteY[i] < marginY ? 1 : 0) + (siteY[i] >= H - marginY ? 1 : 0) : 0;
        total += (cx + 1) * (cy + 1) - 1;
      }
    }
    if (this.points.length < 2 * total) this.points = new Float64Array(2 * Math.ceil(total * 1.1));
    if (this.source.length < total - n) {
      this.source = new Int32Array(Math.ceil((total - n) * 1.25) + 16);
      this.shiftX = new Int8Array(this.source.length);
      this.shiftY = new Int8Array(this.source.length);
    }
    const { points, source, shiftX, shiftY, copies } = this;
    copies.fill(0);
    const order = this.order;
    for (let k = 0; k < n; k++) {
      points[2 * k] = siteX[order[k]];
      points[2 * k + 1] = siteY[order[k]];
    }
    let p = n;
    if (px || py) {
      for (let k = 0; k < n; k++) {
        const i = order[k];
        const x = siteX[i];
        const y = siteY[i];
        // Shifts along each axis: 0, then +L near 0, -L near L.
        const sx0 = px && x < marginX;
        const sx1 = px && x >= W - marginX;
        const sy0 = py && y < marginY;
        const sy1 = py && y >= H - marginY;
        if (!(sx0 || sx1 || sy0 || sy1)) continue;
        copies[i] = (sx0 ? COPY.xPlus : 0) | (sx1 ? COPY.xMinus : 0) | (sy0 ? COPY.yPlus : 0) | (sy1 ? COPY.yMinus : 0);
        for (let a = 0; a < 3; a++) {
          if ((a === 1 && !sx0) || (a === 2 && !sx1)) continue;
          const ox = a === 0 ? 0 : a === 1 ? W : -W;
          for (let b = 0; b < 3; b++) {
            if ((b === 1 && !sy0) || (b === 2 && !sy1) || (a === 0 && b === 0)) continue;
            const oy = b === 0 ? 0 : b === 1 ? H : -H;
            points[2 * p] = x + ox;
            points[2 * p + 1] = y + oy;
            source[p - n] = i;
            shiftX[p - n] = a === 0 ? 0 : a === 1 ? 1 : -1;
            shiftY[p - n] = b === 0 ? 0 : b === 1 ? 1 : -1;
            p++;
          }
        }
      }
    }
    return p;
  }

  /** The label of point p: the site for an original, n + site for a copy. */
  private labelOf(p: number): number {
    return p < this.count ? this.order[p] : this.count + this.source[p - this.count];
  }

  /** d3-delaunay's test: no triangle with a cross product above 1e-10 (also true for none). */
  private isCollinear(): boolean {
    const { triangles, length } = this.triangulation;
    const c = this.points;
    for (let e = 0; e < length; e += 3) {
      const a = 2 * triangles[e];
      const b = 2 * triangles[e + 1];
      const d = 2 * triangles[e + 2];
      const cross = (c[d] - c[a]) * (c[b + 1] - c[a + 1]) - (c[b] - c[a]) * (c[d + 1] - c[a + 1]);
      if (cross > 1e-10) return false;
    }
    return true;
  }

  /**
   * The cell of the k-th site in the spatial order (site siteAt(k), at (xAt(k), yAt(k)) µm) as a
   * labelled polygon relative to its site (µm), clipped to the domain: the fast way to walk every
   * cell (everything it reads is close in memory).
   */
  cellAt(k: number, out: PolygonBuffer): PolygonBuffer {
    out.clear();
    if (this.fallback) {
      const sx = this.points[2 * k];
      const sy = this.points[2 * k + 1];
      const poly = this.fallback[this.order[k]];
      for (let v = 0; v < poly.length / 2; v++) out.push(poly[2 * v] * this.grid.texelX - sx, poly[2 * v + 1] * this.grid.texelY - sy, EDGE_FAR);
      return out;
    }
    if (this.count === 0) return out;
    const raw = this.ping;
    if (!this.walk(k, raw)) return out;
    // The site's index, not its coordinates, is passed on: doubles passed to a call that is not
    // inlined are boxed, a heap allocation per cell of every layer of a sweep.
    this.clipToDomain(raw, out, k);
    this.certify(out, k);
    return out;
  }

  /** Position (µm, wrapped or clamped into the domain) of the k-th site in the spatial order. */
  xAt(k: number): number {
    return this.points[2 * k];
  }

  yAt(k: number): number {
    return this.points[2 * k + 1];
  }

  /**
   * Marks the pass uncertified unless, for every vertex v of the cell (relative to the `site`-th
   * site in the spatial order), the disk around v through the site lies inside the band's box
   * along each periodic axis whose margin is below L (see the module comment).
   */
  private certify(cell: PolygonBuffer, site: number): void {
    const checkX = this.grid.periodicX && this.marginX < this.widthUm;
    const checkY = this.grid.periodicY && this.marginY < this.heightUm;
    if (!(checkX || checkY) || this.uncertified) return;
    const xy = cell.xy;
    // A little slack against rounding: a copy exactly on the circle would tie, not cut.
    const slack = this.epsilon;
    const loX = -this.marginX + slack;
    const hiX = this.widthUm + this.marginX - slack;
    const loY = -this.marginY + slack;
    const hiY = this.heightUm + this.marginY - slack;
    const sx = this.points[2 * site];
    const sy = this.points[2 * site + 1];
    for (let k = 0; k < cell.count; k++) {
      const dx = xy[2 * k];
      const dy = xy[2 * k + 1];
      const r2 = dx * dx + dy * dy;
      if ((checkX && reachesBand(sx, dx, loX, hiX, r2)) || (checkY && reachesBand(sy, dy, loY, hiY, r2))) {
        this.uncertified = true;
        return;
      }
    }
  }

  /** The fan of point i: circumcenters in order, each labelled with the site across the next edge. */
  private walk(i: number, raw: PolygonBuffer): boolean {
    raw.clear();
    const { triangles, halfedges, inedges, length } = this.triangulation;
    const e0 = inedges[i];
    if (e0 < 0) return false;
    const onHull = halfedges[e0] === -1;
    if (onHull) {
      // Ray across the hull edge (p0, i), outward (away from the triangle's third vertex).
      const p0 = triangles[e0];
      const third = triangles[e0 % 3 === 0 ? e0 + 2 : e0 - 1];
      this.circumcenter((e0 / 3) | 0);
      this.pushRayEnd(raw, this.ccx, this.ccy, p0, i, third, this.labelOf(p0));
    }
    let e = e0;
    for (let guard = 0; guard < length; guard++) {
      const t = (e / 3) | 0;
      const next = e % 3 === 2 ? e - 2 : e + 1;
      if (triangles[next] !== i) return false;
      const across = triangles[e % 3 === 0 ? e + 2 : e - 1];
      this.circumcenter(t);
      const cx = this.ccx;
      const cy = this.ccy;
      raw.push(cx, cy, this.labelOf(across));
      const twin = halfedges[next];
      if (twin === -1) {
        // Last fan triangle on the hull: ray across (i, across), then close far away.
        const third = triangles[e];
        const end = raw.count;
        this.pushRayEnd(raw, cx, cy, i, across, third, EDGE_FAR);
        // A point on the bisector of both rays keeps the far closure outside the domain.
        const fx = raw.xy[2 * end];
        const fy = raw.xy[2 * end + 1];
        const gx = raw.xy[0];
        const gy = raw.xy[1];
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

  /** Clips a raw cell to the open axes and writes it relative to its site (the k-th in the spatial order). */
  private clipToDomain(raw: PolygonBuffer, out: PolygonBuffer, site: number): void {
    const { grid } = this;
    const sx = this.points[2 * site];
    const sy = this.points[2 * site + 1];
    let a = raw;
    let b = this.pong;
    // Most cells lie inside the open axes' range: clipping would keep every vertex as it is.
    let inside = true;
    for (let k = 0; k < raw.count && inside; k++) {
      const x = raw.xy[2 * k];
      const y = raw.xy[2 * k + 1];
      if ((!grid.periodicX && !(x >= 0 && x <= this.widthUm)) || (!grid.periodicY && !(y >= 0 && y <= this.heightUm))) inside = false;
    }
    if (inside) {
      for (let k = 0; k < raw.count; k++) out.push(raw.xy[2 * k] - sx, raw.xy[2 * k + 1] - sy, raw.labels[k]);
      return;
    }
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

  /**
   * Circumcentre of triangle t into (ccx, ccy), computed where the walk needs it (the triangle's
   * points are close in memory, a table of centres would not be): the same arithmetic, from the
   * same first vertex, as a table computed after the triangulation.
   */
  private circumcenter(t: number): void {
    const triangles = this.triangulation.triangles;
    const points = this.points;
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
      this.ccx = (x1 + points[i3]) / 2 - this.far * ey;
      this.ccy = (y1 + points[i3 + 1]) / 2 + this.far * ex;
      return;
    }
    const bl = dx * dx + dy * dy;
    const cl = ex * ex + ey * ey;
    this.ccx = x1 + (ey * bl - dy * cl) / ab;
    this.ccy = y1 + (dx * cl - ex * bl) / ab;
  }

  private useFallback(sites: ArrayLike<number>): void {
    const reference = exactVoronoi(this.grid, sites);
    this.fallback = reference.cells.map((cell) => cell.polygon);
  }
}

/** Whether the disk of squared radius r2 around s + d (one coordinate) is not strictly inside lo < x < hi. */
function reachesBand(s: number, d: number, lo: number, hi: number, r2: number): boolean {
  const a = s + d - lo;
  const b = hi - s - d;
  return a <= 0 || b <= 0 || a * a <= r2 || b * b <= r2;
}
