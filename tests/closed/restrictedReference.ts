/**
 * Independent references for the restricted Voronoi diagram (tests only). They share no code
 * with src/core/closed/restricted*: nearest sites come from the grid brute force of
 * tests/oracles/cubeMap.ts (cubeBruteForceLabels, the jump flood's reference), curves are
 * sampled densely instead of clipped, and endpoints are found by bisection on the labels.
 *
 * - ellipsoidContactsReference: for every pair of sites closer than `cutoff`, the conic
 *   bisector plane ∩ ellipsoid is parameterised in the plane's own coordinates (centre and
 *   principal axes of the 2D conic), sampled at `samples` points, each labelled by its nearest
 *   site; runs labelled i or j are the contact, their ends refined by bisection, their length a
 *   dense polyline.
 * - meshContactsReference: every triangle is sampled on a barycentric grid; for every pair of
 *   sites owning samples of it or of a triangle around its vertices, the bisector plane ∩
 *   triangle segment is sampled and measured the same way.
 */
import { cubeBruteForceLabels } from '../oracles/cubeMap';

export interface PairLengths {
  /** key i * count + j (i < j) → contact length, µm. */
  readonly lengths: Map<number, number>;
  readonly count: number;
}

/** One batch of points labelled by their nearest site. */
function label(points: number[], sites: ArrayLike<number>, count: number): Int32Array {
  return cubeBruteForceLabels(Float64Array.from(points), sites, count);
}

/**
 * Curves given as point functions c(u), u in [0, 1], each for a pair (i, j): samples, labels,
 * runs, bisection of the run ends (all curves batched per round), polyline lengths.
 */
function measureCurves(
  curves: { i: number; j: number; at: (u: number, out: number[]) => void; keep?: (p: number[]) => boolean }[],
  sites: ArrayLike<number>,
  count: number,
  samples: number,
): Map<number, number> {
  const p = [0, 0, 0];
  const pts: number[] = [];
  const owner: number[] = []; // curve index per sample
  const param: number[] = [];
  for (let c = 0; c < curves.length; c++) {
    for (let s = 0; s <= samples; s++) {
      const u = s / samples;
      curves[c].at(u, p);
      if (curves[c].keep && !curves[c].keep!(p)) continue;
      pts.push(p[0], p[1], p[2]);
      owner.push(c);
      param.push(u);
    }
  }
  const labels = label(pts, sites, count);
  // Runs: consecutive samples (in u) of one curve labelled i or j.
  interface Run {
    c: number;
    lo: number;
    hi: number;
    loOut: number;
    hiOut: number;
  }
  const runs: Run[] = [];
  const step = 1 / samples;
  for (let k = 0; k < owner.length; k++) {
    const c = owner[k];
    const inside = labels[k] === curves[c].i || labels[k] === curves[c].j;
    if (!inside) continue;
    const last = runs[runs.length - 1];
    if (last && last.c === c && Math.abs(param[k] - last.hi - step) < 1e-12) last.hi = param[k];
    else runs.push({ c, lo: param[k], hi: param[k], loOut: param[k] - step, hiOut: param[k] + step });
  }
  for (const r of runs) r.hiOut = r.hi + step;
  // Contacts shorter than the sample spacing: G(u) = |p - s_i| - |p - s_nearest| is 0 on the
  // contact and > 0 elsewhere; at every local minimum of G between samples (G > 0 there) a
  // golden-section search looks for a point where G reaches 0 (a short contact).
  const G = (k: number) => {
    const { i, j } = curves[owner[k]],
      n = labels[k];
    if (n === i || n === j) return 0;
    const x = pts[3 * k],
      y = pts[3 * k + 1],
      z = pts[3 * k + 2];
    return Math.hypot(x - sites[3 * i], y - sites[3 * i + 1], z - sites[3 * i + 2]) - Math.hypot(x - sites[3 * n], y - sites[3 * n + 1], z - sites[3 * n + 2]);
  };
  const seeds: { c: number; lo: number; hi: number }[] = [];
  for (let k = 1; k + 1 < owner.length; k++) {
    if (owner[k - 1] !== owner[k] || owner[k + 1] !== owner[k]) continue;
    if (Math.abs(param[k + 1] - param[k - 1] - 2 * step) > 1e-12) continue;
    const g = G(k);
    if (g > 0 && g <= G(k - 1) && g <= G(k + 1)) seeds.push({ c: owner[k], lo: param[k - 1], hi: param[k + 1] });
  }
  if (seeds.length > 0) {
    const ratio = (Math.sqrt(5) - 1) / 2;
    const lo = seeds.map((q) => q.lo),
      hi = seeds.map((q) => q.hi);
    const best = seeds.map(() => -1);
    for (let round = 0; round < 60; round++) {
      const q: number[] = [];
      for (let s = 0; s < seeds.length; s++) {
        for (const u of [hi[s] - ratio * (hi[s] - lo[s]), lo[s] + ratio * (hi[s] - lo[s])]) {
          curves[seeds[s].c].at(u, p);
          q.push(...p);
        }
      }
      const l = label(q, sites, count);
      for (let s = 0; s < seeds.length; s++) {
        const { i, j } = curves[seeds[s].c];
        const u1 = hi[s] - ratio * (hi[s] - lo[s]),
          u2 = lo[s] + ratio * (hi[s] - lo[s]);
        const g = (m: number) => {
          const x = q[3 * m],
            y = q[3 * m + 1],
            z = q[3 * m + 2],
            n = l[m];
          if (n === i || n === j) return 0;
          return (
            Math.hypot(x - sites[3 * i], y - sites[3 * i + 1], z - sites[3 * i + 2]) - Math.hypot(x - sites[3 * n], y - sites[3 * n + 1], z - sites[3 * n + 2])
          );
        };
        const g1 = g(2 * s),
          g2 = g(2 * s + 1);
        if (best[s] < 0 && g1 === 0) best[s] = u1;
        else if (best[s] < 0 && g2 === 0) best[s] = u2;
        if (g1 <= g2) hi[s] = u2;
        else lo[s] = u1;
      }
    }
    for (let s = 0; s < seeds.length; s++) {
      if (best[s] < 0) continue;
      runs.push({ c: seeds[s].c, lo: best[s], hi: best[s], loOut: seeds[s].lo, hiOut: seeds[s].hi });
    }
  }
  // Bisection of both ends of every run at once: 40 rounds.
  const loIn = runs.map((r) => r.lo),
    loOut = runs.map((r) => Math.max(0, r.loOut));
  // (A short contact found by the search keeps its neighbouring samples as outside points.)
  const hiIn = runs.map((r) => r.hi),
    hiOut = runs.map((r) => Math.min(1, r.hiOut));
  for (let round = 0; round < 40; round++) {
    const q: number[] = [];
    for (let r = 0; r < runs.length; r++) {
      curves[runs[r].c].at(0.5 * (loIn[r] + loOut[r]), p);
      q.push(...p);
      curves[runs[r].c].at(0.5 * (hiIn[r] + hiOut[r]), p);
      q.push(...p);
    }
    const l = label(q, sites, count);
    for (let r = 0; r < runs.length; r++) {
      const { i, j } = curves[runs[r].c];
      const a = 0.5 * (loIn[r] + loOut[r]),
        b = 0.5 * (hiIn[r] + hiOut[r]);
      if (l[2 * r] === i || l[2 * r] === j) loIn[r] = a;
      else loOut[r] = a;
      if (l[2 * r + 1] === i || l[2 * r + 1] === j) hiIn[r] = b;
      else hiOut[r] = b;
    }
  }
  const out = new Map<number, number>();
  const prev = [0, 0, 0];
  for (let r = 0; r < runs.length; r++) {
    const { i, j, at } = curves[runs[r].c];
    const a = 0.5 * (loIn[r] + loOut[r]),
      b = 0.5 * (hiIn[r] + hiOut[r]);
    const pieces = Math.max(16, Math.ceil(((b - a) / step) * 8));
    let len = 0;
    at(a, prev);
    for (let s = 1; s <= pieces; s++) {
      at(a + ((b - a) * s) / pieces, p);
      len += Math.hypot(p[0] - prev[0], p[1] - prev[1], p[2] - prev[2]);
      prev[0] = p[0];
      prev[1] = p[1];
      prev[2] = p[2];
    }
    const key = Math.min(i, j) * count + Math.max(i, j);
    out.set(key, (out.get(key) ?? 0) + len);
  }
  return out;
}

/** Plane n·p = o ∩ ellipsoid (a, b, c) as c(u) = centre + cos(2πu) A1 + sin(2πu) A2 (3D), or null. */
function planeEllipsoidConic(n: number[], o: number, a: number, b: number, c: number) {
  const nl = Math.hypot(n[0], n[1], n[2]);
  const N = n.map((v) => v / nl),
    off = o / nl;
  const p0 = N.map((v) => v * off);
  // Orthonormal basis e1, e2 of the plane.
  const t = Math.abs(N[0]) < 0.6 ? [1, 0, 0] : [0, 1, 0];
  let e1 = [t[1] * N[2] - t[2] * N[1], t[2] * N[0] - t[0] * N[2], t[0] * N[1] - t[1] * N[0]];
  const l1 = Math.hypot(e1[0], e1[1], e1[2]);
  e1 = e1.map((v) => v / l1);
  const e2 = [N[1] * e1[2] - N[2] * e1[1], N[2] * e1[0] - N[0] * e1[2], N[0] * e1[1] - N[1] * e1[0]];
  const D = [1 / (a * a), 1 / (b * b), 1 / (c * c)];
  const dot = (u: number[], v: number[]) => u[0] * v[0] * D[0] + u[1] * v[1] * D[1] + u[2] * v[2] * D[2];
  // (p0 + X e1 + Y e2)ᵀ D (…) = 1: Q = [[q11, q12], [q12, q22]], linear L, constant k.
  const q11 = dot(e1, e1),
    q12 = dot(e1, e2),
    q22 = dot(e2, e2);
  const L1 = dot(p0, e1),
    L2 = dot(p0, e2),
    k = dot(p0, p0) - 1;
  const det = q11 * q22 - q12 * q12;
  const X0 = -(q22 * L1 - q12 * L2) / det,
    Y0 = -(-q12 * L1 + q11 * L2) / det;
  const g = -(k + L1 * X0 + L2 * Y0);
  if (!(g > 0)) return null;
  // Eigen-decomposition of Q.
  const tr = q11 + q22,
    disc = Math.sqrt(Math.max(0, (q11 - q22) ** 2 / 4 + q12 * q12));
  const lam1 = tr / 2 + disc,
    lam2 = tr / 2 - disc;
  let v1 = Math.abs(q12) > 1e-300 ? [lam1 - q22, q12] : q11 >= q22 ? [1, 0] : [0, 1];
  const vl = Math.hypot(v1[0], v1[1]);
  v1 = [v1[0] / vl, v1[1] / vl];
  const v2 = [-v1[1], v1[0]];
  const r1 = Math.sqrt(g / lam1),
    r2 = Math.sqrt(g / lam2);
  const centre = [0, 1, 2].map((m) => p0[m] + X0 * e1[m] + Y0 * e2[m]);
  const A1 = [0, 1, 2].map((m) => r1 * (v1[0] * e1[m] + v1[1] * e2[m]));
  const A2 = [0, 1, 2].map((m) => r2 * (v2[0] * e1[m] + v2[1] * e2[m]));
  return (u: number, out: number[]) => {
    const th = 2 * Math.PI * u,
      co = Math.cos(th),
      si = Math.sin(th);
    for (let m = 0; m < 3; m++) out[m] = centre[m] + co * A1[m] + si * A2[m];
  };
}

export function ellipsoidContactsReference(
  sites: ArrayLike<number>,
  count: number,
  a: number,
  b: number,
  c: number,
  cutoff: number,
  samples = 4096,
): PairLengths {
  const curves: Parameters<typeof measureCurves>[0] = [];
  for (let i = 0; i < count; i++) {
    for (let j = i + 1; j < count; j++) {
      const si = [sites[3 * i], sites[3 * i + 1], sites[3 * i + 2]],
        sj = [sites[3 * j], sites[3 * j + 1], sites[3 * j + 2]];
      if (Math.hypot(sj[0] - si[0], sj[1] - si[1], sj[2] - si[2]) > cutoff) continue;
      const n = [sj[0] - si[0], sj[1] - si[1], sj[2] - si[2]];
      const o = 0.5 * (sj[0] ** 2 + sj[1] ** 2 + sj[2] ** 2 - si[0] ** 2 - si[1] ** 2 - si[2] ** 2);
      const at = planeEllipsoidConic(n, o, a, b, c);
      if (!at) continue;
      // Only the part of the conic near the pair can be a contact (cells are smaller than cutoff).
      const keep = (p: number[]) => Math.hypot(p[0] - si[0], p[1] - si[1], p[2] - si[2]) <= 0.6 * cutoff;
      curves.push({ i, j, at, keep });
    }
  }
  return { lengths: measureInChunks(curves, sites, count, samples), count };
}

/** measureCurves over chunks of curves (bounded memory), results summed per pair. */
function measureInChunks(
  curves: Parameters<typeof measureCurves>[0],
  sites: ArrayLike<number>,
  count: number,
  samples: number,
  chunk = 64,
): Map<number, number> {
  const out = new Map<number, number>();
  for (let k = 0; k < curves.length; k += chunk) {
    for (const [key, len] of measureCurves(curves.slice(k, k + chunk), sites, count, samples)) out.set(key, (out.get(key) ?? 0) + len);
  }
  return out;
}

export function meshContactsReference(
  positions: ArrayLike<number>,
  indices: ArrayLike<number>,
  sites: ArrayLike<number>,
  count: number,
  grid = 6,
  samples = 48,
): PairLengths {
  const nf = indices.length / 3;
  const pts: number[] = [];
  const tri: number[] = [];
  for (let f = 0; f < nf; f++) {
    const A = 3 * indices[3 * f],
      B = 3 * indices[3 * f + 1],
      C = 3 * indices[3 * f + 2];
    for (let u = 0; u <= grid; u++) {
      for (let v = 0; v <= grid - u; v++) {
        const wa = 1 - (u + v) / grid,
          wb = u / grid,
          wc = v / grid;
        for (let m = 0; m < 3; m++) pts.push(wa * positions[A + m] + wb * positions[B + m] + wc * positions[C + m]);
        tri.push(f);
      }
    }
  }
  const labels = label(pts, sites, count);
  const sampled: Set<number>[] = Array.from({ length: nf }, () => new Set());
  for (let k = 0; k < tri.length; k++) sampled[tri[k]].add(labels[k]);
  // A cell can reach into a triangle as a sliver between grid samples, but then it owns
  // samples of a triangle around one of its vertices: candidates are the owners of every
  // triangle sharing a vertex.
  const nv = positions.length / 3;
  const around: number[][] = Array.from({ length: nv }, () => []);
  for (let f = 0; f < nf; f++) for (let e = 0; e < 3; e++) around[indices[3 * f + e]].push(f);
  const owners: Set<number>[] = Array.from({ length: nf }, (_, f) => {
    const set = new Set<number>();
    for (let e = 0; e < 3; e++) for (const g of around[indices[3 * f + e]]) for (const o of sampled[g]) set.add(o);
    return set;
  });
  const curves: Parameters<typeof measureCurves>[0] = [];
  for (let f = 0; f < nf; f++) {
    const own = [...owners[f]];
    if (own.length < 2) continue;
    const V = [0, 1, 2].map((e) => [0, 1, 2].map((m) => positions[3 * indices[3 * f + e] + m]));
    for (let x = 0; x < own.length; x++) {
      for (let y = x + 1; y < own.length; y++) {
        const i = own[x],
          j = own[y];
        const n = [0, 1, 2].map((m) => sites[3 * j + m] - sites[3 * i + m]);
        const mid = [0, 1, 2].map((m) => 0.5 * (sites[3 * j + m] + sites[3 * i + m]));
        const d = V.map((P) => (P[0] - mid[0]) * n[0] + (P[1] - mid[1]) * n[1] + (P[2] - mid[2]) * n[2]);
        // Segment where the plane crosses the triangle: the crossing points of its edges.
        const cross: number[][] = [];
        for (let e = 0; e < 3; e++) {
          const e1 = (e + 1) % 3;
          if ((d[e] < 0 && d[e1] >= 0) || (d[e] >= 0 && d[e1] < 0)) {
            const s = d[e] / (d[e] - d[e1]);
            cross.push([0, 1, 2].map((m) => V[e][m] + s * (V[e1][m] - V[e][m])));
          }
        }
        if (cross.length !== 2) continue;
        const [P, Q] = cross;
        curves.push({
          i,
          j,
          at: (u, out) => {
            for (let m = 0; m < 3; m++) out[m] = P[m] + u * (Q[m] - P[m]);
          },
        });
      }
    }
  }
  return { lengths: measureInChunks(curves, sites, count, samples, 2048), count };
}

/** Neighbour sets per cell from pair lengths (pairs longer than `tolerance`). */
export function neighbourLists(ref: PairLengths, tolerance: number): number[][] {
  const lists: number[][] = Array.from({ length: ref.count }, () => []);
  for (const [key, len] of ref.lengths) {
    if (!(len > tolerance)) continue;
    const i = Math.floor(key / ref.count),
      j = key % ref.count;
    lists[i].push(j);
    lists[j].push(i);
  }
  for (const l of lists) l.sort((x, y) => x - y);
  return lists;
}

/** Fraction of cells whose CSR neighbour set equals the reference list, and the cells that differ. */
export function compareNeighbourSets(
  adj: { offsets: Int32Array; neighbours: Int32Array },
  lists: number[][],
): { same: number; fraction: number; differ: number[] } {
  const differ: number[] = [];
  for (let i = 0; i < lists.length; i++) {
    const mine = Array.from(adj.neighbours.subarray(adj.offsets[i], adj.offsets[i + 1])).sort((x, y) => x - y);
    if (mine.join() !== lists[i].join()) differ.push(i);
  }
  return { same: lists.length - differ.length, fraction: (lists.length - differ.length) / lists.length, differ };
}
