/**
 * Exact integrals of a density over a Voronoi cell: the weight ∫ρ, the first moments ∫ρ(x - z)
 * and the CVT energy ∫ρ|x - z|² of the cell of site z (µm, relative to the site).
 *
 * How each density is integrated (the exact engine's contract, see docs/protocols.md):
 * - uniform: closed-form polygon moments (shoelace-type formulas): exact to rounding.
 * - The cell is first cut along every line where the density is not smooth: stripe edges
 *   (multiples of period/2), the seam of a periodic axis (multiples of its length) for linear
 *   and stripes, the antipode of a gaussian's centre on a periodic axis (its minimum-image
 *   distance has a kink there), and every texel edge for a per-texel field. Each piece is convex.
 * - stripes and per-texel fields ("texels", what an image density becomes) are constant on each
 *   piece: closed-form moments times the value: exact per-texel coverage of the piecewise-
 *   constant field (not bilinear).
 * - linear and gaussian: each piece is fanned into triangles and integrated with the 7-point
 *   degree-5 rule (Radon's formula as tabulated by Dunavant 1985, exact for polynomials of
 *   degree <= 5). For linear densities the integrands are polynomials of degree <= 3: exact to
 *   rounding. For gaussians each triangle is split into m² similar triangles with edges of at most
 *   σ/2 (m <= 16); the rule's error is O((h/σ)^6), measured below 1e-6 relative in the tests.
 */
import type { DensitySpec, GaussianDensity, LinearDensity, StripesDensity } from '../config';
import { densityField, type GrayImage } from '../density';
import { wrapDelta, type Grid } from '../grid';
import { exp } from '../exp';
import { clipHalfPlane, PolygonBuffer, polygonExtent, polygonMoments } from './polygon';

/** A density the exact engine integrates (analytic, or piecewise constant per texel). */
export type ExactDensity =
  { readonly kind: 'uniform' } | LinearDensity | GaussianDensity | StripesDensity | { readonly kind: 'texels'; readonly field: Float32Array };

/** The exact engine's form of a config density: analytic kinds as they are, images per texel. */
export function exactDensity(spec: DensitySpec, grid: Grid, image?: GrayImage): ExactDensity {
  if (spec.kind === 'image') return { kind: 'texels', field: densityField(spec, grid, image) };
  return spec;
}

/** Degree-5, 7-point rule on a triangle: barycentric (a, b, b) orbits and weights (sum 1). */
const RULE_A = [1 / 3, 0.05971587178977, 0.470142064105115, 0.470142064105115, 0.797426985353087, 0.101286507323456, 0.101286507323456];
const RULE_B = [1 / 3, 0.470142064105115, 0.05971587178977, 0.470142064105115, 0.101286507323456, 0.797426985353087, 0.101286507323456];
const RULE_W = [0.225, 0.132394152788506, 0.132394152788506, 0.132394152788506, 0.125939180544827, 0.125939180544827, 0.125939180544827];

interface CutFamily {
  offset: number;
  step: number;
}

export class CellIntegrator {
  private readonly widthUm: number;
  private readonly heightUm: number;
  private readonly cuts: [CutFamily[], CutFamily[]] = [[], []];
  private readonly smooth: boolean;
  private readonly piece = new Float64Array(4);
  private readonly extent = new Float64Array(2);
  private readonly buffers = Array.from({ length: 6 }, () => new PolygonBuffer());
  private siteX = 0;
  private siteY = 0;
  private acc!: Float64Array;
  private accOffset = 0;

  constructor(
    readonly grid: Grid,
    readonly density: ExactDensity,
  ) {
    this.widthUm = grid.width * grid.texelX;
    this.heightUm = grid.height * grid.texelY;
    const periodic = [grid.periodicX, grid.periodicY];
    const length = [this.widthUm, this.heightUm];
    const axisIndex = (axis: 'x' | 'y') => (axis === 'x' ? 0 : 1);
    switch (density.kind) {
      case 'uniform':
        break;
      case 'linear': {
        const a = axisIndex(density.axis);
        if (periodic[a]) this.cuts[a].push({ offset: 0, step: length[a] });
        break;
      }
      case 'stripes': {
        const a = axisIndex(density.axis);
        if (!(density.period > 0)) throw new Error(`density.period must be > 0 µm (got ${density.period})`);
        this.cuts[a].push({ offset: 0, step: density.period / 2 });
        if (periodic[a]) this.cuts[a].push({ offset: 0, step: length[a] });
        break;
      }
      case 'gaussian':
        if (!(density.sigma > 0)) throw new Error(`density.sigma must be > 0 µm (got ${density.sigma})`);
        for (const a of [0, 1] as const) if (periodic[a]) this.cuts[a].push({ offset: density.center[a] + length[a] / 2, step: length[a] });
        break;
      case 'texels':
        if (density.field.length !== grid.width * grid.height) {
          throw new Error(`density field has ${density.field.length} values but the grid has ${grid.width * grid.height} texels`);
        }
        this.cuts[0].push({ offset: 0, step: grid.texelX });
        this.cuts[1].push({ offset: 0, step: grid.texelY });
        break;
    }
    this.smooth = density.kind === 'linear' || density.kind === 'gaussian';
  }

  /**
   * Adds [∫ρ, ∫ρ(x - z_x), ∫ρ(y - z_y), ∫ρ|x - z|²] of the cell (polygon relative to the site,
   * µm; site at absolute (siteX, siteY) µm, unwrapped) to out[offset .. offset + 3].
   */
  integrate(cell: PolygonBuffer, siteX: number, siteY: number, out: Float64Array, offset: number): void {
    if (cell.count < 3) return;
    if (this.density.kind === 'uniform') {
      polygonMoments(cell.xy, cell.count, this.piece);
      for (let k = 0; k < 4; k++) out[offset + k] += this.piece[k];
      return;
    }
    this.siteX = siteX;
    this.siteY = siteY;
    this.acc = out;
    this.accOffset = offset;
    this.sweep(cell, 0, 0);
  }

  /** Cuts `poly` at every cut line of `axis` inside it; recurses to y, then integrates pieces. */
  private sweep(poly: PolygonBuffer, axis: 0 | 1, midX: number): void {
    const families = this.cuts[axis];
    const origin = axis === 0 ? this.siteX : this.siteY;
    polygonExtent(poly.xy, poly.count, axis, this.extent);
    const lo = this.extent[0] + origin;
    const hi = this.extent[1] + origin;
    const base = axis * 3;
    const left = this.buffers[base];
    let rest = poly;
    let spare = this.buffers[base + 1];
    let other = this.buffers[base + 2];
    let from = lo;
    let cut = nextCut(families, lo);
    while (cut < hi) {
      clipHalfPlane(rest, left, axis, cut - origin, -1, 0);
      clipHalfPlane(rest, spare, axis, cut - origin, 1, 0);
      this.visit(left, axis, (from + cut) / 2, midX);
      rest = spare;
      [spare, other] = [other, spare];
      from = cut;
      cut = nextCut(families, cut);
    }
    this.visit(rest, axis, (from + hi) / 2, midX);
  }

  private visit(piece: PolygonBuffer, axis: 0 | 1, mid: number, midX: number): void {
    if (piece.count < 3) return;
    if (axis === 0) {
      this.sweep(piece, 1, mid);
      return;
    }
    if (this.smooth) {
      this.quadrature(piece);
      return;
    }
    const value = this.constantValue(midX, mid);
    polygonMoments(piece.xy, piece.count, this.piece);
    for (let k = 0; k < 4; k++) this.acc[this.accOffset + k] += value * this.piece[k];
  }

  /** Value of a piecewise-constant density at an absolute point (µm) strictly inside a piece. */
  private constantValue(x: number, y: number): number {
    const { grid, density } = this;
    if (density.kind === 'texels') {
      const i = texelIndex(x / grid.texelX, grid.width, grid.periodicX);
      const j = texelIndex(y / grid.texelY, grid.height, grid.periodicY);
      return density.field[j * grid.width + i];
    }
    if (density.kind === 'stripes') {
      const a = density.axis === 'x' ? 0 : 1;
      let t = a === 0 ? x : y;
      const length = a === 0 ? this.widthUm : this.heightUm;
      if (a === 0 ? grid.periodicX : grid.periodicY) t -= Math.floor(t / length) * length;
      const phase = t / density.period - Math.floor(t / density.period);
      return phase < 0.5 ? density.low : density.high;
    }
    return 1;
  }

  /** Value of a smooth density (linear, gaussian) at an absolute point (µm). */
  private smoothValue(x: number, y: number): number {
    const { grid, density } = this;
    if (density.kind === 'linear') {
      const a = density.axis === 'x' ? 0 : 1;
      let t = a === 0 ? x : y;
      const length = a === 0 ? this.widthUm : this.heightUm;
      if (a === 0 ? grid.periodicX : grid.periodicY) t -= Math.floor(t / length) * length;
      return density.from + ((density.to - density.from) * t) / length;
    }
    if (density.kind === 'gaussian') {
      const dx = wrapDelta(x - density.center[0], this.widthUm, grid.periodicX);
      const dy = wrapDelta(y - density.center[1], this.heightUm, grid.periodicY);
      return 1 + (density.peak - 1) * exp(-(dx * dx + dy * dy) / (2 * density.sigma * density.sigma));
    }
    return 1;
  }

  /** Fan of the piece from its first vertex, each triangle split m x m and integrated by the rule. */
  private quadrature(piece: PolygonBuffer): void {
    const xy = piece.xy;
    const ax = xy[0];
    const ay = xy[1];
    const sigma = this.density.kind === 'gaussian' ? this.density.sigma : Infinity;
    for (let k = 1; k + 1 < piece.count; k++) {
      const bx = xy[2 * k];
      const by = xy[2 * k + 1];
      const cx = xy[2 * k + 2];
      const cy = xy[2 * k + 3];
      const diameter = Math.max(Math.hypot(bx - ax, by - ay), Math.hypot(cx - ax, cy - ay), Math.hypot(cx - bx, cy - by));
      const m = Math.min(16, Math.max(1, Math.ceil(diameter / (0.5 * sigma))));
      const area = Math.abs((bx - ax) * (cy - ay) - (cx - ax) * (by - ay)) / 2 / (m * m);
      const ux = (bx - ax) / m;
      const uy = (by - ay) / m;
      const vx = (cx - ax) / m;
      const vy = (cy - ay) / m;
      for (let p = 0; p < m; p++) {
        for (let q = 0; p + q < m; q++) {
          const ox = ax + p * ux + q * vx;
          const oy = ay + p * uy + q * vy;
          // Upright sub-triangle (o, o+u, o+v), then the inverted one (o+u, o+u+v, o+v).
          this.triangleRule(ox, oy, ox + ux, oy + uy, ox + vx, oy + vy, area);
          if (p + q + 1 < m) this.triangleRule(ox + ux, oy + uy, ox + ux + vx, oy + uy + vy, ox + vx, oy + vy, area);
        }
      }
    }
  }

  private triangleRule(ax: number, ay: number, bx: number, by: number, cx: number, cy: number, area: number): void {
    let w = 0;
    let mx = 0;
    let my = 0;
    let e = 0;
    for (let r = 0; r < 7; r++) {
      const a = RULE_A[r];
      const b = RULE_B[r];
      const c = 1 - a - b;
      const x = a * ax + b * bx + c * cx;
      const y = a * ay + b * by + c * cy;
      const rho = RULE_W[r] * this.smoothValue(x + this.siteX, y + this.siteY);
      w += rho;
      mx += rho * x;
      my += rho * y;
      e += rho * (x * x + y * y);
    }
    const out = this.acc;
    const o = this.accOffset;
    out[o] += w * area;
    out[o + 1] += mx * area;
    out[o + 2] += my * area;
    out[o + 3] += e * area;
  }
}

/** Smallest cut strictly greater than `after` over every family (Infinity when none). */
function nextCut(families: CutFamily[], after: number): number {
  let best = Infinity;
  for (const { offset, step } of families) {
    const k = Math.floor((after - offset) / step) + 1;
    let cut = offset + k * step;
    if (cut <= after) cut += step;
    if (cut < best) best = cut;
  }
  return best;
}

function texelIndex(t: number, n: number, periodic: boolean): number {
  const k = Math.floor(t);
  if (periodic) return ((k % n) + n) % n;
  return k < 0 ? 0 : k >= n ? n - 1 : k;
}
