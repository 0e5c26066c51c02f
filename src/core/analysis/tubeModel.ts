/**
 * The published tube model (Gomez-Galvez et al. 2018) on the exact Voronoi diagram.
 *
 * Geometry: the seeded surface is a strip `grid` (x around the tube, periodic; y along the
 * axis, open), sites in texel units. The other surface at surface ratio s = R_outer / R_inner is
 * the same strip with the circumferential coordinate scaled by s: a grid `width * s` texels
 * around (same texel size, so s times the circumference), same height; a site (x, y) projects
 * radially to (x * s, y). The axial length is unchanged. s < 1 (projecting inwards) works too.
 *
 * Layers: `layerRatios(s, K)` = K intermediate surfaces with ratios stepped linearly from 1 to
 * s: 1 + (s - 1) * k / (K + 1), k = 0..K+1 (first = 1, last = s).
 *
 * `analyzeTubeModel(grid, sites, { ratios, layers, minBoundaryLength })` computes, for every
 * ratio s in `ratios`, the exact diagram on each surface of [1, layers..., s] (each distinct
 * ratio is computed once and shared) and the scutoid statistics of that stack (see
 * scutoids.ts: border cells are those touching an open end on any of those surfaces). With
 * `minBoundaryLength` (µm) contacts shorter than that are dropped on every surface first (to
 * mimic the lab's pixel threshold; the exact method needs none: default 0 = no filter).
 */
import type { Grid } from '../grid';
import type { ExactVoronoi } from '../exact';
import { exactVoronoi } from '../exact';
import type { AnalysisOptions, ScutoidAnalysis, SurfaceAdjacency } from './scutoids';
import { analyzeSurfaces, surfaceFromExact, withMinBoundaryLength } from './scutoids';

/** The grid of the surface at ratio s: width * s texels around, same height and texel size. */
export function tubeSurfaceGrid(grid: Grid, ratio: number): Grid {
  if (!(ratio > 0)) throw new Error(`surface ratio must be positive, got ${ratio}`);
  return { ...grid, width: grid.width * ratio };
}

/** Radial projection of sites (interleaved x, y texel units) onto the surface at ratio s: (x * s, y). */
export function projectTubeSites(sites: ArrayLike<number>, ratio: number): Float64Array {
  const out = new Float64Array(sites.length);
  for (let k = 0; k + 1 < sites.length; k += 2) {
    out[k] = sites[k] * ratio;
    out[k + 1] = sites[k + 1];
  }
  return out;
}

/** Ratios of the stack from 1 to s with `layers` intermediate surfaces, linearly stepped. */
export function layerRatios(ratio: number, layers = 0): number[] {
  const out: number[] = [];
  for (let k = 0; k <= layers + 1; k++) out.push(k === layers + 1 ? ratio : 1 + ((ratio - 1) * k) / (layers + 1));
  return out;
}

/** Exact diagram of the projected sites on the surface at ratio s. */
export function tubeSurfaceVoronoi(grid: Grid, sites: ArrayLike<number>, ratio: number): ExactVoronoi {
  return exactVoronoi(tubeSurfaceGrid(grid, ratio), projectTubeSites(sites, ratio));
}

export interface TubeModelOptions extends AnalysisOptions {
  /** Surface ratios s to evaluate (each against the seeded surface s = 1). */
  ratios: number[];
  /** Intermediate layers between 1 and s (default 0). */
  layers?: number;
  /** Drop contacts shorter than this (µm) on every surface; default 0 (exact, no filter). */
  minBoundaryLength?: number;
}

export interface TubeModelResult {
  ratio: number;
  /** Ratios of the surfaces of the stack (first 1, last `ratio`). */
  stack: number[];
  analysis: ScutoidAnalysis;
}

/** Scutoid statistics of the tube model for each ratio (see the module comment). */
export function analyzeTubeModel(grid: Grid, sites: ArrayLike<number>, options: TubeModelOptions): TubeModelResult[] {
  const cache = new Map<number, SurfaceAdjacency>();
  const minLength = options.minBoundaryLength ?? 0;
  const surfaceAt = (ratio: number): SurfaceAdjacency => {
    let s = cache.get(ratio);
    if (!s) {
      s = surfaceFromExact(tubeSurfaceVoronoi(grid, sites, ratio), `s=${ratio}`);
      if (minLength > 0) s = withMinBoundaryLength(s, minLength);
      cache.set(ratio, s);
    }
    return s;
  };
  return options.ratios.map((ratio) => {
    const stack = layerRatios(ratio, options.layers ?? 0);
    return { ratio, stack, analysis: analyzeSurfaces(stack.map(surfaceAt), options) };
  });
}
