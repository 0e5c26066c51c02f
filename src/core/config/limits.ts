/**
 * Scale guards and a compute budget: what a validated configuration would cost, and refusals
 * (one-line ConfigErrors naming the field) for what cannot be computed honestly or affordably.
 * Pure: the caller supplies the GPU's texture limit and the budget (bytes, work).
 *
 * - Extents: every length (plane width/height, tube radius/length, sphere radius, ellipsoid
 *   semi-axes, sheet thickness) must lie in [MIN_EXTENT_UM, MAX_EXTENT_UM]. Beyond them float32
 *   arithmetic on the GPU breaks down: a plane 1e20 µm wide gives an infinite Lloyd energy
 *   (µm⁴ overflows float32), one 1e-20 µm wide an exact Delaunay with no neighbours.
 * - Texels per side: every surface of the stack needs at least MIN_TEXELS_PER_SIDE texels along
 *   each side; a tube with one texel around has every cell touching itself across the seam.
 * - Texture size: every surface's grid (a tube's other surface is wider by the surface ratio;
 *   a closed surface's cube map is n x 6n) must fit the GPU's largest texture.
 * - Work: texel-floods = seeded texels x lloyd.maxIterations + the texels of every surface
 *   labelled once (one jump flood each); bytes: see estimateRun. Both are estimated before
 *   anything is allocated and compared with the caller's budget.
 */
import { unrolledDomain } from './feasibility';
import { maxResolution, surfaceLayout } from './surfaceLayout';
import type { Config, PlanarConfig } from './types';
import { ConfigError } from './validate';

export const MIN_EXTENT_UM = 1e-3;
export const MAX_EXTENT_UM = 1e7;
const MIN_TEXELS_PER_SIDE = 8;
/** Default work budget: 2^34 texel-floods (a 16384² plane for 64 iterations). */
export const DEFAULT_MAX_WORK = 2 ** 34;

/**
 * Bytes per texel of the surface being computed (GPU: two RGBA32F label targets of site
 * coordinates and ids, the packed-id target and the weight texture, 40; CPU: density, weights,
 * label readback and adjacency) and per texel of every surface kept until the result is
 * written (Int32 labels + adjacency).
 */
const ACTIVE_BYTES_PER_TEXEL = 76;
/** The exact engine: the density field and the placement density (float32 each). */
const EXACT_BYTES_PER_TEXEL = 8;
const KEPT_BYTES_PER_TEXEL = 8;
/**
 * Per cell: the Lloyd run (the exact engine's triangulation of the sites and their copies near
 * the seams, cell sums; GPU: site buffers) and, per surface of the stack, its adjacency, the
 * analysis's neighbour sets and the result's cell columns. Measured with `tissue-sheet run
 * --workers 1` (peak RSS, /usr/bin/time -v) on a periodic plane, 10 iterations, a thickness, exact
 * engine: 572 MB at 250,000 cells and 863 MB at 500,000, 1.16 kB a cell on 2 surfaces (the result
 * drawn, kept while the other realizations run one at a time); this estimate says 1.22 kB.
 */
const BYTES_PER_CELL = 560;
const BYTES_PER_CELL_PER_SURFACE = 330;
/**
 * Each realization computed on a thread beside the drawn one (`run --workers`): a whole run
 * without cell tables. Measured as above with 2 threads: 0.89 kB a cell more on 2 surfaces and
 * about 90 MB for the thread itself.
 */
const THREAD_BYTES = 96 * 2 ** 20;
const THREAD_BYTES_PER_CELL = 400;
const THREAD_BYTES_PER_CELL_PER_SURFACE = 250;

export interface ComputeBudget {
  /** The GPU's MAX_TEXTURE_SIZE. */
  maxTextureSize: number;
  /** Texel-floods at most (see the module comment). */
  maxWork: number;
  /** Estimated bytes at most. */
  maxBytes: number;
}

export interface RunEstimate {
  /** Width x height of every surface of the stack, seeded first. */
  grids: { width: number; height: number }[];
  /** Texels of the seeded surface. */
  texels: number;
  surfaces: number;
  iterations: number;
  /** Texel-floods (see the module comment). */
  work: number;
  bytes: number;
  /** The part of `bytes` that grows with the cells (the rest grows with the texels). */
  cellBytes: number;
}

export function estimateRun(config: Config): RunEstimate {
  const layout = surfaceLayout(config);
  const grids = layout.grids();
  const sizes = grids.map((g) => g.width * g.height);
  const texels = sizes[0];
  const iterations = config.lloyd.maxIterations;
  const total = sizes.reduce((a, b) => a + b, 0);
  // A cube map's geometry image and per-texel points add to the active texels (see surfaceLayout).
  const perActive = ACTIVE_BYTES_PER_TEXEL + layout.extraBytesPerTexel;
  const cellBytes = config.cells * (BYTES_PER_CELL + BYTES_PER_CELL_PER_SURFACE * grids.length);
  // The exact engine (planes and tubes) holds no texture: the density per texel, no label images
  // unless a view draws them.
  const texelBytes = config.engine === 'exact' ? EXACT_BYTES_PER_TEXEL * texels : perActive * Math.max(...sizes) + KEPT_BYTES_PER_TEXEL * total;
  return {
    grids,
    texels,
    surfaces: grids.length,
    iterations,
    work: texels * iterations + total,
    bytes: texelBytes + cellBytes,
    cellBytes,
  };
}

/**
 * How many of `wanted` realization threads fit the memory budget beside the run itself (each
 * holds a whole run at a time): threads are for speed, so fewer are started where the memory
 * would not hold them, rather than the run refused.
 */
export function threadsWithinBudget(config: Config, estimate: RunEstimate, budget: ComputeBudget, wanted: number): number {
  const texelBytes = estimate.bytes - estimate.cellBytes;
  const perThread = THREAD_BYTES + texelBytes + config.cells * (THREAD_BYTES_PER_CELL + THREAD_BYTES_PER_CELL_PER_SURFACE * estimate.surfaces);
  const room = Math.floor((budget.maxBytes - estimate.bytes) / perThread);
  return Math.max(0, Math.min(wanted, room));
}

/** Refuses lengths outside [MIN_EXTENT_UM, MAX_EXTENT_UM] (see the module comment). */
export function checkExtents(config: Config): void {
  const lengths: [string, number][] = [];
  const s = config.surface;
  if (s.kind === 'plane') lengths.push(['surface.width', s.width], ['surface.height', s.height]);
  else if (s.kind === 'tube') lengths.push(['surface.radius', s.radius], ['surface.length', s.length]);
  else if (s.kind === 'sphere') lengths.push(['surface.radius', s.radius]);
  else if (s.kind === 'ellipsoid') lengths.push(['surface.a', s.a], ['surface.b', s.b], ['surface.c', s.c]);
  for (const [field, value] of lengths) {
    if (value < MIN_EXTENT_UM || value > MAX_EXTENT_UM) {
      throw new ConfigError(
        field,
        `${field}: ${value} µm is outside ${MIN_EXTENT_UM} to ${MAX_EXTENT_UM} µm, where single-precision GPU arithmetic stays meaningful; rescale the surface into that range (results scale with it)`,
      );
    }
  }
  if (config.sheet.thickness > MAX_EXTENT_UM) {
    throw new ConfigError('sheet.thickness', `sheet.thickness: ${config.sheet.thickness} µm is above ${MAX_EXTENT_UM} µm; use a smaller thickness`);
  }
  // A tube's ratio sets the other radius, R·s outward: the same bound as a thickness (without
  // it a huge ratio overflowed the stack's offsets to Infinity and NaN).
  const ratio = (config.sheet as { surfaceRatio?: number | null }).surfaceRatio;
  if (s.kind === 'tube' && typeof ratio === 'number' && config.sheet.direction === 'outward' && !(s.radius * (ratio - 1) <= MAX_EXTENT_UM)) {
    throw new ConfigError(
      'sheet.surfaceRatio',
      `sheet.surfaceRatio: ${ratio} x the radius (${s.radius} µm) puts the other surface more than ${MAX_EXTENT_UM} µm outside the tube; lower sheet.surfaceRatio to at most ${fmt(1 + MAX_EXTENT_UM / s.radius)}`,
    );
  }
}

/** Refuses grids with fewer than MIN_TEXELS_PER_SIDE texels along a side, naming the cause. */
export function checkTexelsPerSide(config: Config): void {
  const layout = surfaceLayout(config);
  if (!layout.aspectSetsShortSide) return; // a cube map is resolution² per face, and resolution >= 16
  const grids = layout.grids();
  const [seeded] = grids;
  const short = Math.min(seeded.width, seeded.height);
  if (short < MIN_TEXELS_PER_SIDE) {
    // The long side gets `resolution` texels, the short one resolution x short/long (rounded).
    const d = unrolledDomain((config as PlanarConfig).surface);
    const need = Math.ceil((MIN_TEXELS_PER_SIDE * Math.max(d.lengthX, d.lengthY)) / Math.min(d.lengthX, d.lengthY));
    throw new ConfigError(
      'resolution',
      `resolution: the grid is ${seeded.width} x ${seeded.height} texels, so its short side has ${short} (at least ${MIN_TEXELS_PER_SIDE} are needed to resolve cells); ${
        need <= 16384
          ? `raise resolution to at least ${need}, or make the surface less elongated`
          : `the surface is too elongated (${fmt(Math.max(d.lengthX, d.lengthY) / Math.min(d.lengthX, d.lengthY))}:1) for any resolution up to 16384: make it shorter or wider`
      }`,
    );
  }
  const field = sheetField(config);
  grids.forEach((g, k) => {
    if (k > 0 && Math.min(g.width, g.height) < MIN_TEXELS_PER_SIDE) {
      throw new ConfigError(
        field,
        `${field}: the ${k === grids.length - 1 ? 'other surface' : `layer ${k}`} is ${g.width} x ${g.height} texels, fewer than ${MIN_TEXELS_PER_SIDE} along a side; use a smaller inward ${field === 'sheet.surfaceRatio' ? 'ratio' : 'thickness'} or raise resolution`,
      );
    }
  });
}

/** Refuses a grid wider than the GPU's texture limit, naming the field that made it so. */
function checkTextureSize(config: Config, maxTextureSize: number): void {
  const layout = surfaceLayout(config);
  const grids = layout.grids();
  grids.forEach((g, k) => {
    if (g.width <= maxTextureSize && g.height <= maxTextureSize) return;
    // Only a widened other surface or layer of a grid can exceed the limit after the seeded one
    // fits (a cube map's surfaces are all n x 6n).
    if (k === 0) {
      const max = maxResolution(layout, maxTextureSize);
      throw new ConfigError(
        'resolution',
        `resolution: the ${layout.textureName} would be ${g.width} x ${g.height} texels but this GPU allows at most ${maxTextureSize} per side; lower resolution to at most ${max}`,
      );
    }
    const field = sheetField(config);
    throw new ConfigError(
      field,
      `${field}: the ${k === grids.length - 1 ? 'other surface' : `layer ${k}`} would be ${g.width} x ${g.height} texels (the seeded grid widened by the surface ratio) but this GPU allows at most ${maxTextureSize} per side; lower ${field}${field === 'sheet.surfaceRatio' ? ` to at most about ${fmt((maxTextureSize / grids[0].width) * 0.99)}` : ''} (or resolution)`,
    );
  });
}

/** Refuses a run whose estimated work or memory exceeds the budget (before allocating anything). */
export function checkBudget(config: Config, budget: ComputeBudget, raiseHint: string): RunEstimate {
  const e = estimateRun(config);
  // Name what made the run large: the seeded grid (resolution) or a wider other surface (only a
  // tube's grids differ in size; a cube map's surfaces are all n x 6n, so largest stays 0).
  const largest = e.grids.reduce((k, g, i) => (g.width * g.height > e.grids[k].width * e.grids[k].height ? i : k), 0);
  const field = largest > 0 ? sheetField(config) : 'resolution';
  if (e.work > budget.maxWork) {
    throw new ConfigError(
      field,
      `${field}: this run is ${fmt(e.work)} texel-floods (${e.texels} texels x ${e.iterations} iterations + ${e.surfaces} surfaces of ${e.grids.map((g) => `${g.width}x${g.height}`).join(', ')} texels), above the limit of ${fmt(budget.maxWork)}; lower ${field === 'resolution' ? 'resolution, lloyd.maxIterations or sheet.layers' : field}, or ${raiseHint}`,
    );
  }
  if (e.bytes > budget.maxBytes && 2 * e.cellBytes > e.bytes) {
    throw new ConfigError(
      'cells',
      `cells: this run needs about ${gib(e.bytes)} of memory (${config.cells} cells on ${e.surfaces} surfaces, ${gib(e.cellBytes)} of it for the cells), above the limit of ${gib(budget.maxBytes)}; lower cells or sheet.layers, or ${raiseHint}`,
    );
  }
  if (e.bytes > budget.maxBytes) {
    throw new ConfigError(
      field,
      `${field}: this run needs about ${gib(e.bytes)} of memory (surfaces of ${e.grids.map((g) => `${g.width}x${g.height}`).join(', ')} texels), above the limit of ${gib(budget.maxBytes)}; lower ${field === 'resolution' ? 'resolution or sheet.layers' : field}, or ${raiseHint}`,
    );
  }
  return e;
}

/** The checks that hold whatever the budget: the scale guards and this GPU's texture size. */
export function checkScale(config: Config, maxTextureSize: number): void {
  checkExtents(config);
  checkTexelsPerSide(config);
  checkTextureSize(config, maxTextureSize);
}

/** Every check of this module, in the order a user would fix them. */
export function checkLimits(config: Config, budget: ComputeBudget, raiseHint: string): RunEstimate {
  checkScale(config, budget.maxTextureSize);
  return checkBudget(config, budget, raiseHint);
}

function sheetField(config: Config): string {
  return (config as PlanarConfig).sheet.surfaceRatio !== null ? 'sheet.surfaceRatio' : 'sheet.thickness';
}

function fmt(value: number): string {
  return value >= 1e6 ? value.toExponential(2) : Number(value.toPrecision(4)).toString();
}

function gib(bytes: number): string {
  return bytes >= 2 ** 30 ? `${(bytes / 2 ** 30).toFixed(1)} GiB` : `${Math.ceil(bytes / 2 ** 20)} MiB`;
}
