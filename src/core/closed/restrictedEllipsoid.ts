/**
 * Restricted Voronoi diagram of sites on the analytic ellipsoid x²/a² + y²/b² + z²/c² = 1
 * (a sphere when a = b = c): no triangulation, the contacts are conic arcs.
 *
 * Cell i = E ∩ {p : p·n_j ≤ o_j for every other site j}, n_j = s_j - s_i,
 * o_j = (|s_j|² - |s_i|²) / 2. With p = M x (M = diag(a, b, c), |x| = 1) the constraints
 * become x·(M n_j) ≤ o_j: caps of the unit sphere. The contact of (i, j) is the circle
 * x·m̂_j = h_j (h_j = o_j / |M n_j|) minus what the other constraints cut away: on the
 * circle x(θ) = h m̂ + r (cos θ u + sin θ v), constraint k reads A cos θ + B sin θ ≤ C, an arc
 * of allowed θ; intersecting these arcs gives exactly the θ-intervals where j is a neighbour.
 * Contact length: ∫ |M x'| dθ over those intervals; cell area: Stokes along the same arcs
 * (conicArc.ts). Neighbour sets are exact up to rounding: a contact exists iff an interval of
 * positive length survives.
 *
 * Candidates and the radius of security: the k nearest sites of s_i (k-d tree). Let R be
 * the largest distance from s_i to the candidate cell's boundary arcs (sampled, plus a
 * Lipschitz margin, so an upper bound). For a site s_i on E, the squared distance to s_i
 * restricted to E has no critical point other than s_i closer than 2 × reach (reach = smallest
 * radius of curvature = min axis² / max axis): a point p with p - s_i along the normal at p
 * would have the midpoint of p and s_i, at distance < reach from both, with two closest
 * points. So for R < 2 reach, E ∩ B(s_i, R) is a disc, and if a point of E beyond it (the
 * farthest candidate site, which its own constraint excludes) lies outside the candidate
 * cell, the whole candidate cell lies in B(s_i, R): every site beyond 2 R cannot cut it (as
 * on meshes). Otherwise k doubles (up to all sites, which is exact by definition).
 */
import { EllipsoidArcIntegrator, ellipsoidArea } from './conicArc';
import type { KdTree3 } from './kdTree';
import type { ContactRecorder } from './restrictedContacts';
import type { EllipsoidGeometry } from './restrictedSurface';

const INITIAL_CANDIDATES = 20;
const TWO_PI = 2 * Math.PI;

export interface EllipsoidRvdStats {
  /** Candidate sets enlarged because the radius of security was not reached. */
  enlargements: number;
  /** Largest candidate count any cell needed. */
  maxCandidates: number;
}

export class EllipsoidRestrictedVoronoi {
  private readonly a: number;
  private readonly b: number;
  private readonly c: number;
  private readonly reach: number;
  private readonly arcs: EllipsoidArcIntegrator;
  private cap = 0;
  private cand = new Int32Array(0);
  private candD2 = new Float64Array(0);
  // Per candidate: constraint x·m ≤ off in parameter space, and its circle (C, U, V).
  private m = new Float64Array(0);
  private off = new Float64Array(0);
  private circC = new Float64Array(0);
  private circU = new Float64Array(0);
  private circV = new Float64Array(0);
  private ivStart = new Int32Array(0);
  private ivLo = new Float64Array(64);
  private ivHi = new Float64Array(64);
  private curLo = new Float64Array(0);
  private curHi = new Float64Array(0);
  private nxtLo = new Float64Array(0);
  private nxtHi = new Float64Array(0);
  private readonly pt = new Float64Array(3);
  readonly stats: EllipsoidRvdStats = { enlargements: 0, maxCandidates: 0 };

  constructor(
    surface: EllipsoidGeometry,
    private readonly sites: Float64Array,
    private readonly count: number,
    private readonly siteTree: KdTree3,
    private readonly recorder: ContactRecorder,
    private readonly areas: Float64Array,
    private readonly lengthTolerance: number,
  ) {
    this.a = surface.a;
    this.b = surface.b;
    this.c = surface.c;
    const lo = Math.min(this.a, this.b, this.c),
      hi = Math.max(this.a, this.b, this.c);
    this.reach = (lo * lo) / hi;
    this.arcs = new EllipsoidArcIntegrator(this.a, this.b, this.c);
    this.ensure(Math.min(INITIAL_CANDIDATES, Math.max(1, count - 1)));
  }

  private ensure(k: number): void {
    if (k <= this.cap) return;
    this.cap = k;
    this.cand = new Int32Array(k);
    this.candD2 = new Float64Array(k);
    this.m = new Float64Array(3 * k);
    this.off = new Float64Array(k);
    this.circC = new Float64Array(3 * k);
    this.circU = new Float64Array(3 * k);
    this.circV = new Float64Array(3 * k);
    this.ivStart = new Int32Array(k + 1);
    this.curLo = new Float64Array(k + 2);
    this.curHi = new Float64Array(k + 2);
    this.nxtLo = new Float64Array(k + 2);
    this.nxtHi = new Float64Array(k + 2);
  }

  run(): void {
    if (this.count === 1) {
      this.areas[0] = ellipsoidArea(this.a, this.b, this.c);
      return;
    }
    for (let i = 0; i < this.count; i++) this.cell(i);
    this.recorder.flush();
  }

  private cell(i: number): void {
    const S = this.sites;
    const sx = S[3 * i],
      sy = S[3 * i + 1],
      sz = S[3 * i + 2];
    // Parameter direction of the site (the pole of the area form).
    const px = sx / this.a,
      py = sy / this.b,
      pz = sz / this.c;
    // kNN list of `found` sites; the cell is clipped by its first n. Every site outside the
    // prefix is at least sqrt(next) away; the cell is proven once next > (2 R)².
    let k = Math.min(INITIAL_CANDIDATES, this.count - 1);
    this.ensure(k);
    let found = this.siteTree.knn(sx, sy, sz, k, this.cand, this.candD2, i);
    let n = found;
    this.clipArcs(i, n);
    for (;;) {
      if (n >= this.count - 1) break;
      const R = this.boundaryRadius(n, sx, sy, sz);
      // E minus the disc E ∩ B(s_i, R) is connected; the farthest candidate site lies in it
      // when beyond R, and outside the candidate cell (its own constraint excludes it), so
      // the whole candidate cell is inside the disc.
      if (!(R < 2 * this.reach) || !(this.candD2[n - 1] > R * R)) {
        // No proof possible yet (the candidate cell is still too large): twice the candidates.
        this.stats.enlargements++;
        k = Math.min(2 * k, this.count - 1);
        this.ensure(k);
        found = this.siteTree.knn(sx, sy, sz, k, this.cand, this.candD2, i);
        n = found;
        this.clipArcs(i, n);
        continue;
      }
      const next = n < found ? this.candD2[n] : this.candD2[found - 1];
      if (next > 4 * R * R) break;
      this.stats.enlargements++;
      // Sites beyond 2 R cannot cut the current candidate cell, nor the smaller cell that
      // more candidates leave: fetch more only while the list ends inside 2 R.
      while (found < this.count - 1 && this.candD2[found - 1] <= 4 * R * R) {
        k = Math.min(2 * k, this.count - 1);
        this.ensure(k);
        found = this.siteTree.knn(sx, sy, sz, k, this.cand, this.candD2, i);
      }
      let m = n;
      while (m < found && this.candD2[m] <= 4 * R * R) m++;
      n = m;
      this.clipArcs(i, n);
    }
    if (n > this.stats.maxCandidates) this.stats.maxCandidates = n;
    // The pole's antipode must lie outside the cell; if the site's own antipode does not
    // (a cell over half the surface), use the direction away from the nearest other site.
    if (this.inCell(-px, -py, -pz, n)) {
      const j = this.cand[0];
      this.arcs.setPole(-S[3 * j] / this.a, -S[3 * j + 1] / this.b, -S[3 * j + 2] / this.c);
    } else this.arcs.setPole(px, py, pz);
    this.recorder.begin(i);
    const scale = Math.max(this.a, this.b, this.c);
    const lengthTol = 1e-10 * scale,
      areaTol = 1e-12 * scale * scale;
    let area = 0;
    for (let q = 0; q < n; q++) {
      if (!this.onCircle(q)) continue;
      let len = 0;
      for (let t = this.ivStart[q]; t < this.ivStart[q + 1]; t++) {
        len += this.arcs.length(this.ivLo[t], this.ivHi[t], lengthTol);
        // The cell lies on the side x·m̂ ≤ h, i.e. to the right of increasing θ (u × v = m̂):
        // its counter-clockwise boundary runs with decreasing θ.
        area -= this.arcs.areaTerm(this.ivLo[t], this.ivHi[t], areaTol);
      }
      if (len > this.lengthTolerance) this.recorder.add(this.cand[q], len);
    }
    this.areas[i] = area;
  }

  /** Puts `arcs` on candidate q's circle, false (and nothing set) where none of it survived clipping. */
  private onCircle(q: number): boolean {
    if (this.ivStart[q] === this.ivStart[q + 1]) return false;
    this.arcs.setCircle(this.circC, this.circU, this.circV, 3 * q);
    return true;
  }

  /** Whether the unit vector x lies in the candidate cell (all n constraints). */
  private inCell(x: number, y: number, z: number, n: number): boolean {
    const m = this.m;
    for (let q = 0; q < n; q++) if (x * m[3 * q] + y * m[3 * q + 1] + z * m[3 * q + 2] > this.off[q]) return false;
    return true;
  }

  /** Constraints and circles of the n candidates, and the surviving θ-intervals of each. */
  private clipArcs(i: number, n: number): void {
    const S = this.sites,
      m = this.m;
    const sx = S[3 * i],
      sy = S[3 * i + 1],
      sz = S[3 * i + 2];
    const s2 = sx * sx + sy * sy + sz * sz;
    for (let q = 0; q < n; q++) {
      const j = this.cand[q];
      const jx = S[3 * j],
        jy = S[3 * j + 1],
        jz = S[3 * j + 2];
      m[3 * q] = this.a * (jx - sx);
      m[3 * q + 1] = this.b * (jy - sy);
      m[3 * q + 2] = this.c * (jz - sz);
      this.off[q] = 0.5 * (jx * jx + jy * jy + jz * jz - s2);
    }
    let ivCount = 0;
    for (let q = 0; q < n; q++) {
      this.ivStart[q] = ivCount;
      const mx = m[3 * q],
        my = m[3 * q + 1],
        mz = m[3 * q + 2];
      const L = Math.hypot(mx, my, mz);
      if (L === 0) continue; // duplicate site
      const h = this.off[q] / L;
      if (!(Math.abs(h) < 1)) continue; // the bisector plane misses the ellipsoid
      const nx = mx / L,
        ny = my / L,
        nz = mz / L;
      const r = Math.sqrt(1 - h * h);
      // u ⊥ m̂, v = m̂ × u, so u × v = m̂.
      const ax = Math.abs(nx) < 0.9 ? 1 : 0,
        ay = 1 - ax;
      let ux = ay * nz,
        uy = -ax * nz,
        uz = ax * ny - ay * nx;
      const ul = Math.hypot(ux, uy, uz);
      ux /= ul;
      uy /= ul;
      uz /= ul;
      const vx = ny * uz - nz * uy,
        vy = nz * ux - nx * uz,
        vz = nx * uy - ny * ux;
      const C = this.circC,
        U = this.circU,
        V = this.circV;
      C[3 * q] = h * nx;
      C[3 * q + 1] = h * ny;
      C[3 * q + 2] = h * nz;
      U[3 * q] = r * ux;
      U[3 * q + 1] = r * uy;
      U[3 * q + 2] = r * uz;
      V[3 * q] = r * vx;
      V[3 * q + 1] = r * vy;
      V[3 * q + 2] = r * vz;
      let cur = 1;
      this.curLo[0] = 0;
      this.curHi[0] = TWO_PI;
      for (let p = 0; p < n && cur > 0; p++) {
        if (p === q) continue;
        const kx = m[3 * p],
          ky = m[3 * p + 1],
          kz = m[3 * p + 2];
        const A = r * (ux * kx + uy * ky + uz * kz);
        const B = r * (vx * kx + vy * ky + vz * kz);
        const Cc = this.off[p] - h * (nx * kx + ny * ky + nz * kz);
        const rho = Math.hypot(A, B);
        if (Cc >= rho) continue; // the whole circle satisfies constraint p
        if (Cc <= -rho) {
          cur = 0;
          break;
        }
        // Allowed: cos(θ - φ0) ≤ Cc / ρ, i.e. θ ∈ [φ0 + α, φ0 + 2π - α].
        const alpha = Math.acos(Cc / rho);
        let start = Math.atan2(B, A) + alpha;
        start -= TWO_PI * Math.floor(start / TWO_PI);
        cur = this.intersect(cur, start, TWO_PI - 2 * alpha);
      }
      for (let t = 0; t < cur; t++) {
        if (!(this.curHi[t] > this.curLo[t])) continue;
        if (ivCount === this.ivLo.length) this.growIntervals();
        this.ivLo[ivCount] = this.curLo[t];
        this.ivHi[ivCount++] = this.curHi[t];
      }
    }
    this.ivStart[n] = ivCount;
  }

  /** cur ∩ the arc [start, start + len] (mod 2π); returns the new interval count (sorted). */
  private intersect(cur: number, start: number, len: number): number {
    let out = 0;
    const end = start + len;
    // Pieces of the arc within [0, 2π], in increasing order.
    for (let piece = 0; piece < 2; piece++) {
      let lo: number, hi: number;
      if (end > TWO_PI) {
        if (piece === 0) {
          lo = 0;
          hi = end - TWO_PI;
        } else {
          lo = start;
          hi = TWO_PI;
        }
      } else {
        if (piece === 1) break;
        lo = start;
        hi = end;
      }
      for (let t = 0; t < cur; t++) {
        const a = Math.max(lo, this.curLo[t]),
          b = Math.min(hi, this.curHi[t]);
        if (b > a) {
          if (out === this.nxtLo.length) this.growScratch();
          this.nxtLo[out] = a;
          this.nxtHi[out++] = b;
        }
      }
    }
    const tl = this.curLo,
      th = this.curHi;
    this.curLo = this.nxtLo;
    this.curHi = this.nxtHi;
    this.nxtLo = tl;
    this.nxtHi = th;
    return out;
  }

  private growScratch(): void {
    const n = 2 * this.nxtLo.length;
    for (const key of ['curLo', 'curHi', 'nxtLo', 'nxtHi'] as const) {
      const next = new Float64Array(n);
      next.set(this[key]);
      this[key] = next;
    }
  }

  private growIntervals(): void {
    const lo = new Float64Array(2 * this.ivLo.length),
      hi = new Float64Array(2 * this.ivHi.length);
    lo.set(this.ivLo);
    hi.set(this.ivHi);
    this.ivLo = lo;
    this.ivHi = hi;
  }

  /**
   * Upper bound of the distance from (sx, sy, sz) to the candidate cell's boundary arcs:
   * samples every Δθ ≤ 0.05 plus the speed bound × Δθ / 2.
   */
  private boundaryRadius(n: number, sx: number, sy: number, sz: number): number {
    let R = 0;
    for (let q = 0; q < n; q++) {
      if (!this.onCircle(q)) continue;
      const speed = this.arcs.speedBound();
      for (let t = this.ivStart[q]; t < this.ivStart[q + 1]; t++) {
        const lo = this.ivLo[t],
          hi = this.ivHi[t];
        const steps = Math.max(2, Math.ceil((hi - lo) / 0.05));
        const dt = (hi - lo) / steps;
        for (let s = 0; s <= steps; s++) {
          this.arcs.point(lo + s * dt, this.pt);
          const d = Math.hypot(this.pt[0] - sx, this.pt[1] - sy, this.pt[2] - sz) + 0.5 * speed * dt;
          if (d > R) R = d;
        }
      }
    }
    return R;
  }
}
