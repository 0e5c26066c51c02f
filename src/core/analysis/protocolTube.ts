/**
 * The lab protocol on the tube model (see protocol.ts and docs/protocols.md), computed exactly.
 *
 * Geometry: the surface at ratio s is the seeded strip with the circumference scaled by s (a grid
 * `width * s` texels around, same texel size and height); a site (x, y) projects radially to
 * (x * s, y). `surfaceOf` turns a grid and projected sites into the adjacency record; the
 * default is `exactVoronoi(...).adjacency` (d3-delaunay), and sweeps pass the exact engine's
 * `exactSurface` (the same numbers, tested cell by cell, several times faster).
 */
import { isCanonical } from './sortedSets';
import { exactVoronoi } from '../exact';
import type { Grid } from '../grid';
import { neighbourSet, type SurfaceAdjacency } from './adjacency';
import { analyzeSurfaces, type ScutoidAnalysis } from './scutoids';
import { excludeInvalid, invalidOnAnySurface, labLayerRatios, LAB_PROTOCOL, validityRatios, type LabProtocolSettings } from './protocol';

export type SurfaceOf = (grid: Grid, sites: ArrayLike<number>, label: string) => SurfaceAdjacency;

/** The exact diagram of the projected sites by d3-delaunay (exactVoronoi). */
const exactVoronoiSurface: SurfaceOf = (grid, sites, label) => ({ ...exactVoronoi(grid, sites).adjacency, label });

/** The tube surface at ratio s: `width * s` texels around, same height and texel size. */
function tubeLayerGrid(grid: Grid, ratio: number): Grid {
  if (!(ratio > 0)) throw new Error(`surface ratio must be positive (got ${ratio})`);
  return { ...grid, width: grid.width * ratio };
}

/** Radial projection onto the surface at ratio s: (x * s, y), texel units. */
function projectToRatio(sites: ArrayLike<number>, ratio: number, out = new Float64Array(sites.length)): Float64Array {
  for (let k = 0; k + 1 < sites.length; k += 2) {
    out[k] = sites[k] * ratio;
    out[k + 1] = sites[k + 1];
  }
  return out;
}

export interface LabTubeAnalysis {
  readonly ratio: number;
  /** Ratios of the analysed stack: 1, 1 + step, ..., ratio. */
  readonly stackRatios: number[];
  /** Ratios validity was decided on. */
  readonly validityRatios: number[];
  /** 1 = excluded (open-end contact on some validity layer or stack surface). */
  readonly invalid: Uint8Array;
  /** The statistics of the stack on the protocol's valid cells, transitions counted the lab's way. */
  readonly analysis: ScutoidAnalysis;
}

/** Computes each distinct ratio's surface once. */
function surfaceCache(grid: Grid, sites: ArrayLike<number>, surfaceOf: SurfaceOf): (ratio: number) => SurfaceAdjacency {
  const cache = new Map<number, SurfaceAdjacency>();
  const projected = new Float64Array(sites.length);
  return (ratio) => {
    const key = Math.round(ratio * 1e9) / 1e9;
    let surface = cache.get(key);
    if (!surface) {
      surface = surfaceOf(tubeLayerGrid(grid, ratio), projectToRatio(sites, ratio, projected), `s=${key}`);
      cache.set(key, surface);
    }
    return surface;
  };
}

/** The lab protocol's analysis of one tube at one apical ratio. */
export function analyzeTubeLab(grid: Grid, sites: ArrayLike<number>, apicalRatio: number, settings: LabProtocolSettings = LAB_PROTOCOL): LabTubeAnalysis {
  const count = Math.floor(sites.length / 2);
  const surfaceAt = surfaceCache(grid, sites, exactVoronoiSurface);
  const validity = validityRatios(settings, apicalRatio < 1);
  const stackRatios = labLayerRatios(apicalRatio, settings);
  const stack = stackRatios.map(surfaceAt);
  const invalid = invalidOnAnySurface([...validity.map(surfaceAt), ...stack], count);
  const masked = excludeInvalid(stack, invalid);
  const analysis = analyzeSurfaces(masked);
  applyLabTransitions(analysis, masked);
  return { ratio: apicalRatio, stackRatios, validityRatios: validity, invalid, analysis };
}

/**
 * The lab protocol's statistics of an analysed stack (any adjacency method): cells in `invalid`
 * or touching an open end on a surface of the stack are excluded, and intercalations are
 * accumulated layer to layer, |∪ lost| + |∪ won|.
 */
export function analyzeLabStack(stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  const excluded = invalidOnAnySurface(stack, invalid.length, invalid.slice());
  const masked = excludeInvalid(stack, excluded);
  const analysis = analyzeSurfaces(masked);
  applyLabTransitions(analysis, masked);
  return analysis;
}

/** Lab intercalation count per cell over a stack: |∪ lost| + |∪ won| layer to layer. */
function labTransitions(stack: SurfaceAdjacency[]): { won: Int32Array; lost: Int32Array; transitions: Int32Array } {
  const count = stack[0].count;
  const csr = stack;
  const won = new Int32Array(count);
  const lost = new Int32Array(count);
  const transitions = new Int32Array(count);
  const wonSet: number[] = [];
  const lostSet: number[] = [];
  for (let i = 0; i < count; i++) {
    wonSet.length = 0;
    lostSet.length = 0;
    let previous = neighbourSet(csr[0], i);
    for (let k = 1; k < csr.length; k++) {
      const current = neighbourSet(csr[k], i);
      addDifference(previous, current, lostSet);
      addDifference(current, previous, wonSet);
      previous = current;
    }
    won[i] = wonSet.length;
    lost[i] = lostSet.length;
    transitions[i] = wonSet.length + lostSet.length;
  }
  return { won, lost, transitions };
}

/** Replaces the analysis's transitions (and won/lost means) with the lab's accumulated counts. */
function applyLabTransitions(analysis: ScutoidAnalysis, stack: SurfaceAdjacency[]): void {
  const { transitions, won, lost } = labTransitions(stack);
  const valid = analysis.cells.valid;
  let t = 0;
  let w = 0;
  let l = 0;
  for (let i = 0; i < valid.length; i++) {
    analysis.cells.transitions[i] = transitions[i];
    if (!valid[i]) continue;
    t += transitions[i];
    w += won[i];
    l += lost[i];
  }
  const n = analysis.summary.validCells;
  analysis.summary.meanTransitions = n > 0 ? t / n : NaN;
  analysis.summary.meanWon = n > 0 ? w / n : NaN;
  analysis.summary.meanLost = n > 0 ? l / n : NaN;
}

/** Sorted sets a, b: adds the elements of a \ b not yet in `into`. */
function addDifference(a: Int32Array, b: Int32Array, into: number[]): void {
  let j = 0;
  for (let k = 0; k < a.length; k++) {
    const v = a[k];
    while (j < b.length && b[j] < v) j++;
    if (j < b.length && b[j] === v) continue;
    if (!into.includes(v)) into.push(v);
  }
}

/** One row of a protocol table: one realization at one ratio. */
export interface LabRatioRow {
  readonly ratio: number;
  readonly validCells: number;
  readonly percentScutoids: number;
  /** Mean of |∪ lost| + |∪ won| over valid cells. */
  readonly meanTransitions: number;
  /** Mean |∪_k N_k| over valid cells (n3D of the Flintstones law). */
  readonly meanNeighbours3D: number;
  /** Mean number of neighbours on the surface at this ratio (valid cells). */
  readonly meanSides: number;
}

/**
 * Every ratio of `ratios` for one realization, the lab way, in one pass over the layers
 * 1 : step : max(validityMaxRatio, ratios): each layer's diagram is computed once and
 * intercalations are accumulated incrementally. Every ratio must lie on the layer grid
 * (1 + k·step); use analyzeTubeLab for others.
 */
export function labTubeTable(
  grid: Grid,
  sites: ArrayLike<number>,
  ratios: readonly number[],
  settings: LabProtocolSettings = LAB_PROTOCOL,
  surfaceOf: SurfaceOf = exactVoronoiSurface,
): LabRatioRow[] {
  const count = Math.floor(sites.length / 2);
  const top = Math.max(settings.validityMaxRatio, ...ratios);
  const layers = validityRatios({ ...settings, validityMaxRatio: top });
  const targetLayer = ratios.map((r) => {
    const k = Math.round((r - 1) / settings.layerStep);
    if (!(r >= 1) || Math.abs(1 + k * settings.layerStep - r) > 1e-9) {
      throw new Error(`labTubeTable: ratio ${r} is not on the layer grid 1 + k·${settings.layerStep}; use analyzeTubeLab`);
    }
    return k;
  });
  const projected = new Float64Array(sites.length);
  const surfaces = layers.map((r) => surfaceOf(tubeLayerGrid(grid, r), projectToRatio(sites, r, projected), `s=${r}`));
  // Validity on 1 : step : validityMaxRatio, plus any layer a target stack reaches beyond it.
  const validityTop = Math.max(...targetLayer, Math.round((settings.validityMaxRatio - 1) / settings.layerStep));
  const invalid = invalidOnAnySurface(surfaces.slice(0, validityTop + 1), count);
  const csr = surfaces;
  // exactSurface and exactVoronoi list neighbours ascending, once, never the cell itself: read
  // them in place (no copy per cell and layer); anything else goes through neighbourSet.
  const canonical = csr.map(isCanonical);
  const setOf = (k: number, i: number) => (canonical[k] ? csr[k].neighbours.subarray(csr[k].offsets[i], csr[k].offsets[i + 1]) : neighbourSet(csr[k], i));

  const lastTarget = Math.max(...targetLayer);
  const sums = targetLayer.map(() => ({ scutoids: 0, transitions: 0, n3D: 0, sides: 0 }));
  const union: number[] = [];
  const won: number[] = [];
  const lost: number[] = [];
  let validCells = 0;
  for (let i = 0; i < count; i++) {
    if (invalid[i]) continue;
    validCells++;
    union.length = 0;
    won.length = 0;
    lost.length = 0;
    let previous = setOf(0, i);
    for (const v of previous) union.push(v);
    for (let k = 0; k <= lastTarget; k++) {
      const current = k === 0 ? previous : setOf(k, i);
      if (k > 0) {
        addDifference(previous, current, lost);
        addDifference(current, previous, won);
        for (const v of current) if (!union.includes(v)) union.push(v);
        previous = current;
      }
      for (let t = 0; t < targetLayer.length; t++) {
        if (targetLayer[t] !== k) continue;
        const row = sums[t];
        const changes = won.length + lost.length;
        row.scutoids += changes > 0 ? 1 : 0;
        row.transitions += changes;
        row.n3D += union.length;
        row.sides += current.length;
      }
    }
  }
  const mean = (x: number) => (validCells > 0 ? x / validCells : NaN);
  return ratios.map((ratio, t) => ({
    ratio,
    validCells,
    percentScutoids: mean(100 * sums[t].scutoids),
    meanTransitions: mean(sums[t].transitions),
    meanNeighbours3D: mean(sums[t].n3D),
    meanSides: mean(sums[t].sides),
  }));
}
