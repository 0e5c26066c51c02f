/**
 * Sparse symmetric matrices (CSR) and a sparse Cholesky factorization.
 *
 * Why a direct solver: the heat method solves the same two matrices for every Voronoi site
 * (and the spherical parameterization one more), so factoring once and doing two triangular
 * solves per right-hand side is what makes repeated distance queries cheap (Crane et al.'s
 * point, and the seed document's). A fill-reducing ordering is what keeps the factor small:
 * we use nested dissection on the matrix graph (BFS level-set separators), which on surface
 * meshes gives O(n log n) fill, far below a banded/envelope factor.
 *
 * The factorization is the up-looking algorithm of CSparse (Davis, "Direct Methods for Sparse
 * Linear Systems", 2006): elimination tree, row patterns by `ereach`, column counts from them,
 * then one numeric pass. All arithmetic is float64.
 */

/** Compressed sparse row matrix. For the symmetric matrices here, rows and columns coincide. */
export interface CsrMatrix {
  n: number;
  rowPtr: Int32Array;
  colIdx: Int32Array;
  values: Float64Array;
}

/** Builds a CSR matrix from (row, col, value) triplets; duplicates are summed. */
export function csrFromTriplets(n: number, rows: ArrayLike<number>, cols: ArrayLike<number>, vals: ArrayLike<number>): CsrMatrix {
  const count = new Int32Array(n + 1);
  for (let k = 0; k < rows.length; k++) count[rows[k] + 1]++;
  for (let i = 0; i < n; i++) count[i + 1] += count[i];
  const fill = count.slice(0, n);
  const c = new Int32Array(rows.length);
  const v = new Float64Array(rows.length);
  for (let k = 0; k < rows.length; k++) {
    const p = fill[rows[k]]++;
    c[p] = cols[k];
    v[p] = vals[k];
  }
  // Sort each row by column and sum duplicates.
  const rowPtr = new Int32Array(n + 1);
  const colIdx: number[] = [];
  const values: number[] = [];
  const order: number[] = [];
  for (let i = 0; i < n; i++) {
    order.length = 0;
    for (let p = count[i]; p < count[i + 1]; p++) order.push(p);
    order.sort((a, b) => c[a] - c[b]);
    let last = -1;
    for (const p of order) {
      if (c[p] === last) values[values.length - 1] += v[p];
      else {
        colIdx.push(c[p]);
        values.push(v[p]);
        last = c[p];
      }
    }
    rowPtr[i + 1] = colIdx.length;
  }
  return { n, rowPtr, colIdx: Int32Array.from(colIdx), values: Float64Array.from(values) };
}

/** Adds d to the diagonal (d: one value per row). The diagonal must be in the pattern. */
export function csrAddDiagonal(A: CsrMatrix, d: ArrayLike<number>, scale = 1): CsrMatrix {
  const values = A.values.slice();
  for (let i = 0; i < A.n; i++) {
    let found = false;
    for (let p = A.rowPtr[i]; p < A.rowPtr[i + 1]; p++) {
      if (A.colIdx[p] === i) {
        values[p] += scale * d[i];
        found = true;
        break;
      }
    }
    if (!found) throw new Error(`csrAddDiagonal: row ${i} has no diagonal entry in its pattern`);
  }
  return { ...A, values };
}

const LEAF_SIZE = 48;

/**
 * Nested-dissection ordering of the graph of A (fill-reducing for Cholesky). Each part is
 * split by the middle BFS level from a pseudo-peripheral vertex; the two halves are ordered
 * first (recursively) and the separating level last, so eliminating a half never fills into
 * the other. Small parts (up to LEAF_SIZE vertices) are ordered by BFS (a Cuthill-McKee-like
 * local order). Returns perm with perm[newIndex] = oldIndex.
 */
function nestedDissection(A: CsrMatrix): Int32Array {
  const n = A.n;
  const inPart = new Int32Array(n).fill(-1); // part stamp
  const level = new Int32Array(n);
  let stamp = 0;
  const queue = new Int32Array(n);

  /** BFS inside the current stamp from `start`; fills `level`, returns visited vertices in order. */
  const bfs = (start: number, partStamp: number, seen: Int32Array, seenStamp: number): Int32Array => {
    let head = 0,
      tail = 0;
    queue[tail++] = start;
    seen[start] = seenStamp;
    level[start] = 0;
    while (head < tail) {
      const v = queue[head++];
      for (let p = A.rowPtr[v]; p < A.rowPtr[v + 1]; p++) {
        const w = A.colIdx[p];
        if (inPart[w] === partStamp && seen[w] !== seenStamp) {
          seen[w] = seenStamp;
          level[w] = level[v] + 1;
          queue[tail++] = w;
        }
      }
    }
    return queue.slice(0, tail);
  };
  const seen = new Int32Array(n).fill(-1);
  let seenStamp = 0;

  const stack: Int32Array[] = [];
  // Process parts with an explicit stack; separators must be numbered after both halves,
  // so we number from the end: a part pushes [separator last] by reserving from the back.
  const order = new Int32Array(n);
  let back = n;
  const all = new Int32Array(n);
  for (let i = 0; i < n; i++) all[i] = i;
  stack.push(all);
  while (stack.length > 0) {
    const part = stack.pop()!;
    const ps = ++stamp;
    for (const v of part) inPart[v] = ps;
    // Connected component of part[0].
    const s0 = ++seenStamp;
    let comp = bfs(part[0], ps, seen, s0);
    if (comp.length < part.length) {
      const rest = part.filter((v) => seen[v] !== s0);
      stack.push(rest);
    }
    if (comp.length <= LEAF_SIZE) {
      for (let k = comp.length - 1; k >= 0; k--) order[--back] = comp[k];
      continue;
    }
    // Pseudo-peripheral start: the last vertex of a BFS, twice.
    for (let it = 0; it < 2; it++) {
      const far = comp[comp.length - 1];
      comp = bfs(far, ps, seen, ++seenStamp);
    }
    const maxLevel = level[comp[comp.length - 1]];
    if (maxLevel < 2) {
      for (let k = comp.length - 1; k >= 0; k--) order[--back] = comp[k];
      continue;
    }
    // Middle level by vertex count.
    const half = comp.length / 2;
    let mid = 1;
    for (let k = 0; k < comp.length; k++) {
      if (k >= half) {
        mid = Math.min(Math.max(level[comp[k]], 1), maxLevel - 1);
        break;
      }
    }
    const sep: number[] = [],
      left: number[] = [],
      right: number[] = [];
    for (const v of comp) {
      if (level[v] === mid) sep.push(v);
      else if (level[v] < mid) left.push(v);
      else right.push(v);
    }
    for (let k = sep.length - 1; k >= 0; k--) order[--back] = sep[k];
    stack.push(Int32Array.from(left));
    stack.push(Int32Array.from(right));
  }
  if (back !== 0) throw new Error('nestedDissection: internal error');
  return order;
}

/** Sparse Cholesky factor P A Pᵀ = L Lᵀ of a symmetric positive definite matrix. */
export class SparseCholesky {
  readonly n: number;
  /** perm[new] = old, and its inverse. */
  readonly perm: Int32Array;
  readonly inv: Int32Array;
  readonly Lp: Int32Array;
  readonly Li: Int32Array;
  readonly Lx: Float64Array;
  private readonly work: Float64Array;

  /**
   * Factors A (full symmetric CSR: both triangles stored). `perm` can be given to reuse an
   * ordering between matrices with the same graph (e.g. M + tL and L in the heat method).
   */
  constructor(A: CsrMatrix, perm?: Int32Array) {
    const n = A.n;
    this.n = n;
    this.perm = perm ?? nestedDissection(A);
    const inv = new Int32Array(n);
    for (let k = 0; k < n; k++) inv[this.perm[k]] = k;
    this.inv = inv;
    // C = P A Pᵀ, upper triangle by columns == lower triangle by rows: column k holds i <= k.
    const Cp = new Int32Array(n + 1);
    for (let i = 0; i < n; i++) {
      for (let p = A.rowPtr[i]; p < A.rowPtr[i + 1]; p++) {
        const a = inv[i],
          b = inv[A.colIdx[p]];
        if (a <= b) Cp[b + 1]++;
      }
    }
    for (let k = 0; k < n; k++) Cp[k + 1] += Cp[k];
    const Ci = new Int32Array(Cp[n]);
    const Cx = new Float64Array(Cp[n]);
    const fill = Cp.slice(0, n);
    for (let i = 0; i < n; i++) {
      for (let p = A.rowPtr[i]; p < A.rowPtr[i + 1]; p++) {
        const a = inv[i],
          b = inv[A.colIdx[p]];
        if (a <= b) {
          const q = fill[b]++;
          Ci[q] = a;
          Cx[q] = A.values[p];
        }
      }
    }
    // Elimination tree (Liu's algorithm with path compression).
    const parent = new Int32Array(n).fill(-1);
    const ancestor = new Int32Array(n).fill(-1);
    for (let k = 0; k < n; k++) {
      for (let p = Cp[k]; p < Cp[k + 1]; p++) {
        let i = Ci[p];
        while (i !== -1 && i < k) {
          const nexti = ancestor[i];
          ancestor[i] = k;
          if (nexti === -1) parent[i] = k;
          i = nexti;
        }
      }
    }
    const mark = new Int32Array(n).fill(-1);
    const s = new Int32Array(n);
    const ereach = (k: number): number => {
      let top = n;
      mark[k] = k;
      for (let p = Cp[k]; p < Cp[k + 1]; p++) {
        let i = Ci[p];
        if (i > k) continue;
        let len = 0;
        while (mark[i] !== k) {
          s[len++] = i;
          mark[i] = k;
          i = parent[i];
        }
        while (len > 0) s[--top] = s[--len];
      }
      return top;
    };
    // Column counts: row k of L has its pattern from ereach(k) plus the diagonal.
    const counts = new Int32Array(n).fill(1);
    for (let k = 0; k < n; k++) {
      const top = ereach(k);
      for (let q = top; q < n; q++) counts[s[q]]++;
    }
    const Lp = new Int32Array(n + 1);
    for (let k = 0; k < n; k++) Lp[k + 1] = Lp[k] + counts[k];
    const Li = new Int32Array(Lp[n]);
    const Lx = new Float64Array(Lp[n]);
    const c = Lp.slice(0, n);
    // Diagonal goes first in each column: reserve it.
    for (let k = 0; k < n; k++) c[k] = Lp[k] + 1;
    const x = new Float64Array(n);
    mark.fill(-1);
    for (let k = 0; k < n; k++) {
      const top = ereach(k);
      x[k] = 0;
      for (let p = Cp[k]; p < Cp[k + 1]; p++) if (Ci[p] <= k) x[Ci[p]] += Cx[p];
      let d = x[k];
      x[k] = 0;
      for (let q = top; q < n; q++) {
        const i = s[q];
        const lki = x[i] / Lx[Lp[i]];
        x[i] = 0;
        for (let p = Lp[i] + 1; p < c[i]; p++) x[Li[p]] -= Lx[p] * lki;
        d -= lki * lki;
        const p = c[i]++;
        Li[p] = k;
        Lx[p] = lki;
      }
      if (!(d > 0)) throw new Error(`SparseCholesky: matrix is not positive definite (pivot ${k}: ${d})`);
      Li[Lp[k]] = k;
      Lx[Lp[k]] = Math.sqrt(d);
    }
    this.Lp = Lp;
    this.Li = Li;
    this.Lx = Lx;
    this.work = new Float64Array(n);
  }

  /** Number of stored entries of L (a measure of the ordering's quality). */
  get nnz(): number {
    return this.Lp[this.n];
  }

  /** Solves A x = b (a new array); b is not modified. */
  solve(b: ArrayLike<number>): Float64Array {
    const { n, Lp, Li, Lx, perm, work: y } = this;
    for (let k = 0; k < n; k++) y[k] = b[perm[k]];
    for (let j = 0; j < n; j++) {
      const yj = (y[j] /= Lx[Lp[j]]);
      if (yj === 0) continue;
      for (let p = Lp[j] + 1; p < Lp[j + 1]; p++) y[Li[p]] -= Lx[p] * yj;
    }
    for (let j = n - 1; j >= 0; j--) {
      let v = y[j];
      for (let p = Lp[j] + 1; p < Lp[j + 1]; p++) v -= Lx[p] * y[Li[p]];
      y[j] = v / Lx[Lp[j]];
    }
    const out = new Float64Array(n);
    for (let k = 0; k < n; k++) out[perm[k]] = y[k];
    return out;
  }
}
