/**
 * Delaunay triangulation of a variable number of points into buffers that are kept between
 * calls: the exact engine's triangulation, rebuilt every Lloyd iteration with no allocation
 * (arrays grow only when the point count exceeds every earlier one).
 *
 * The algorithm is Delaunator 5.1 (Mapbox, ISC licence; the library d3-delaunay 6 triangulates
 * with), ported line for line: a sweep-hull insertion in order of distance from a seed
 * triangle's circumcentre, Lawson flips with the same non-robust in-circle test, robust
 * orientation tests (robust-predicates' orient2d), near-duplicate points skipped (a later
 * duplicate gets no triangle). Same input, same triangles, half-edges and order as Delaunator.
 * Delaunator sizes its arrays by `coords.length` and cannot take fewer points than it was built
 * for; the exact engine's point count changes every iteration (periodic copies of the sites
 * near a seam), hence this port.
 *
 * Besides Delaunator's output: `inedges[p]`, a half-edge ending at point p, a hull edge where p
 * is on the hull (d3-delaunay's convention), -1 for a skipped duplicate.
 *
 * Delaunator: Copyright (c) 2026, Mapbox. Permission to use, copy, modify, and/or distribute
 * this software for any purpose with or without fee is hereby granted, provided that the above
 * copyright notice and this permission notice appear in all copies. THE SOFTWARE IS PROVIDED
 * "AS IS" AND THE AUTHOR DISCLAIMS ALL WARRANTIES WITH REGARD TO THIS SOFTWARE.
 */
import { orient2d } from 'robust-predicates';

const EPSILON = Math.pow(2, -52);

export class Triangulation {
  /** Vertex indices, three per triangle (counter-clockwise); valid up to `length`. */
  triangles = new Uint32Array(0);
  /** Twin of each half-edge, -1 on the hull; valid up to `length`. */
  halfedges = new Int32Array(0);
  /** A half-edge ending at each point (a hull edge for hull points), -1 for none. */
  inedges = new Int32Array(0);
  /** Half-edges in use (3 x triangles); 0 when every point is collinear. */
  length = 0;
  /** Points of the last call. */
  count = 0;
  private coords: Float64Array = new Float64Array(0);
  private hullPrev = new Uint32Array(0);
  private hullNext = new Uint32Array(0);
  private hullTri = new Uint32Array(0);
  private hullHash = new Int32Array(0);
  private hashSize = 0;
  private ids = new Uint32Array(0);
  private dists = new Float64Array(0);
  private hullStart = 0;
  private cx = 0;
  private cy = 0;
  private readonly edgeStack = new Uint32Array(512);

  /** Triangulates the first `n` points of `coords` (interleaved x, y). */
  triangulate(coords: Float64Array, n: number): this {
    this.reserve(n);
    this.coords = coords;
    this.count = n;
    this.hashSize = Math.ceil(Math.sqrt(n));
    this.run(n);
    this.inedges.fill(-1, 0, n);
    const { triangles, halfedges, inedges } = this;
    for (let e = 0; e < this.length; e++) {
      const p = triangles[e % 3 === 2 ? e - 2 : e + 1];
      if (halfedges[e] === -1 || inedges[p] === -1) inedges[p] = e;
    }
    return this;
  }

  private reserve(n: number): void {
    if (this.ids.length >= n) return;
    const capacity = Math.max(n, Math.ceil(this.ids.length * 1.25));
    const maxTriangles = Math.max(2 * capacity - 5, 0);
    this.triangles = new Uint32Array(maxTriangles * 3);
    this.halfedges = new Int32Array(maxTriangles * 3);
    this.inedges = new Int32Array(capacity);
    this.hullPrev = new Uint32Array(capacity);
    this.hullNext = new Uint32Array(capacity);
    this.hullTri = new Uint32Array(capacity);
    this.hullHash = new Int32Array(Math.ceil(Math.sqrt(capacity)));
    this.ids = new Uint32Array(capacity);
    this.dists = new Float64Array(capacity);
  }

  private run(n: number): void {
    const { coords, hullPrev, hullNext, hullTri, hullHash, ids, dists } = this;
    this.length = 0;
    let minX = Infinity;
    let minY = Infinity;
    let maxX = -Infinity;
    let maxY = -Infinity;
    for (let i = 0; i < n; i++) {
      const x = coords[2 * i];
      const y = coords[2 * i + 1];
      if (x < minX) minX = x;
      if (y < minY) minY = y;
      if (x > maxX) maxX = x;
      if (y > maxY) maxY = y;
      ids[i] = i;
    }
    const cx = (minX + maxX) / 2;
    const cy = (minY + maxY) / 2;
    let i0 = 0;
    let i1 = 0;
    let i2 = 0;
    for (let i = 0, minDist = Infinity; i < n; i++) {
      const d = dist(cx, cy, coords[2 * i], coords[2 * i + 1]);
      if (d < minDist) {
        i0 = i;
        minDist = d;
      }
    }
    const i0x = coords[2 * i0];
    const i0y = coords[2 * i0 + 1];
    for (let i = 0, minDist = Infinity; i < n; i++) {
      if (i === i0) continue;
      const d = dist(i0x, i0y, coords[2 * i], coords[2 * i + 1]);
      if (d < minDist && d > 0) {
        i1 = i;
        minDist = d;
      }
    }
    let i1x = coords[2 * i1];
    let i1y = coords[2 * i1 + 1];
    let minRadius = Infinity;
    for (let i = 0; i < n; i++) {
      if (i === i0 || i === i1) continue;
      const r = circumradius(i0x, i0y, i1x, i1y, coords[2 * i], coords[2 * i + 1]);
      if (r < minRadius) {
        i2 = i;
        minRadius = r;
      }
    }
    let i2x = coords[2 * i2];
    let i2y = coords[2 * i2 + 1];
    if (minRadius === Infinity) return; // every point collinear: no triangle

    if (orient2d(i0x, i0y, i1x, i1y, i2x, i2y) < 0) [i1, i1x, i1y, i2, i2x, i2y] = [i2, i2x, i2y, i1, i1x, i1y];
    circumOffset(i0x, i0y, i1x, i1y, i2x, i2y, CENTER);
    this.cx = i0x + CENTER[0];
    this.cy = i0y + CENTER[1];
    const centerX = this.cx;
    const centerY = this.cy;
    for (let i = 0; i < n; i++) dists[i] = dist(coords[2 * i], coords[2 * i + 1], centerX, centerY);
    quicksort(ids, dists, 0, n - 1);

    this.hullStart = i0;
    hullNext[i0] = hullPrev[i2] = i1;
    hullNext[i1] = hullPrev[i0] = i2;
    hullNext[i2] = hullPrev[i1] = i0;
    hullTri[i0] = 0;
    hullTri[i1] = 1;
    hullTri[i2] = 2;
    hullHash.fill(-1, 0, this.hashSize);
    hullHash[this.hashKey(i0x, i0y)] = i0;
    hullHash[this.hashKey(i1x, i1y)] = i1;
    hullHash[this.hashKey(i2x, i2y)] = i2;
    this.addTriangle(i0, i1, i2, -1, -1, -1);

    for (let k = 0, xp = 0, yp = 0; k < n; k++) {
      const i = ids[k];
      const x = coords[2 * i];
      const y = coords[2 * i + 1];
      if (k > 0 && Math.abs(x - xp) <= EPSILON && Math.abs(y - yp) <= EPSILON) continue;
      xp = x;
      yp = y;
      if (i === i0 || i === i1 || i === i2) continue;

      let start = 0;
      for (let j = 0, key = this.hashKey(x, y); j < this.hashSize; j++) {
        start = hullHash[(key + j) % this.hashSize];
        if (start !== -1 && start !== hullNext[start]) break;
      }
      start = hullPrev[start];
      let e = start;
      let q = 0;
      while (((q = hullNext[e]), orient2d(x, y, coords[2 * e], coords[2 * e + 1], coords[2 * q], coords[2 * q + 1]) >= 0)) {
        e = q;
        if (e === start) {
          e = -1;
          break;
        }
      }
      if (e === -1) continue;

      let t = this.addTriangle(e, i, hullNext[e], -1, -1, hullTri[e]);
      hullTri[i] = this.legalize(t + 2);
      hullTri[e] = t;

      let m = hullNext[e];
      while (((q = hullNext[m]), orient2d(x, y, coords[2 * m], coords[2 * m + 1], coords[2 * q], coords[2 * q + 1]) < 0)) {
        t = this.addTriangle(m, i, q, hullTri[i], -1, hullTri[m]);
        hullTri[i] = this.legalize(t + 2);
        hullNext[m] = m;
        m = q;
      }
      if (e === start) {
        while (((q = hullPrev[e]), orient2d(x, y, coords[2 * q], coords[2 * q + 1], coords[2 * e], coords[2 * e + 1]) < 0)) {
          t = this.addTriangle(q, i, e, -1, hullTri[e], hullTri[q]);
          this.legalize(t + 2);
          hullTri[q] = t;
          hullNext[e] = e;
          e = q;
        }
      }
      this.hullStart = hullPrev[i] = e;
      hullNext[e] = hullPrev[m] = i;
      hullNext[i] = m;
      hullHash[this.hashKey(x, y)] = i;
      hullHash[this.hashKey(coords[2 * e], coords[2 * e + 1])] = e;
    }
  }

  private hashKey(x: number, y: number): number {
    return Math.floor(pseudoAngle(x - this.cx, y - this.cy) * this.hashSize) % this.hashSize;
  }

  private legalize(a: number): number {
    const { triangles, halfedges, coords, edgeStack } = this;
    let i = 0;
    let ar = 0;
    for (;;) {
      const b = halfedges[a];
      const a0 = a - (a % 3);
      ar = a0 + ((a + 2) % 3);
      if (b === -1) {
        if (i === 0) break;
        a = edgeStack[--i];
        continue;
      }
      const b0 = b - (b % 3);
      const al = a0 + ((a + 1) % 3);
      const bl = b0 + ((b + 2) % 3);
      const p0 = triangles[ar];
      const pr = triangles[a];
      const pl = triangles[al];
      const p1 = triangles[bl];
      const illegal = inCircle(
        coords[2 * p0],
        coords[2 * p0 + 1],
        coords[2 * pr],
        coords[2 * pr + 1],
        coords[2 * pl],
        coords[2 * pl + 1],
        coords[2 * p1],
        coords[2 * p1 + 1],
      );
      if (illegal) {
        triangles[a] = p1;
        triangles[b] = p0;
        const hbl = halfedges[bl];
        if (hbl === -1) {
          let e = this.hullStart;
          do {
            if (this.hullTri[e] === bl) {
              this.hullTri[e] = a;
              break;
            }
            e = this.hullPrev[e];
          } while (e !== this.hullStart);
        }
        this.link(a, hbl);
        this.link(b, halfedges[ar]);
        this.link(ar, bl);
        const br = b0 + ((b + 1) % 3);
        if (i < edgeStack.length) edgeStack[i++] = br;
      } else {
        if (i === 0) break;
        a = edgeStack[--i];
      }
    }
    return ar;
  }

  private link(a: number, b: number): void {
    this.halfedges[a] = b;
    if (b !== -1) this.halfedges[b] = a;
  }

  private addTriangle(i0: number, i1: number, i2: number, a: number, b: number, c: number): number {
    const t = this.length;
    this.triangles[t] = i0;
    this.triangles[t + 1] = i1;
    this.triangles[t + 2] = i2;
    this.link(t, a);
    this.link(t + 1, b);
    this.link(t + 2, c);
    this.length += 3;
    return t;
  }
}

function pseudoAngle(dx: number, dy: number): number {
  const p = dx / (Math.abs(dx) + Math.abs(dy));
  return (dy > 0 ? 3 - p : 1 + p) / 4;
}

function dist(ax: number, ay: number, bx: number, by: number): number {
  const dx = ax - bx;
  const dy = ay - by;
  return dx * dx + dy * dy;
}

/** Delaunator's (non-robust) test: true when p lies inside the circle through a, b, c. */
export function inCircle(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, px: number, py: number): boolean {
  const dx = ax - px;
  const dy = ay - py;
  const ex = bx - px;
  const ey = by - py;
  const fx = cx - px;
  const fy = cy - py;
  const ap = dx * dx + dy * dy;
  const bp = ex * ex + ey * ey;
  const cp = fx * fx + fy * fy;
  return dx * (ey * cp - bp * fy) - dy * (ex * cp - bp * fx) + ap * (ex * fy - ey * fx) < 0;
}

/** Squared circumradius of A, B, C. */
function circumradius(ax: number, ay: number, bx: number, by: number, cx: number, cy: number): number {
  circumOffset(ax, ay, bx, by, cx, cy, CENTER);
  return CENTER[0] * CENTER[0] + CENTER[1] * CENTER[1];
}

/** Scratch for a circumcentre's offset. */
const CENTER = new Float64Array(2);

/** Circumcentre of A, B, C minus A, written to out[0], out[1] (no object allocated). */
function circumOffset(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, out: Float64Array): void {
  const dx = bx - ax;
  const dy = by - ay;
  const ex = cx - ax;
  const ey = cy - ay;
  const bl = dist(bx, by, ax, ay);
  const cl = dist(cx, cy, ax, ay);
  const d = 0.5 / (dx * ey - dy * ex);
  out[0] = (ey * bl - dy * cl) * d;
  out[1] = (dx * cl - ex * bl) * d;
}

function quicksort(ids: Uint32Array, dists: Float64Array, left: number, right: number): void {
  if (right - left <= 20) {
    for (let i = left + 1; i <= right; i++) {
      const temp = ids[i];
      const tempDist = dists[temp];
      let j = i - 1;
      while (j >= left && dists[ids[j]] > tempDist) ids[j + 1] = ids[j--];
      ids[j + 1] = temp;
    }
  } else {
    const median = (left + right) >> 1;
    let i = left + 1;
    let j = right;
    swap(ids, median, i);
    if (dists[ids[left]] > dists[ids[right]]) swap(ids, left, right);
    if (dists[ids[i]] > dists[ids[right]]) swap(ids, i, right);
    if (dists[ids[left]] > dists[ids[i]]) swap(ids, left, i);
    const temp = ids[i];
    const tempDist = dists[temp];
    for (;;) {
      do i++;
      while (dists[ids[i]] < tempDist);
      do j--;
      while (dists[ids[j]] > tempDist);
      if (j < i) break;
      swap(ids, i, j);
    }
    ids[left + 1] = ids[j];
    ids[j] = temp;
    if (right - i + 1 >= j - left) {
      quicksort(ids, dists, i, right);
      quicksort(ids, dists, left, j - 1);
    } else {
      quicksort(ids, dists, left, j - 1);
      quicksort(ids, dists, i, right);
    }
  }
}

function swap(arr: Uint32Array, i: number, j: number): void {
  const tmp = arr[i];
  arr[i] = arr[j];
  arr[j] = tmp;
}
