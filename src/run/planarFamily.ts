import {
  invalidOnAnySurface,
  LAB_PROTOCOL,
  labelContactThresholdTexels,
  labMinBoundaryLength,
  type LabProtocolSettings,
  type SurfaceAdjacency,
} from '../core/analysis';
import { checkFeasible, checkSheet, layerStepOf, makeGrid, minContactPixelsOf, type PlanarConfig } from '../core/config';
import { densityField, type GrayImage } from '../core/density';
import { exactVoronoi } from '../core/exact';
import { ExactLloydRun, exactDensity, exactSurface, PlanarVoronoi, rasterizeCells } from '../core/exactEngine';
import type { Grid } from '../core/grid';
import { labelAdjacency } from '../core/labels';
import { projectSites, surfaceStack, type StackSurface } from '../core/sheetGeometry';
import { placeSites } from '../core/sites';
import { embedAll } from '../core/surface';
import type { EngineChoice } from './enginePolicy';
import type { GpuContext } from '../gpu/context';
import { GpuEngine } from '../gpu/engine';
import { gridLayout } from '../gpu/layout';
import { GpuLloydRun, gridSites } from '../gpu/lloyd';
import type { Labeller, RunInputs, SurfaceFamily } from './family';
import { engineRelaxation, relaxation } from './relax';

/** A plane or tube, unrolled: its texel grid and the density per texel. */
export interface PlanarGeometry {
  readonly grid: Grid;
  readonly density: Float32Array;
  /** The decoded density image, for `density.kind = "image"`. */
  readonly densityImage?: GrayImage;
}

/** Sites of a planar surface: interleaved x, y in texel units of its grid. */
type PlanarSites = Float32Array;

/**
 * Planes and tubes: one rectangular texel grid per surface of the stack (a tube's surfaces are
 * the same strip with the circumference scaled), square texels, periodic edges where the
 * surface wraps. Exact adjacency is the Delaunay of the unrolled sites (src/core/exact.ts).
 */
export const planarFamily: SurfaceFamily<PlanarConfig, PlanarGeometry, PlanarSites, StackSurface, PlanarSites> = {
  name: 'planar grid',

  async prepare(config, inputs: RunInputs) {
    const grid = makeGrid(config);
    checkFeasible(config, grid);
    const { densityImage } = inputs;
    return { grid, density: densityField(config.density, grid, densityImage), ...(densityImage ? { densityImage } : {}) };
  },

  // Again for a reused seeded surface: its sheet may be new.
  checkSheet: (config) => checkSheet(config),

  relax(context, config, geometry, choice) {
    const { grid, density } = geometry;
    const sites = placeSites(grid, config.cells, config.seed, config.minSpacing, placementDensity(config, density));
    if (choice.name === 'exact') {
      const run = new ExactLloydRun(grid, sites, config.lloyd, exactDensity(config.density, grid, geometry.densityImage));
      // finish() leaves the diagram of the final sites built: the seeded surface's exact
      // adjacency reads it instead of triangulating the same sites again (exactAdjacency).
      memo(sites, FINAL_DIAGRAM, () => run.voronoi);
      // No label image: the stack rasterizes the exact cells for views when asked.
      return { sites, relaxation: relaxation(run, () => null) };
    }
    const engine = new GpuEngine(context, gridLayout(grid), config.cells, { variant: config.jumpFlood.variant, centroidPath: choice.centroidPath });
    const start = () => {
      // Planar-family texels all cover the same area, so the weight is the density alone.
      engine.setGeometry(density);
      return new GpuLloydRun(engine, gridSites(grid, sites), config.lloyd);
    };
    // Label the final sites with a cold flood, as every other surface of the stack is
    // labelled: identical surfaces then get identical labels (no warm-start residue at s = 1).
    return { sites, relaxation: engineRelaxation(engine, start, () => engine.floodLabels()) };
  },

  stack: (config, geometry) => surfaceStack(config, geometry.grid),

  // Once per seeded surface and grid, as the layer's exact diagram (exactLayer).
  project: (geometry, layer, sites) => (layer.role === 'seeded' ? sites : projected(geometry.grid, layer.grid, sites)),

  labeller: (context, config, _geometry, choice) => planarLabeller(context, config, choice),

  exactLabels: (_geometry, layer, projected) => rasterizeCells(layer.grid, exactVoronoi(layer.grid, projected)),

  labelFrame: (_geometry, layer) => ({ name: layer.name, grid: layer.grid }),

  // Contact lengths without the staircase bias, except under a pixel rule (the lab's 6 px),
  // which counts texel edges: there the staircase is the quantity the rule is about.
  labelAdjacency(config, _geometry, layer, labels, count) {
    const pixelRule = minContactPixelsOf(config.sheet) !== null;
    return labelAdjacency(layer.grid, labels, count, pixelRule ? 'staircase' : 'true', layer.name);
  },

  // A pixel rule (texel edges, e.g. the lab's 6 px around a 512 px tube) or a length in µm;
  // by default the lab's threshold scaled to this sheet's mean cell size. Texels are square
  // and the same size on every surface of the stack, so one length serves them all.
  minContactLengths(config, geometry, layers, method) {
    // The exact Delaunay needs no threshold: every contact of positive length counts.
    if (method === 'exact') return null;
    const pixels = minContactPixelsOf(config.sheet);
    const length =
      pixels !== null
        ? labelContactThresholdTexels(geometry.grid, { ...LAB_PROTOCOL, minContactPixels: pixels }) * geometry.grid.texelX
        : (config.sheet.minContactLength ?? defaultMinContactLength(geometry.grid, config.cells));
    return { reported: length, perLayer: layers.map(() => length) };
  },

  // Once per seeded surface and settings: a sweep over ratios asks again for every ratio. The
  // layers s = 1 : step : validityMaxRatio are laid out as a stack to that ratio lays them out
  // (surfaceStack, projectSites), so they are the very surfaces the stacks of the sweep's ratios
  // are made of: one exact diagram per layer serves the validity and every ratio (exactLayer).
  protocolInvalid(config, geometry, sites) {
    if (config.sheet.protocol !== 'lab') return null;
    const settings = labSettings(config.sheet);
    return memo(sites, `lab ${settings.layerStep} ${settings.validityMaxRatio}`, () => {
      const sheet = { ...config.sheet, surfaceRatio: settings.validityMaxRatio, direction: 'outward' as const, layerStep: settings.layerStep };
      const layers = surfaceStack({ ...config, sheet }, geometry.grid);
      return invalidOnAnySurface(
        layers.map((layer) => exactLayer(layer.grid, sites, layer.role === 'seeded' ? sites : projected(geometry.grid, layer.grid, sites))),
        config.cells,
      );
    });
  },

  // Kept per seeded surface: runs that differ in the sheet share most of their layers (and the
  // seeded surface's own sites reuse the exact Lloyd run's final diagram: see exactLayer).
  exactAdjacency: (_config, _geometry, layer, sites, projected) => ({ ...exactLayer(layer.grid, sites, projected), label: layer.name }),

  cellPlacements: (config, layer, _sites, projected, position, coordinates) =>
    embedAll(config.surface, layer.grid, projected, layer.offset, position, coordinates),

  gridRecord: (geometry) => ({ ...geometry.grid }),

  resultSection: () => ({}),
};

/** The lab's threshold scaled to this sheet's mean cell size (see labMinBoundaryLength). */
export function defaultMinContactLength(grid: Grid, cells: number): number {
  return labMinBoundaryLength(grid.width * grid.texelX * grid.height * grid.texelY, cells);
}

/**
 * Initial sites follow the point density a CVT converges to, rho^(d/(d+2)) = sqrt(rho) in 2D
 * (Gersho; Du et al.), not rho itself: Lloyd then has little mass to move across the sheet.
 */
function placementDensity(config: PlanarConfig, density: Float32Array): Float32Array | undefined {
  if (config.density.kind === 'uniform') return undefined;
  return density.map(Math.sqrt);
}

/**
 * Values computed from a seeded surface's sites, kept while those sites live (SheetRunner keeps
 * the last seeded surface): the lab's valid cells and the exact diagrams of the stack's layers,
 * which a sweep over `sheet.*` would otherwise compute again for every run.
 */
const memos = new WeakMap<PlanarSites, Map<string, unknown>>();

function memo<T>(sites: PlanarSites, key: string, compute: () => T): T {
  let values = memos.get(sites);
  if (!values) memos.set(sites, (values = new Map()));
  if (!values.has(key)) values.set(key, compute());
  return values.get(key) as T;
}

/** Memo key of the exact Lloyd run's diagram of the final sites. */
const FINAL_DIAGRAM = 'final diagram';

/**
 * The exact adjacency of the seeded sites projected onto a layer's grid (`projected`: as
 * `project` moves them there), once per seeded surface and grid: the same grid is the same
 * surface in every stack and in the lab validity. exactSurface gives the numbers of
 * exactVoronoi(...).adjacency (tested cell by cell) without the per-cell records. The
 * seeded sites themselves (the seeded surface; a plane's other surface) read the exact Lloyd
 * run's final diagram, already built for them: nothing is triangulated twice.
 */
function exactLayer(grid: Grid, sites: PlanarSites, projected: ArrayLike<number>): SurfaceAdjacency {
  const { width, height, texelX, texelY, periodicX, periodicY } = grid;
  return memo(sites, `exact ${width} ${height} ${texelX} ${texelY} ${periodicX} ${periodicY}`, () => {
    const final = memos.get(sites)?.get(FINAL_DIAGRAM) as PlanarVoronoi | undefined;
    if (final && sameValues(projected, sites)) {
      memos.get(sites)?.delete(FINAL_DIAGRAM); // read once; its buffers are not kept
      return exactSurface(grid, projected, undefined, final);
    }
    const kept = scratchVoronoi(grid, sites.length / 2);
    // After the previous layer of the same seeded sites, its triangulation, moved, is flipped to
    // this layer's (PlanarVoronoi.build): the same neighbours and open edges as a fresh
    // triangulation (lengths and areas equal to rounding, which no sweep column reads).
    const continues = kept.sites === sites;
    kept.sites = sites;
    return exactSurface(grid, projected, undefined, kept.voronoi, continues);
  });
}

/**
 * The triangulation buffers exactSurface builds in, kept for the next layer of the same shape
 * (one set: the last cell count and periodic axes), as bench/exactSweep.ts reuses them, with the
 * seeded sites whose layer it holds.
 */
let scratch: { key: string; voronoi: PlanarVoronoi; sites: PlanarSites | null } | null = null;
function scratchVoronoi(grid: Grid, count: number): { voronoi: PlanarVoronoi; sites: PlanarSites | null } {
  const key = `${count} ${grid.periodicX} ${grid.periodicY}`;
  if (scratch?.key !== key) scratch = { key, voronoi: new PlanarVoronoi(grid, count, true), sites: null };
  return scratch;
}

/** The seeded sites moved onto a layer's grid (projectSites), once per seeded surface and grid. */
function projected(seededGrid: Grid, grid: Grid, sites: PlanarSites): PlanarSites {
  return memo(sites, `project ${seededGrid.width} ${grid.width}`, () => projectSites(seededGrid, grid, sites));
}

function sameValues(a: ArrayLike<number>, b: ArrayLike<number>): boolean {
  if (a.length !== b.length) return false;
  for (let k = 0; k < a.length; k++) if (a[k] !== b[k]) return false;
  return true;
}

/** The lab protocol's knobs as the config sets them. */
function labSettings(sheet: PlanarConfig['sheet']): LabProtocolSettings {
  return {
    ...LAB_PROTOCOL,
    layerStep: layerStepOf(sheet) ?? LAB_PROTOCOL.layerStep,
    validityMaxRatio: sheet.validityMaxRatio,
    minContactPixels: minContactPixelsOf(sheet) ?? LAB_PROTOCOL.minContactPixels,
  };
}

/** A tube's surfaces differ in width, so each gets an engine of its own grid. */
function planarLabeller(context: GpuContext, config: PlanarConfig, choice: EngineChoice): Labeller<StackSurface, PlanarSites> {
  return {
    label(layer, sites) {
      // The exact engine makes no label textures: exactLabels draws its cells instead.
      if (choice.name !== 'gpu') throw new Error('planar labeller: the exact engine has no label textures');
      const engine = new GpuEngine(context, gridLayout(layer.grid), config.cells, { variant: config.jumpFlood.variant, centroidPath: choice.centroidPath });
      try {
        engine.setSites(sites);
        engine.floodLabels();
        return engine.readLabels();
      } finally {
        engine.dispose();
      }
    },
    dispose() {},
  };
}
