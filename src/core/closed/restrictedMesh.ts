/**
 * Restricted Voronoi diagram of sites on a triangle mesh, as geogram computes it (Yan, Lévy
 * et al. 2009, "Isotropic remeshing with fast and exact computation of restricted Voronoi
 * diagram"): the cell of site i on the surface is the union over triangles of
 * (triangle ∩ every half-space {p : |p - s_i| ≤ |p - s_j|}).
 *
 * - Per-seed traversal: seed i starts at a triangle near it, clips it, and walks to the
 *   triangles across every original triangle edge that survived the clipping (the cell
 *   continues there). Each triangle is clipped at most once per traversal (stamps).
 * - Candidates: the k nearest sites of i (k-d tree), clipped nearest first. Radius of
 *   security (Lévy & Bonneel 2012): once the next candidate j has |s_j - s_i| > 2 R, R the
 *   largest distance from s_i to a vertex of the clipped (convex) polygon, no further site
 *   can cut it: for p in the polygon |p - s_j| ≥ |s_j - s_i| - |p - s_i| > R ≥ |p - s_i|.
 *   When the k candidates run out before that, k doubles.
 * - Coverage repair: a restricted cell can have more than one connected piece (a fold, a
 *   saddle); a traversal only sees the piece it starts in. Every triangle's clipped areas
 *   must add up to its area; where they fall short, every site that can own part of the
 *   triangle (within max over its vertices of the nearest-site distance + 2 × its diameter of
 *   its centroid) that has not clipped it yet starts a traversal there.
 *
 * Polygon clipping is Sutherland–Hodgman on convex polygons, with a label per edge: the
 * original triangle edge it lies on (-1 - e) or the site whose bisector made it (j ≥ 0). The
 * length of a bisector edge is the contact length of (i, j) inside this triangle. All scratch
 * is preallocated; the loops allocate nothing (the candidate buffer grows by doubling only).
 */
import { KdTree3 } from './kdTree';
import type { ContactRecorder } from './restrictedContacts';
import { triangleNeighbours, type MeshGeometry } from './restrictedSurface';
import { triangleArea } from '../mesh/types';

const MAX_POLYGON = 512;
const INITIAL_CANDIDATES = 24;
/** Relative shortfall of a triangle's covered area that triggers the repair pass. */
const COVERAGE_SLACK = 1e-9;

/**
 * One clipped piece of a cell: site i's part of triangle f, a convex polygon of `vertices`
 * points (x, y, z each in `polygon`, which is scratch: read it during the call only).
 */
export type PieceCallback = (site: number, triangle: number, polygon: Float64Array, vertices: number) => void;

export interface MeshRvdStats {
  triangles: number;
  /** Triangle clippings performed (all seeds). */
  clips: number;
  /** Traversals started by the coverage repair (extra connected pieces). */
  repairTraversals: number;
}

export class MeshRestrictedVoronoi {
  private readonly P: Float64Array;
  private readonly T: Int32Array;
  private readonly adj: Int32Array;
  private readonly nf: number;
  private readonly triArea: Float64Array;
  private readonly covered: Float64Array;
  private readonly stamp: Int32Array;
  private readonly queue: Int32Array;
  private ownerHead: Int32Array;
  private ownerNext = new Int32Array(1024);
  private ownerSeed = new Int32Array(1024);
  private owners = 0;
  private traversal = 0;
  // Polygons (ping-pong) with one label per edge k (vertex k to k + 1).
  private polyA = new Float64Array(3 * MAX_POLYGON);
  private polyB = new Float64Array(3 * MAX_POLYGON);
  private labA = new Int32Array(MAX_POLYGON);
  private labB = new Int32Array(MAX_POLYGON);
  private readonly dist = new Float64Array(MAX_POLYGON);
  /** Result of the last clip: vertices / labels (one of the ping-pong buffers) and size. */
  private out = this.polyA;
  private outLab = this.labA;
  // Candidates of the current seed.
  private cand = new Int32Array(INITIAL_CANDIDATES);
  private candD2 = new Float64Array(INITIAL_CANDIDATES);
  private nCand = 0;
  private candSeed = -1;
  private triTree: KdTree3 | null = null;
  private readonly centroids: Float64Array;
  /** Per site: the first triangle of its cell (its traversal's start), -1 when it has none. */
  readonly startTriangles: Int32Array;
  private readonly near = new Int32Array(64);
  private readonly nearD2 = new Float64Array(64);
  readonly stats: MeshRvdStats;

  constructor(
    surface: MeshGeometry,
    private readonly sites: Float64Array,
    private readonly count: number,
    private readonly siteTree: KdTree3,
    private readonly recorder: ContactRecorder,
    private readonly areas: Float64Array,
    private readonly hints?: ArrayLike<number>,
    private readonly onPiece?: PieceCallback,
  ) {
    const p = surface.positions;
    this.P = Float64Array.from(p as ArrayLike<number>);
    this.T = Int32Array.from(surface.indices as ArrayLike<number>);
    this.nf = this.T.length / 3;
    this.adj = surface.triangleNeighbours ?? triangleNeighbours(this.T, this.P.length / 3);
    const nf = this.nf;
    this.triArea = new Float64Array(nf);
    const centroids = new Float64Array(3 * nf);
    for (let f = 0; f < nf; f++) {
      const a = 3 * this.T[3 * f],
        b = 3 * this.T[3 * f + 1],
        c = 3 * this.T[3 * f + 2];
      const P = this.P;
      this.triArea[f] = triangleArea(P, this.T, f);
      for (let k = 0; k < 3; k++) centroids[3 * f + k] = (P[a + k] + P[b + k] + P[c + k]) / 3;
    }
    this.centroids = centroids;
    this.startTriangles = new Int32Array(count).fill(-1);
    this.covered = new Float64Array(nf);
    this.stamp = new Int32Array(nf).fill(-1);
    this.queue = new Int32Array(nf);
    this.ownerHead = new Int32Array(nf).fill(-1);
    this.ownerNext = new Int32Array(Math.max(1024, 2 * nf));
    this.ownerSeed = new Int32Array(Math.max(1024, 2 * nf));
    this.stats = { triangles: nf, clips: 0, repairTraversals: 0 };
  }

  /**
   * Runs every seed's traversal, then the coverage repair. Fills `areas`, the recorder and
   * `startTriangles`. A seed starts at its hint (the triangle its cell started in on another
   * surface of the stack with the same topology) when that triangle is in its cell, else at
   * the nearest triangle centroids (k-d tree built on first need).
   */
  run(): void {
    for (let i = 0; i < this.count; i++) {
      this.recorder.begin(i);
      const hint = this.hints ? this.hints[i] : -1;
      if (hint >= 0 && hint < this.nf && this.traverse(i, hint) > 0) {
        this.startTriangles[i] = hint;
        continue;
      }
      if (!this.triTree) this.triTree = new KdTree3(this.centroids, this.nf);
      const x = this.sites[3 * i],
        y = this.sites[3 * i + 1],
        z = this.sites[3 * i + 2];
      const found = this.triTree.knn(x, y, z, 8, this.near, this.nearD2);
      for (let q = 0; q < found; q++) {
        const f = this.near[q];
        if (this.owns(f, i)) continue;
        if (this.traverse(i, f) > 0) {
          this.startTriangles[i] = f;
          break;
        }
      }
    }
    this.repair();
    this.recorder.flush();
  }

  private owns(f: number, i: number): boolean {
    for (let e = this.ownerHead[f]; e >= 0; e = this.ownerNext[e]) if (this.ownerSeed[e] === i) return true;
    return false;
  }

  private addOwner(f: number, i: number): void {
    if (this.owners === this.ownerSeed.length) {
      const n = 2 * this.owners;
      const next = new Int32Array(n),
        seed = new Int32Array(n);
      next.set(this.ownerNext);
      seed.set(this.ownerSeed);
      this.ownerNext = next;
      this.ownerSeed = seed;
    }
    this.ownerSeed[this.owners] = i;
    this.ownerNext[this.owners] = this.ownerHead[f];
    this.ownerHead[f] = this.owners++;
  }

  /** Breadth-first walk of seed i's cell from triangle `start`; returns the area found. */
  private traverse(i: number, start: number): number {
    const t = ++this.traversal;
    let head = 0,
      tail = 0;
    this.queue[tail++] = start;
    this.stamp[start] = t;
    let total = 0;
    while (head < tail) {
      const f = this.queue[head++];
      const n = this.clip(f, i);
      if (n === 0) continue;
      const V = this.out,
        L = this.outLab;
      this.onPiece?.(i, f, V, n);
      // Area of the convex planar polygon (fan from vertex 0).
      let cx = 0,
        cy = 0,
        cz = 0;
      const x0 = V[0],
        y0 = V[1],
        z0 = V[2];
      for (let k = 1; k + 1 < n; k++) {
        const ux = V[3 * k] - x0,
          uy = V[3 * k + 1] - y0,
          uz = V[3 * k + 2] - z0;
        const vx = V[3 * k + 3] - x0,
          vy = V[3 * k + 4] - y0,
          vz = V[3 * k + 5] - z0;
        cx += uy * vz - uz * vy;
        cy += uz * vx - ux * vz;
        cz += ux * vy - uy * vx;
      }
      const area = 0.5 * Math.sqrt(cx * cx + cy * cy + cz * cz);
      total += area;
      this.areas[i] += area;
      this.covered[f] += area;
      this.addOwner(f, i);
      for (let k = 0; k < n; k++) {
        const k1 = k + 1 === n ? 0 : k + 1;
        const len = Math.hypot(V[3 * k1] - V[3 * k], V[3 * k1 + 1] - V[3 * k + 1], V[3 * k1 + 2] - V[3 * k + 2]);
        if (!(len > 0)) continue;
        const label = L[k];
        if (label >= 0) {
          this.recorder.add(label, len);
          continue;
        }
        const g = this.adj[3 * f + (-1 - label)];
        if (g < 0 || this.stamp[g] === t || this.owns(g, i)) continue;
        this.stamp[g] = t;
        this.queue[tail++] = g;
      }
    }
    return total;
  }

  /** Candidates of seed i: its k nearest other sites, nearest first. */
  private loadCandidates(i: number, k: number): void {
    if (k > this.cand.length) {
      this.cand = new Int32Array(k);
      this.candD2 = new Float64Array(k);
    }
    this.nCand = this.siteTree.knn(this.sites[3 * i], this.sites[3 * i + 1], this.sites[3 * i + 2], k, this.cand, this.candD2, i);
    this.candSeed = i;
  }

  /**
   * Triangle f clipped by seed i's bisectors, nearest candidate first, until the radius of
   * security proves the rest cannot cut. Returns the vertex count (0: empty); the polygon
   * is in this.out / this.outLab.
   */
  private clip(f: number, i: number): number {
    this.stats.clips++;
    if (this.candSeed !== i) this.loadCandidates(i, Math.min(INITIAL_CANDIDATES, this.count - 1));
    const sx = this.sites[3 * i],
      sy = this.sites[3 * i + 1],
      sz = this.sites[3 * i + 2];
    let V = this.polyA,
      L = this.labA,
      W = this.polyB,
      M = this.labB;
    for (let e = 0; e < 3; e++) {
      const v = 3 * this.T[3 * f + e];
      V[3 * e] = this.P[v];
      V[3 * e + 1] = this.P[v + 1];
      V[3 * e + 2] = this.P[v + 2];
      L[e] = -1 - e;
    }
    let n = 3;
    let R2 = this.maxDistance2(V, n, sx, sy, sz);
    let c = 0;
    for (;;) {
      if (c === this.nCand) {
        if (this.nCand >= this.count - 1) break;
        this.loadCandidates(i, Math.min(2 * this.nCand, this.count - 1));
        continue;
      }
      if (this.candD2[c] > 4 * R2) break;
      const j = this.cand[c++];
      const jx = this.sites[3 * j],
        jy = this.sites[3 * j + 1],
        jz = this.sites[3 * j + 2];
      const nx = jx - sx,
        ny = jy - sy,
        nz = jz - sz;
      if (nx === 0 && ny === 0 && nz === 0) continue; // a duplicate site has no bisector
      const mx = 0.5 * (jx + sx),
        my = 0.5 * (jy + sy),
        mz = 0.5 * (jz + sz);
      let outside = 0;
      for (let k = 0; k < n; k++) {
        const d = (V[3 * k] - mx) * nx + (V[3 * k + 1] - my) * ny + (V[3 * k + 2] - mz) * nz;
        this.dist[k] = d;
        if (d > 0) outside++;
      }
      if (outside === 0) continue;
      if (outside === n) {
        this.out = V;
        this.outLab = L;
        return 0;
      }
      let m = 0;
      for (let k = 0; k < n; k++) {
        const k1 = k + 1 === n ? 0 : k + 1;
        const da = this.dist[k],
          db = this.dist[k1];
        if (m + 2 > MAX_POLYGON) throw new Error(`restrictedVoronoi: a clipped polygon exceeded ${MAX_POLYGON} vertices`);
        if (da <= 0) {
          W[3 * m] = V[3 * k];
          W[3 * m + 1] = V[3 * k + 1];
          W[3 * m + 2] = V[3 * k + 2];
          M[m++] = L[k];
          if (db > 0) {
            const s = da / (da - db);
            W[3 * m] = V[3 * k] + s * (V[3 * k1] - V[3 * k]);
            W[3 * m + 1] = V[3 * k + 1] + s * (V[3 * k1 + 1] - V[3 * k + 1]);
            W[3 * m + 2] = V[3 * k + 2] + s * (V[3 * k1 + 2] - V[3 * k + 2]);
            M[m++] = j;
          }
        } else if (db <= 0) {
          const s = da / (da - db);
          W[3 * m] = V[3 * k] + s * (V[3 * k1] - V[3 * k]);
          W[3 * m + 1] = V[3 * k + 1] + s * (V[3 * k1 + 1] - V[3 * k + 1]);
          W[3 * m + 2] = V[3 * k + 2] + s * (V[3 * k1 + 2] - V[3 * k + 2]);
          M[m++] = L[k];
        }
      }
      const tv = V,
        tl = L;
      V = W;
      L = M;
      W = tv;
      M = tl;
      n = m;
      R2 = this.maxDistance2(V, n, sx, sy, sz);
    }
    this.out = V;
    this.outLab = L;
    return n;
  }

  private maxDistance2(V: Float64Array, n: number, x: number, y: number, z: number): number {
    let r = 0;
    for (let k = 0; k < n; k++) {
      const dx = V[3 * k] - x,
        dy = V[3 * k + 1] - y,
        dz = V[3 * k + 2] - z;
      const d = dx * dx + dy * dy + dz * dz;
      if (d > r) r = d;
    }
    return r;
  }

  /**
   * Triangles whose clipped pieces do not add up to their area: every site that can own part
   * of one and has not clipped it yet starts a traversal there.
   */
  private repair(): void {
    const P = this.P,
      T = this.T;
    let ids = new Int32Array(32),
      d2 = new Float64Array(32);
    const one = new Int32Array(1),
      oneD = new Float64Array(1);
    for (let f = 0; f < this.nf; f++) {
      if (!(this.covered[f] < this.triArea[f] * (1 - COVERAGE_SLACK))) continue;
      let cx = 0,
        cy = 0,
        cz = 0,
        reach = 0,
        diam = 0;
      for (let e = 0; e < 3; e++) {
        const v = 3 * T[3 * f + e],
          w = 3 * T[3 * f + ((e + 1) % 3)];
        cx += P[v] / 3;
        cy += P[v + 1] / 3;
        cz += P[v + 2] / 3;
        this.siteTree.knn(P[v], P[v + 1], P[v + 2], 1, one, oneD);
        reach = Math.max(reach, Math.sqrt(oneD[0]));
        diam = Math.max(diam, Math.hypot(P[w] - P[v], P[w + 1] - P[v + 1], P[w + 2] - P[v + 2]));
      }
      // A site owning a point p of the triangle is its nearest: |s - p| = d(p) ≤ reach + diam,
      // so |s - centroid| ≤ reach + 2 diam.
      const radius = reach + 2 * diam;
      let k = Math.min(ids.length, this.count);
      let found = 0;
      for (;;) {
        found = this.siteTree.knn(cx, cy, cz, k, ids, d2);
        if (found < k || d2[found - 1] > radius * radius || k === this.count) break;
        k = Math.min(2 * k, this.count);
        if (k > ids.length) {
          ids = new Int32Array(k);
          d2 = new Float64Array(k);
        }
      }
      for (let q = 0; q < found && d2[q] <= radius * radius; q++) {
        const s = ids[q];
        if (this.owns(f, s)) continue;
        this.recorder.begin(s);
        if (this.traverse(s, f) > 0) this.stats.repairTraversals++;
      }
    }
  }
}
