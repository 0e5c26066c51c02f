import { analyzeSurfaces, withMinBoundaryLength, type SurfaceAdjacency } from '../core/analysis';
import type { AnyConfig } from '../core/config';
import type { GpuContext } from '../gpu/context';
import { analysisRecord } from './analysisRecord';
import type { LabelSurfaceAdjacency, StackLayer, SurfaceFamily } from './family';
import { throwIfAborted, yieldToEventLoop, type SeededSurface } from './relax';
import type { AnalysisRecord, CellRecord, ClosedSurfaceRecord, LabelImage, SurfaceRecord } from './result';

/** Everything the stack of a sheet gives the result. */
export interface SheetStack {
  /** Cells of the seeded surface. */
  readonly seededCells: CellRecord[];
  /** Layers (seeded side first), then the other surface. */
  readonly surfaces: SurfaceRecord[];
  readonly analyses: AnalysisRecord[];
  /** [seeded, layers..., other]. */
  readonly labelImages: LabelImage[];
  readonly closed?: ClosedSurfaceRecord;
  readonly adjacencyMs: number;
}

/**
 * Moves the converged sites along the normal onto every surface of the stack, labels each
 * surface with a jump flood (no Lloyd: the sites stay where the seeded surface put them), and
 * computes the scutoid statistics from the label adjacency and, where the surface has one, the
 * exact adjacency.
 */
export async function analyzeStack<C extends AnyConfig, G, S, L extends StackLayer, P>(
  family: SurfaceFamily<C, G, S, L, P>,
  config: C,
  seeded: SeededSurface<G, S>,
  context: GpuContext,
  signal?: AbortSignal,
): Promise<SheetStack> {
  const start = performance.now();
  const { geometry } = seeded;
  family.checkSheet(config, geometry);
  const layers = family.stack(config, geometry);
  const labeller = family.labeller(context, config, geometry, seeded.engine);
  try {
    const projected: P[] = [];
    const labelImages: LabelImage[] = [];
    const labelled: LabelSurfaceAdjacency[] = [];
    for (const layer of layers) {
      throwIfAborted(signal);
      const sites = family.project(geometry, layer, seeded.sites);
      let labels = seeded.labels;
      if (layer.role !== 'seeded') {
        labels = labeller.label(layer, sites);
        await yieldToEventLoop();
      }
      projected.push(sites);
      labelImages.push(family.labelImage(geometry, layer, labels));
      labelled.push(family.labelAdjacency(geometry, layer, labels, config.cells));
    }

    const analyses: AnalysisRecord[] = [];
    const { adjacency } = config.sheet;
    if (adjacency !== 'exact') {
      const minContact = family.minContactLengths(config, geometry, layers);
      const inputs = labelled.map((surface, k) => withMinBoundaryLength(surface, minContact.perLayer[k]));
      analyses.push(analysisRecord('labels', minContact.reported, analyzeSurfaces(inputs)));
    }
    if (adjacency !== 'labels') {
      const exact = layers.map((layer, k) => family.exactAdjacency(config, geometry, layer, seeded.sites, projected[k]));
      if (exact.every((surface): surface is SurfaceAdjacency => surface !== null)) analyses.push(analysisRecord('exact', 0, analyzeSurfaces(exact)));
    }
    const adjacencyMs = performance.now() - start;

    const section = family.resultSection(config, geometry, seeded, labeller);
    const cellsOf = (k: number) => cellRecords(labelled[k], (id) => family.cellPlacement(config, layers[k], seeded.sites, projected[k], id));
    const surfaces: SurfaceRecord[] = layers.slice(1).map((layer, index) => ({
      name: layer.name,
      role: layer.role === 'layer' ? 'layer' : 'other',
      offset: layer.offset,
      ratio: family.layerRatio(geometry, layer),
      grid: { ...labelImages[index + 1].grid },
      cells: cellsOf(index + 1),
    }));
    return { seededCells: cellsOf(0), surfaces, analyses, labelImages, ...section, adjacencyMs };
  } finally {
    labeller.dispose();
  }
}

/** The cells of one surface from its label adjacency. */
function cellRecords(surface: LabelSurfaceAdjacency, placement: (id: number) => Pick<CellRecord, 'position' | 'surface'>): CellRecord[] {
  const { offsets, neighbours: ids, lengths } = surface.adjacency;
  const cells: CellRecord[] = [];
  for (let id = 0; id < surface.count; id++) {
    const neighbours = [];
    for (let k = offsets[id]; k < offsets[id + 1]; k++) neighbours.push({ id: ids[k], length: lengths[k] });
    const { position, surface: coordinates } = placement(id);
    cells.push({ id, position, surface: coordinates, area: surface.areas[id], neighbours, touchesBorder: surface.touchesBorder[id] === 1 });
  }
  return cells;
}
