/**
 * Cell density fields: one relative density per texel, sampled at texel centres.
 *
 * The density weights the centroid (cells crowd where it is high: cell diameter scales as
 * density^-1/4) and, when given to placeSites, the initial site distribution. Values are
 * relative (unitless), strictly positive and finite: a zero would make a cell's weight vanish
 * and its centroid undefined.
 *
 * Coordinates: texel (i, j) has its centre at u = (i + 0.5)·texelX, v = (j + 0.5)·texelY µm in
 * the unrolled domain (see grid.ts). "Start of an axis" means coordinate 0.
 */
import type { DensitySpec } from './config';
import { ConfigError } from './config/configError';
import { distanceSquared, type Grid } from './grid';
import { exp } from './exp';

/** A decoded grayscale image. */
export interface GrayImage {
  width: number;
  height: number;
  /** 0 (black) .. 1 (white), row-major, row 0 = top of the image. */
  luminance: Float32Array;
}

/** The density at every texel centre, row-major (index j * width + i). */
export function densityField(spec: DensitySpec, grid: Grid, image?: GrayImage): Float32Array {
  const out = new Float32Array(grid.width * grid.height);
  switch (spec.kind) {
    case 'uniform':
      out.fill(1);
      break;
    case 'linear':
      fillLinear(out, grid, spec.axis, spec.from, spec.to);
      break;
    case 'gaussian':
      fillGaussian(out, grid, spec.center, spec.sigma, spec.peak);
      break;
    case 'stripes':
      fillStripes(out, grid, spec.axis, spec.period, spec.low, spec.high);
      break;
    case 'image':
      if (!image) throw new Error(`density: kind "image" needs the decoded image of ${JSON.stringify(spec.src)}; load it (loadGrayImage) and pass it in`);
      fillImage(out, grid, image, spec.low, spec.high, spec.invert);
      break;
  }
  assertPositiveFinite(out, spec.kind);
  return out;
}

/** Linear from `from` at coordinate 0 to `to` at the far end of the axis. */
function fillLinear(out: Float32Array, grid: Grid, axis: 'x' | 'y', from: number, to: number): void {
  const { width, height } = grid;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const t = axis === 'x' ? (i + 0.5) / width : (j + 0.5) / height;
      out[j * width + i] = from + (to - from) * t;
    }
  }
}

/** 1 + (peak - 1)·exp(-r²/2σ²), r the physical (minimum-image) distance to the centre. */
function fillGaussian(out: Float32Array, grid: Grid, center: readonly [number, number], sigma: number, peak: number): void {
  const { width, height } = grid;
  // Centre in texel units, so distanceSquared applies the wrap and the texel sizes.
  const cx = center[0] / grid.texelX;
  const cy = center[1] / grid.texelY;
  const scale = -1 / (2 * sigma * sigma);
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const r2 = distanceSquared(grid, cx, cy, i + 0.5, j + 0.5);
      out[j * width + i] = 1 + (peak - 1) * exp(r2 * scale);
    }
  }
}

/**
 * Square wave: `low` on the first half of each period, `high` on the second, periods starting at
 * coordinate 0. A period equal to the axis length gives two halves (low, then high).
 */
function fillStripes(out: Float32Array, grid: Grid, axis: 'x' | 'y', period: number, low: number, high: number): void {
  const { width, height } = grid;
  for (let j = 0; j < height; j++) {
    for (let i = 0; i < width; i++) {
      const t = axis === 'x' ? (i + 0.5) * grid.texelX : (j + 0.5) * grid.texelY;
      const phase = t / period - Math.floor(t / period);
      out[j * width + i] = phase < 0.5 ? low : high;
    }
  }
}

/**
 * The image stretched over the whole unrolled domain, upright when the domain is drawn with y
 * pointing up: the image's left column is at x = 0, its TOP row at y = height (the far end of
 * the axis), its bottom row at y = 0. Sampling is bilinear between image pixel centres; a
 * periodic axis wraps (so the seam of a tube is seamless), an open axis clamps to the edge.
 */
function fillImage(out: Float32Array, grid: Grid, image: GrayImage, low: number, high: number, invert: boolean): void {
  const { width: iw, height: ih, luminance } = image;
  if (!(iw >= 1 && ih >= 1 && Number.isInteger(iw) && Number.isInteger(ih)) || luminance.length !== iw * ih) {
    throw new Error(`density image: ${iw} x ${ih} pixels with ${luminance.length} values is inconsistent; it needs width*height luminance values`);
  }
  const { width, height } = grid;
  for (let j = 0; j < height; j++) {
    // Continuous image row (pixel centres at q + 0.5), counted from the top.
    const py = (1 - (j + 0.5) / height) * ih - 0.5;
    for (let i = 0; i < width; i++) {
      const px = ((i + 0.5) / width) * iw - 0.5;
      let l = bilinear(luminance, iw, ih, px, py, grid.periodicX, grid.periodicY);
      if (invert) l = 1 - l;
      out[j * width + i] = low + (high - low) * l;
    }
  }
}

function bilinear(values: Float32Array, w: number, h: number, x: number, y: number, wrapX: boolean, wrapY: boolean): number {
  const x0 = Math.floor(x);
  const y0 = Math.floor(y);
  const fx = x - x0;
  const fy = y - y0;
  const ia = index(x0, w, wrapX);
  const ib = index(x0 + 1, w, wrapX);
  const ja = index(y0, h, wrapY) * w;
  const jb = index(y0 + 1, h, wrapY) * w;
  const top = values[ja + ia] * (1 - fx) + values[ja + ib] * fx;
  const bottom = values[jb + ia] * (1 - fx) + values[jb + ib] * fx;
  return top * (1 - fy) + bottom * fy;
}

function index(k: number, n: number, wrap: boolean): number {
  if (wrap) return ((k % n) + n) % n;
  return k < 0 ? 0 : k >= n ? n - 1 : k;
}

function assertPositiveFinite(values: Float32Array, kind: string): void {
  for (let k = 0; k < values.length; k++) {
    const v = values[k];
    if (!(v > 0 && Number.isFinite(v))) {
      throw new ConfigError(
        'density',
        `density "${kind}": value ${v} at texel ${k} is not positive and finite; densities must be > 0 (check low/high/from/to/peak and the image's luminance)`,
      );
    }
  }
}
