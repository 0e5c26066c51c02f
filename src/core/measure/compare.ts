/**
 * The Voronoi model beside a measured tissue (docs/measure.md, "Comparison with the model").
 *
 * - Model sheet: the basal layer's size in µm (width x height pixels of `pixelSize`), its
 *   periodicity in x, open in y, as many sites as the basal layer has labels, placed at random
 *   with the lab's minimum spacing (5 px for cells 102.4 px across, scaled to this cell size).
 * - "Voronoi k": k - 1 exact Lloyd iterations (sites moved to the centroids of their exact
 *   Voronoi cells), k = 1..maxK.
 * - Distance: L1 between polygon distributions over the classes 3..9, 10+ (valid cells; the
 *   model's is the mean over realizations).
 * - The best k is simulated at the measured surface ratio s with as many layers as measured,
 *   layer j scaled around the tube by 1 + (s - 1) j / (K - 1) (the sites keep their unrolled
 *   position: radial projection), exact adjacency, open-border cells excluded.
 */
import { analyzeSurfaces, type ScutoidSummary } from '../analysis';
import { exactVoronoi } from '../exact';
import type { Grid } from '../grid';
import { placeSites } from '../sites';

export interface CompareOptions {
  /** Pixels of the basal layer. */
  readonly width: number;
  readonly height: number;
  /** µm per pixel. */
  readonly pixelSize: number;
  readonly periodicX: boolean;
  /** Cells of the model (labels on the basal layer). */
  readonly cells: number;
  /** The measured basal polygon distribution (classes 3..9, 10+). */
  readonly distribution: number[];
  /** Measured layers (>= 2) and apical / basal ratio. */
  readonly layers: number;
  readonly surfaceRatio: number;
  readonly realizations: number;
  readonly seed: number;
  readonly maxK?: number;
  readonly onProgress?: (line: string) => void;
}

export interface ModelCandidate {
  readonly k: number;
  /** Mean polygon distribution of the model's valid cells over the realizations. */
  readonly polygonDistribution: number[];
  readonly distance: number;
}

export interface ModelComparison {
  readonly method: 'exact';
  readonly distance: 'L1 over polygon classes 3..9, 10+';
  readonly cells: number;
  readonly realizations: number;
  readonly seed: number;
  readonly minSpacing: number;
  readonly candidates: ModelCandidate[];
  readonly bestK: number;
  readonly surfaceRatio: number;
  /** % scutoids of the best model at the measured ratio, per realization, and their mean and SD. */
  readonly percentScutoids: number[];
  readonly meanPercentScutoids: number;
  readonly sdPercentScutoids: number;
  /** Mean apico-basal transitions and mean 3D neighbours of the best model's valid cells, per realization. */
  readonly meanTransitions: number[];
  readonly meanNeighbours3D: number[];
  /** Summary of the best model's first realization at the measured ratio (same shape as the measured one). */
  readonly summary: ScutoidSummary;
}

export const LAB_MIN_SPACING_PIXELS = 5;
const LAB_CELL_DIAMETER_PIXELS = Math.sqrt((512 * 4096) / 200);

export function l1Distance(a: number[], b: number[]): number {
  let d = 0;
  for (let c = 0; c < a.length; c++) d += Math.abs(a[c] - b[c]);
  return d;
}

/**
 * The model's Voronoi k for k = 1..maxK: every realization's sites after k - 1 Lloyd steps
 * (`step`), the mean of their polygon distributions (`distributionOf`, NaN classes as 0), and
 * its L1 distance to the measured `target`; the best k is the nearest (the first on a tie).
 */
export function searchVoronoiK<S>(
  target: number[],
  initial: S[],
  maxK: number,
  step: (sites: S) => S,
  distributionOf: (sites: S) => readonly number[],
  onProgress?: (line: string) => void,
): { candidates: ModelCandidate[]; best: ModelCandidate; atK: S[][] } {
  let sites = initial;
  const atK: S[][] = [];
  const candidates: ModelCandidate[] = [];
  for (let k = 1; k <= maxK; k++) {
    if (k > 1) sites = sites.map(step);
    atK.push(sites);
    const mean = new Array<number>(target.length).fill(0);
    for (const s of sites) distributionOf(s).forEach((f, c) => (mean[c] += (Number.isNaN(f) ? 0 : f) / initial.length));
    candidates.push({ k, polygonDistribution: mean, distance: l1Distance(target, mean) });
    onProgress?.(`model Voronoi ${k}: L1 distance ${candidates[k - 1].distance.toFixed(4)}`);
  }
  return { candidates, best: candidates.reduce((a, b) => (b.distance < a.distance ? b : a)), atK };
}

/**
 * The comparison record: the model (its sites), the Voronoi k search, and the best model's stack
 * statistics over the realizations (`summaries`: one analysed stack each).
 */
export function modelComparison(
  model: Pick<ModelComparison, 'cells' | 'realizations' | 'seed' | 'minSpacing' | 'surfaceRatio'>,
  search: { candidates: ModelCandidate[]; best: ModelCandidate },
  summaries: ScutoidSummary[],
): ModelComparison {
  const percents = summaries.map((s) => s.percentScutoids);
  const mean = percents.reduce((a, b) => a + b, 0) / percents.length;
  const sd = percents.length > 1 ? Math.sqrt(percents.reduce((a, b) => a + (b - mean) ** 2, 0) / (percents.length - 1)) : NaN;
  return {
    method: 'exact',
    distance: 'L1 over polygon classes 3..9, 10+',
    cells: model.cells,
    realizations: model.realizations,
    seed: model.seed,
    minSpacing: model.minSpacing,
    candidates: search.candidates,
    bestK: search.best.k,
    surfaceRatio: model.surfaceRatio,
    percentScutoids: percents,
    meanPercentScutoids: mean,
    sdPercentScutoids: sd,
    meanTransitions: summaries.map((s) => s.meanTransitions),
    meanNeighbours3D: summaries.map((s) => s.meanNeighbours3D),
    summary: summaries[0],
  };
}

/** `iterations` exact Lloyd steps (sites to their exact cells' centroids). */
export function exactLloyd(grid: Grid, sites: Float64Array, iterations: number): Float64Array {
  let current = sites;
  for (let it = 0; it < iterations; it++) current = Float64Array.from(exactVoronoi(grid, current).centroids);
  return current;
}

export function compareWithModel(options: CompareOptions): ModelComparison {
  const { width, height, pixelSize, periodicX, cells, realizations, seed } = options;
  const maxK = options.maxK ?? 10;
  if (!(cells >= 3)) throw new Error(`compareWithModel: ${cells} cells is too few for a model`);
  const grid: Grid = { width, height, texelX: pixelSize, texelY: pixelSize, periodicX, periodicY: false };
  const area = width * height * pixelSize * pixelSize;
  const minSpacing = (LAB_MIN_SPACING_PIXELS * Math.sqrt(area / cells)) / LAB_CELL_DIAMETER_PIXELS;

  // Sites of every realization after k - 1 iterations, advanced one k at a time.
  const initial = Array.from({ length: realizations }, (_, r) => Float64Array.from(placeSites(grid, cells, seed + r, minSpacing)));
  const search = searchVoronoiK<Float64Array>(
    options.distribution,
    initial,
    maxK,
    (s) => exactLloyd(grid, s, 1),
    (s) => analyzeSurfaces([exactVoronoi(grid, s).adjacency]).summary.perSurface[0].polygonDistribution,
    options.onProgress,
  );

  const layers = Math.max(2, options.layers);
  const s = options.surfaceRatio;
  const summaries = search.atK[search.best.k - 1].map((siteSet) => {
    const surfaces = [];
    for (let j = 0; j < layers; j++) {
      const ratio = 1 + ((s - 1) * j) / (layers - 1);
      surfaces.push({ ...exactVoronoi({ ...grid, texelX: pixelSize * ratio }, siteSet).adjacency, label: `ratio ${ratio}` });
    }
    return analyzeSurfaces(surfaces).summary;
  });
  return modelComparison({ cells, realizations, seed, minSpacing, surfaceRatio: s }, search, summaries);
}
