/**
 * The "Flintstones law" of Gómez-Gálvez et al. 2022 (Cell Systems 13:631–643): the mean number
 * of 3D neighbours n3D of a cell in a tube grows with the surface ratio s and saturates.
 *
 * Functional form (as fitted in the lab's released code, Epithelia3D,
 * InSilicoModels/TubularModel/src/lib/fittingLogFunc.m):
 *
 *   n3D(s) = Nmax · (b + e^{s/c}) / (d + e^{s/c}),
 *
 * with the anchor n3D(1) = n1 (6 in the lab's fit: a cell of a planar tessellation has 6
 * neighbours on average) fixing b = (n1·d − e^{1/c}(Nmax − n1)) / Nmax. Free parameters: Nmax
 * (the saturation value), c (> 0, the ratio scale) and d (< 0 with d + e^{1/c} > 0, so the
 * curve is finite for s >= 1), as in that script's constraints. With `anchor: null`, b is a
 * fourth free parameter.
 *
 * Fit: nonlinear least squares (Levenberg–Marquardt from a few starting points, numerical
 * Jacobian by central differences), weights 1/σ² when σ is given. Standard errors from the
 * covariance s²·(JᵀWJ)⁻¹ with s² = χ²/(m − p) (the convention of scipy's curve_fit and MATLAB's
 * fit: residual scatter sets the scale). e^x by src/core/exp.ts, not Math.exp: the same bits
 * in Node and in every browser, so a sweep's fits are the same in the CLI and the page.
 */
import { exp } from '../exp';

export interface FlintstonesPoint {
  /** Surface ratio. */
  readonly s: number;
  /** Mean number of 3D neighbours at s (one realization, or a mean over several). */
  readonly n: number;
  /** Standard deviation of n (optional; weights the fit by 1/σ²). */
  readonly sigma?: number;
}

export interface FlintstonesParameters {
  readonly nMax: number;
  readonly c: number;
  readonly d: number;
  readonly b: number;
}

export interface FlintstonesFit {
  readonly parameters: FlintstonesParameters;
  /** Standard errors of nMax, c, d (and b when it was free; NaN when anchored). */
  readonly standardErrors: FlintstonesParameters;
  /** Covariance of the free parameters, row-major, in the order nMax, c, d[, b]. */
  readonly covariance: number[];
  readonly anchor: number | null;
  /** Sum of weighted squared residuals. */
  readonly chiSquared: number;
  readonly degreesOfFreedom: number;
  readonly rSquared: number;
  readonly iterations: number;
  readonly converged: boolean;
}

export interface FlintstonesOptions {
  /** n3D(1); null makes b a free parameter. Default 6 (the lab's fit). */
  readonly anchor?: number | null;
  readonly maxIterations?: number;
}

/** b from the anchor n3D(1) = n1. */
export function anchoredB(nMax: number, c: number, d: number, n1: number): number {
  return (n1 * d - exp(1 / c) * (nMax - n1)) / nMax;
}

/** n3D(s) for the given parameters. */
export function flintstonesLaw(s: number, p: FlintstonesParameters): number {
  const e = exp(s / p.c);
  return (p.nMax * (p.b + e)) / (p.d + e);
}

function parametersOf(theta: number[], anchor: number | null): FlintstonesParameters {
  const [nMax, c, d] = theta;
  const b = anchor === null ? theta[3] : anchoredB(nMax, c, d, anchor);
  return { nMax, c, d, b };
}

/** The constraints of the lab's fit (fittingLogFunc.m): c > 0, d < 0, d > b, d + e^{1/c} > 0. */
function admissible(theta: number[], anchor: number | null, sMin: number): boolean {
  const p = parametersOf(theta, anchor);
  return p.c > 0.02 && p.d < 0 && p.d > p.b && p.d + exp(sMin / p.c) > 0 && p.nMax > 0 && Number.isFinite(p.b);
}

/**
 * The points as the fit reads them: one row per distinct ratio. A sweep gives one point per run,
 * so each ratio as many times as there are realizations, and the law takes one value per ratio:
 * with weights w = 1/sigma (else 1), the points at ratio r add up to
 *
 *   sum_k w_k^2 (n_k - f_r)^2 = W_r (m_r - f_r)^2 + within_r,
 *
 * W_r = sum w_k^2, m_r = their weighted mean, within_r = sum w_k^2 (n_k - m_r)^2 (which no
 * parameter changes). So the fit iterates on residuals sqrt(W_r) (m_r - f_r), one per ratio
 * (JᵀWJ and JᵀWr are those of the points), and chi² adds the constant `within`: the same
 * problem as one residual per point, a realization count times cheaper per iteration.
 */
interface FitData {
  readonly ratios: Float64Array;
  /** Per ratio: sqrt(W_r) and the weighted mean m_r. */
  readonly root: Float64Array;
  readonly mean: Float64Array;
  /** chi² of the points about their ratios' means. */
  readonly within: number;
  /** Scratch: the residuals either side of a parameter. */
  readonly plus: Float64Array;
  readonly minus: Float64Array;
  /**
   * e^{s_r/c} per ratio and e^{1/c}, for the c they were computed at: most residual evaluations
   * (the Jacobian's steps in nMax and d, tries that change only them) keep c, and the
   * exponentials were most of a fit's time. The same calls on the same c: the same bits.
   */
  readonly exps: Float64Array;
  expOne: number;
  expC: number;
  /** Scratch: theta stepped either side of a parameter (the Jacobian). */
  readonly thetaPlus: number[];
  readonly thetaMinus: number[];
}

function fitData(points: readonly FlintstonesPoint[]): FitData {
  const index = new Map<number, number>();
  const at = points.map((q) => {
    let i = index.get(q.s);
    if (i === undefined) index.set(q.s, (i = index.size));
    return i;
  });
  const count = index.size;
  const ratios = Float64Array.from(index.keys());
  const weights = new Float64Array(count);
  const sums = new Float64Array(count);
  const w2 = (q: FlintstonesPoint) => (q.sigma ? 1 / (q.sigma * q.sigma) : 1);
  points.forEach((q, k) => {
    weights[at[k]] += w2(q);
    sums[at[k]] += w2(q) * q.n;
  });
  const mean = sums.map((sum, i) => sum / weights[i]);
  let within = 0;
  points.forEach((q, k) => (within += w2(q) * (q.n - mean[at[k]]) ** 2));
  return {
    ratios,
    root: weights.map(Math.sqrt),
    mean,
    within,
    plus: new Float64Array(count),
    minus: new Float64Array(count),
    exps: new Float64Array(count),
    expOne: NaN,
    expC: NaN,
    thetaPlus: [],
    thetaMinus: [],
  };
}

/** chi² of the points at theta, with the per-ratio residuals into `out`. */
function residuals(theta: number[], data: FitData, anchor: number | null, out: Float64Array): number {
  const { ratios, root, mean, exps } = data;
  const [nMax, c, d] = theta;
  if (!Object.is(c, data.expC)) {
    for (let i = 0; i < ratios.length; i++) exps[i] = exp(ratios[i] / c);
    data.expOne = exp(1 / c);
    data.expC = c;
  }
  // parametersOf and flintstonesLaw, term for term, with the kept exponentials.
  const b = anchor === null ? theta[3] : (anchor * d - data.expOne * (nMax - anchor)) / nMax;
  let chi = data.within;
  for (let i = 0; i < ratios.length; i++) {
    const e = exps[i];
    const r = (mean[i] - (nMax * (b + e)) / (d + e)) * root[i];
    out[i] = r;
    chi += r * r;
  }
  return chi;
}

/**
 * Central differences of the per-ratio residuals, into `J` (one row of theta.length per ratio,
 * row-major; reused across iterations).
 */
function jacobian(theta: number[], data: FitData, anchor: number | null, J = new Float64Array(data.ratios.length * theta.length)): Float64Array {
  const m = data.ratios.length;
  const p = theta.length;
  const plus = data.plus;
  const minus = data.minus;
  const tp = data.thetaPlus;
  const tm = data.thetaMinus;
  for (let j = 0; j < p; j++) {
    const h = 1e-6 * Math.max(1, Math.abs(theta[j]));
    for (let i = 0; i < p; i++) tp[i] = tm[i] = theta[i];
    tp.length = tm.length = p;
    tp[j] += h;
    tm[j] -= h;
    residuals(tp, data, anchor, plus);
    residuals(tm, data, anchor, minus);
    // Residuals are (data - model): the model's derivative is minus their derivative.
    for (let k = 0; k < m; k++) J[k * p + j] = -(plus[k] - minus[k]) / (2 * h);
  }
  return J;
}

/** Buffers of one size of solveSpd (its result is `x`, overwritten by the next solve). */
interface SpdScratch {
  readonly L: number[][];
  readonly z: number[];
  readonly x: number[];
}

function spdScratch(n: number): SpdScratch {
  return { L: zeroMatrix(n), z: new Array<number>(n).fill(0), x: new Array<number>(n).fill(0) };
}

/**
 * Solves A x = y for a small symmetric positive definite A (Cholesky); null when singular. The
 * result is `scratch.x` (a fresh scratch by default).
 */
function solveSpd(A: number[][], y: number[], scratch: SpdScratch = spdScratch(y.length)): number[] | null {
  const n = y.length;
  const { L, z, x } = scratch;
  for (let i = 0; i < n; i++) {
    for (let j = 0; j <= i; j++) {
      let sum = A[i][j];
      for (let k = 0; k < j; k++) sum -= L[i][k] * L[j][k];
      if (i === j) {
        if (!(sum > 0)) return null;
        L[i][i] = Math.sqrt(sum);
      } else L[i][j] = sum / L[j][j];
    }
  }
  for (let i = 0; i < n; i++) {
    let sum = y[i];
    for (let k = 0; k < i; k++) sum -= L[i][k] * z[k];
    z[i] = sum / L[i][i];
  }
  for (let i = n - 1; i >= 0; i--) {
    let sum = z[i];
    for (let k = i + 1; k < n; k++) sum -= L[k][i] * x[k];
    x[i] = sum / L[i][i];
  }
  return x;
}

/** An n x n matrix of zeros (rows as arrays; a plain loop: Array.from with a mapper cost the fits a good part of their time). */
function zeroMatrix(n: number): number[][] {
  const rows: number[][] = [];
  for (let i = 0; i < n; i++) rows.push(new Array<number>(n).fill(0));
  return rows;
}

/** JᵀJ and Jᵀr of the row-major m x p Jacobian (summed over the rows in order), into A and g (fresh by default). */
function normalEquations(J: Float64Array, p: number, r: ArrayLike<number>, A = zeroMatrix(p), g = new Array<number>(p)): { A: number[][]; g: number[] } {
  const m = J.length / p;
  for (let i = 0; i < p; i++) {
    g[i] = 0;
    A[i].fill(0);
  }
  for (let k = 0; k < m; k++) {
    const row = k * p;
    for (let i = 0; i < p; i++) {
      const Ji = J[row + i];
      g[i] += Ji * r[k];
      const Ai = A[i];
      for (let j = 0; j < p; j++) Ai[j] += Ji * J[row + j];
    }
  }
  return { A, g };
}

function levenbergMarquardt(start: number[], data: FitData, anchor: number | null, sMin: number, maxIterations: number) {
  let theta = start.slice();
  const r = new Float64Array(data.ratios.length);
  const trial = new Float64Array(data.ratios.length);
  let chi = residuals(theta, data, anchor, r);
  const J = new Float64Array(data.ratios.length * theta.length);
  const damped = zeroMatrix(theta.length);
  const normal = { A: zeroMatrix(theta.length), g: new Array<number>(theta.length) };
  const scratch = spdScratch(theta.length);
  // The trial point, swapped with theta when it is taken.
  let next = theta.slice();
  let lambda = 1e-3;
  let iterations = 0;
  let converged = false;
  for (; iterations < maxIterations; iterations++) {
    jacobian(theta, data, anchor, J);
    const { A, g } = normalEquations(J, theta.length, r, normal.A, normal.g);
    let improved = false;
    while (lambda < 1e12) {
      // A with its diagonal damped, into one matrix reused across tries.
      for (let i = 0; i < A.length; i++) for (let j = 0; j < A.length; j++) damped[i][j] = i === j ? A[i][j] * (1 + lambda) + 1e-15 : A[i][j];
      const step = solveSpd(damped, g, scratch);
      if (step) {
        for (let i = 0; i < theta.length; i++) next[i] = theta[i] + step[i];
        if (admissible(next, anchor, sMin)) {
          const chiNext = residuals(next, data, anchor, trial);
          if (chiNext < chi) {
            const relative = (chi - chiNext) / Math.max(chi, 1e-300);
            [theta, next] = [next, theta];
            chi = chiNext;
            r.set(trial);
            lambda = Math.max(lambda / 10, 1e-12);
            improved = true;
            if (relative < 1e-12) converged = true;
            break;
          }
        }
      }
      lambda *= 10;
    }
    if (!improved) {
      converged = true;
      break;
    }
    if (converged) break;
  }
  return { theta, chi, iterations, converged };
}

/** Fits the law to points (s, n3D) of one Voronoi k; see the module comment. */
export function fitFlintstones(points: readonly FlintstonesPoint[], options: FlintstonesOptions = {}): FlintstonesFit {
  const anchor = options.anchor === undefined ? 6 : options.anchor;
  const p = anchor === null ? 4 : 3;
  if (points.length <= p) throw new Error(`fitFlintstones: ${points.length} points cannot fit ${p} parameters; give more ratios`);
  for (const q of points) {
    if (!(Number.isFinite(q.s) && q.s > 0 && Number.isFinite(q.n))) throw new Error(`fitFlintstones: point (${q.s}, ${q.n}) is not a finite ratio > 0 and n3D`);
    if (q.sigma !== undefined && !(q.sigma > 0)) throw new Error(`fitFlintstones: sigma ${q.sigma} at s = ${q.s} must be > 0`);
  }
  const sMin = Math.min(...points.map((q) => q.s));
  const sMax = Math.max(...points.map((q) => q.s));
  const nTop = Math.max(...points.map((q) => q.n));
  const n1 = anchor ?? Math.min(...points.map((q) => q.n));
  const maxIterations = options.maxIterations ?? 500;

  const data = fitData(points);
  let best: ReturnType<typeof levenbergMarquardt> | null = null;
  for (const cScale of [0.1, 0.25, 0.5, 1]) {
    for (const dFraction of [0.2, 0.6, 0.95]) {
      const c = cScale * sMax;
      const d = -dFraction * exp(sMin / c);
      const nMax = nTop + 0.3;
      const start = anchor === null ? [nMax, c, d, anchoredB(nMax, c, d, n1)] : [nMax, c, d];
      if (!admissible(start, anchor, sMin)) continue;
      const fit = levenbergMarquardt(start, data, anchor, sMin, maxIterations);
      if (!best || fit.chi < best.chi) best = fit;
    }
  }
  if (!best) throw new Error('fitFlintstones: no admissible starting point; check that n3D grows with s');

  const J = jacobian(best.theta, data, anchor);
  const { A } = normalEquations(J, p, new Float64Array(data.ratios.length));
  const dof = points.length - p;
  const scale = best.chi / dof;
  const covariance: number[] = [];
  const columns: number[][] = [];
  for (let j = 0; j < p; j++) {
    const unit = new Array(p).fill(0);
    unit[j] = 1;
    columns.push(solveSpd(A, unit)?.map((v) => v * scale) ?? new Array(p).fill(NaN));
  }
  for (let i = 0; i < p; i++) for (let j = 0; j < p; j++) covariance.push(columns[j][i]);
  const se = (j: number) => Math.sqrt(columns[j][j]);

  const parameters = parametersOf(best.theta, anchor);
  let mean = 0;
  for (const q of points) mean += q.n;
  mean /= points.length;
  let total = 0;
  let residual = 0;
  for (const q of points) {
    total += (q.n - mean) ** 2;
    residual += (q.n - flintstonesLaw(q.s, parameters)) ** 2;
  }
  return {
    parameters,
    standardErrors: { nMax: se(0), c: se(1), d: se(2), b: anchor === null ? se(3) : NaN },
    covariance,
    anchor,
    chiSquared: best.chi,
    degreesOfFreedom: dof,
    rSquared: total > 0 ? 1 - residual / total : NaN,
    iterations: best.iterations,
    converged: best.converged,
  };
}
