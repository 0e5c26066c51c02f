import { analyzeSurfaces, labMinBoundaryLength, withMinBoundaryLength, surfaceFromExact, type SurfaceAdjacency } from '../core/analysis';
import type { Config } from '../core/config';
import type { Grid } from '../core/grid';
import { exactVoronoi } from '../core/exact';
import { labelAdjacency, type LabelAdjacency } from '../core/labels';
import { projectSites, surfaceStack, type StackSurface } from '../core/sheetGeometry';
import { embed, surfaceCoordinates } from '../core/surface';
import type { GpuContext } from '../gpu/context';
import { CcvtEngine } from '../gpu/engine';
import { analysisRecord } from './analysisRecord';
import type { AnalysisRecord, CellRecord, LabelImage, SurfaceRecord } from './result';
import { throwIfAborted, yieldToEventLoop, type SeededSurface } from './seededSurface';

export interface SheetStack {
  readonly surfaces: SurfaceRecord[];
  readonly analyses: AnalysisRecord[];
  /** [seeded, layers..., other]. */
  readonly labelImages: LabelImage[];
  /** Cells of the seeded surface. */
  readonly seededCells: CellRecord[];
  readonly adjacencyMs: number;
}

/**
 * Projects the converged sites onto every surface of the stack, labels each surface with a jump
 * flood (no Lloyd: the sites stay where the seeded surface put them), and computes the scutoid
 * statistics from label adjacency and, where asked, from the exact Delaunay adjacency.
 */
export async function analyzeStack(config: Config, seeded: SeededSurface, context: GpuContext, signal?: AbortSignal): Promise<SheetStack> {
  const start = performance.now();
  const stack = surfaceStack(config, seeded.grid);
  const count = config.cells;
  const labelImages: LabelImage[] = [];
  const labelAdjacencies: LabelAdjacency[] = [];
  const projected: Float32Array[] = [];
  for (const surface of stack) {
    throwIfAborted(signal);
    const sites = surface.role === 'seeded' ? seeded.sites : projectSites(seeded.grid, surface.grid, seeded.sites);
    const labels = surface.role === 'seeded' ? seeded.labels : await labelSurface(context, surface, sites, config);
    projected.push(sites);
    labelImages.push({ name: surface.name, grid: surface.grid, labels });
    labelAdjacencies.push(labelAdjacency(surface.grid, labels, count));
  }

  const analyses: AnalysisRecord[] = [];
  const { adjacency } = config.sheet;
  if (adjacency !== 'exact') {
    const minContactLength = config.sheet.minContactLength ?? defaultMinContactLength(seeded.grid, config.cells);
    const inputs = labelAdjacencies.map((a, k) => withMinBoundaryLength(fromLabels(a, stack[k].name), minContactLength));
    analyses.push(analysisRecord('labels', minContactLength, analyzeSurfaces(inputs)));
  }
  if (adjacency !== 'labels') {
    const inputs = stack.map((surface, k) => surfaceFromExact(exactVoronoi(surface.grid, projected[k]), surface.name));
    analyses.push(analysisRecord('exact', 0, analyzeSurfaces(inputs)));
  }

  const cellsOf = (k: number) => cellRecords(config, stack[k], projected[k], labelAdjacencies[k]);
  const surfaces: SurfaceRecord[] = stack.slice(1).map((surface, index) => ({
    name: surface.name,
    role: surface.role as 'layer' | 'other',
    offset: surface.offset,
    ratio: surface.ratio,
    grid: { ...surface.grid },
    cells: cellsOf(index + 1),
  }));
  return { surfaces, analyses, labelImages, seededCells: cellsOf(0), adjacencyMs: performance.now() - start };
}

async function labelSurface(context: GpuContext, surface: StackSurface, sites: Float32Array, config: Config): Promise<Int32Array> {
  const engine = new CcvtEngine(context, surface.grid, config.cells, { variant: config.jumpFlood.variant, centroidPath: 'auto' });
  try {
    engine.setSites(sites);
    engine.floodLabels();
    const labels = engine.readLabels();
    await yieldToEventLoop();
    return labels;
  } finally {
    engine.dispose();
  }
}

/** The lab's threshold scaled to this sheet's mean cell size (see labMinBoundaryLength). */
export function defaultMinContactLength(grid: Grid, cells: number): number {
  return labMinBoundaryLength(grid.width * grid.texelX * grid.height * grid.texelY, cells);
}

function fromLabels(adjacency: LabelAdjacency, label: string): SurfaceAdjacency {
  return {
    count: adjacency.count,
    adjacency: { offsets: adjacency.offsets, neighbours: adjacency.neighbours, lengths: adjacency.lengths },
    areas: adjacency.area,
    touchesBorder: adjacency.touchesBorder,
    label,
  };
}

function cellRecords(config: Config, surface: StackSurface, sites: Float32Array, adjacency: LabelAdjacency): CellRecord[] {
  const cells: CellRecord[] = [];
  for (let id = 0; id < adjacency.count; id++) {
    const x = sites[2 * id];
    const y = sites[2 * id + 1];
    const neighbours = [];
    for (let k = adjacency.offsets[id]; k < adjacency.offsets[id + 1]; k++) {
      neighbours.push({ id: adjacency.neighbours[k], length: adjacency.lengths[k] });
    }
    cells.push({
      id,
      position: embed(config.surface, surface.grid, x, y, surface.offset).position,
      surface: surfaceCoordinates(surface.grid, x, y),
      area: adjacency.area[id],
      neighbours,
      touchesBorder: adjacency.touchesBorder[id] === 1,
    });
  }
  return cells;
}
