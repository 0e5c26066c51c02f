/**
 * Parts 1 and 2 of the GPU check on one case: the jump flood's labels against the exact
 * nearest site, and every centroid path's sums against CPU sums over the exact labels (and over
 * the GPU's own labels, which isolates the centroid pass's arithmetic from the flood's errors).
 */
import type { JumpFloodVariant } from '../../src/core/jumpSchedule';
import type { CentroidPath } from '../../src/gpu/centroidPolicy';
import type { GpuContext } from '../../src/gpu/context';
import { GpuEngine, SUMS_STRIDE } from '../../src/gpu/engine';
import type { FloodCase } from './surfaces';

/** How the flood's labels differ from the exact nearest sites. */
export interface LabelStats {
  readonly texels: number;
  /** Labels that differ from brute force (ties included). */
  readonly differing: number;
  /** Differing, but the GPU's site is as near as the nearest within float32 rounding: acceptable. */
  readonly ties: number;
  /** Differing beyond the tie tolerance (or no site, or an id out of range): the flood's errors. */
  readonly errors: number;
  /** Largest (GPU site's distance − nearest distance) over the errors, in texel edges. */
  readonly worstExcessTexels: number;
  /** One cold flood (passes and a one-texel sync), ms. */
  readonly floodMs: number;
  readonly passes: number;
}

/** A centroid path's sums against CPU sums, as largest relative errors over the cells. */
export interface CentroidStats {
  readonly path: CentroidPath;
  /**
   * Against CPU sums over the GPU's own labels, on the cells the flood labelled exactly: the
   * centroid pass's arithmetic alone (the flood's errors are the labels part's).
   */
  readonly own: CentroidErrors;
  /** Against CPU sums over the brute-force labels, every cell: what Lloyd moves the sites by, flood errors included. */
  readonly exact: CentroidErrors;
  /** Cells owning a texel that the flood labelled unlike brute force (left out of `own`). */
  readonly touched: number;
  readonly sumsMs: number;
}

export interface CentroidErrors {
  /** max |Δ centroid| / cell size (sqrt of the cell's texels, or of its area on a cube map). */
  readonly centroid: number;
  /** max |Δ Σw| / Σw. */
  readonly mass: number;
  /** max |Δ Σw|d|²| / Σw|d|² (the cell's CVT energy). */
  readonly energy: number;
  /** Cells whose centroid, weight or energy error is above the limit asked for. */
  readonly beyond: number;
  /** Cells with a site but no weight in the GPU's sums (never expected: a site owns its texel). */
  readonly emptyCells: number;
}

/**
 * Float32 tie tolerance (µm): the shader computes each distance in float32 from coordinates of
 * magnitude up to `scale` (texel centres, sites, minimum-image wraps; cube-map points read from
 * a float32 image): a few roundings of about 2^-24 · scale in the offsets and 2^-24 relative in
 * the squares and sums. 8 · 2^-24 · (scale + d) bounds those with a factor ~2 to spare; two
 * sites nearer alike than that are a tie that float32 arithmetic cannot order.
 */
export function tieTolerance(scale: number, distance: number): number {
  return 8 * 2 ** -24 * (scale + distance);
}

/** Floods the case (cold) and compares every texel's label with brute force. */
export function checkLabels(context: GpuContext, c: FloodCase, variant: JumpFloodVariant, reference: Int32Array): LabelStats {
  const engine = new GpuEngine(context, c.layout, c.sites, { variant, centroidPath: 'readback' });
  try {
    c.upload(engine);
    engine.floodLabels(); // warm-up: compiles the programs, uploads the textures
    const start = performance.now();
    engine.floodLabels();
    engine.sync();
    const floodMs = performance.now() - start;
    const labels = engine.readLabels();
    let differing = 0,
      ties = 0,
      errors = 0,
      worst = 0;
    for (let k = 0; k < reference.length; k++) {
      const gpu = labels[k];
      const exact = reference[k];
      if (gpu === exact) continue;
      differing++;
      if (gpu < 0 || gpu >= c.sites) {
        errors++;
        worst = Infinity;
        continue;
      }
      const nearest = c.distance(k, exact);
      const excess = c.distance(k, gpu) - nearest;
      if (excess <= tieTolerance(c.scale, nearest)) ties++;
      else {
        errors++;
        worst = Math.max(worst, excess / c.texelEdge);
      }
    }
    return { texels: c.texels, differing, ties, errors, worstExcessTexels: worst, floodMs, passes: engine.lastPassCount };
  } finally {
    engine.dispose();
  }
}

/**
 * One centroid path on the case: flood, sum twice, compare each with the CPU sums over both
 * label images (the largest errors of the two). The second sum is a converged Lloyd loop's: the
 * gather path sizes its windows from the first's cell areas with no margin for moved sites.
 * `limit`: the relative error a cell's own-label sums may have (counted in `beyond`).
 */
export function checkCentroids(
  context: GpuContext,
  c: FloodCase,
  path: CentroidPath,
  reference: Int32Array,
  exactSums: Float64Array,
  limit: number,
): CentroidStats {
  const engine = new GpuEngine(context, c.layout, c.sites, { variant: 'jfa+2', centroidPath: path });
  try {
    c.upload(engine);
    engine.floodLabels();
    const first = engine.computeSums().slice();
    const start = performance.now();
    const second = engine.computeSums().slice();
    const sumsMs = performance.now() - start;
    const labels = engine.readLabels();
    const ownSums = c.sums(labels);
    const texels = texelsPerCell(reference, c.sites);
    const touched = new Uint8Array(c.sites);
    for (let k = 0; k < labels.length; k++) {
      if (labels[k] === reference[k]) continue;
      if (labels[k] >= 0 && labels[k] < c.sites) touched[labels[k]] = 1;
      touched[reference[k]] = 1;
    }
    const compare = (ref: Float64Array, skip: Uint8Array | null) => {
      const a = compareSums(c, first, ref, exactSums, texels, skip, limit);
      const b = compareSums(c, second, ref, exactSums, texels, skip, limit);
      return {
        centroid: Math.max(a.centroid, b.centroid),
        mass: Math.max(a.mass, b.mass),
        energy: Math.max(a.energy, b.energy),
        beyond: Math.max(a.beyond, b.beyond),
        emptyCells: Math.max(a.emptyCells, b.emptyCells),
      };
    };
    return { path, own: compare(ownSums, touched), exact: compare(exactSums, null), touched: touched.reduce((n, t) => n + t, 0), sumsMs };
  } finally {
    engine.dispose();
  }
}

/** Largest relative errors of `gpu` against `reference` over the cells not skipped; cell sizes from the exact cells. */
function compareSums(
  c: FloodCase,
  gpu: Float64Array,
  reference: Float64Array,
  exactSums: Float64Array,
  exactTexels: Int32Array,
  skip: Uint8Array | null,
  limit: number,
): CentroidErrors {
  let centroid = 0,
    mass = 0,
    energy = 0,
    beyond = 0,
    emptyCells = 0;
  for (let i = 0; i < c.sites; i++) {
    const o = SUMS_STRIDE * i;
    const w = reference[o + 3];
    if (!(gpu[o + 3] > 0)) emptyCells++;
    if (skip?.[i]) continue;
    let squared = 0;
    for (let axis = 0; axis < 3; axis++) squared += (gpu[o + axis] / gpu[o + 3] - reference[o + axis] / w) ** 2;
    // NaN (an empty cell on either side) counts as infinitely wrong.
    const errors = [
      Math.sqrt(squared) / c.cellSize(exactSums, exactTexels[i], i),
      Math.abs(gpu[o + 3] - w) / w,
      reference[o + 4] > 0 ? Math.abs(gpu[o + 4] - reference[o + 4]) / reference[o + 4] : 0,
    ].map((e) => (Number.isNaN(e) ? Infinity : e));
    centroid = Math.max(centroid, errors[0]);
    mass = Math.max(mass, errors[1]);
    energy = Math.max(energy, errors[2]);
    if (Math.max(...errors) > limit) beyond++;
  }
  return { centroid, mass, energy, beyond, emptyCells };
}

/** Texels per cell of a label image (for cell sizes). */
export function texelsPerCell(labels: Int32Array, count: number): Int32Array {
  const texels = new Int32Array(count);
  for (const id of labels) if (id >= 0) texels[id]++;
  return texels;
}
