import { analyzeSurfaces, withMinBoundaryLength, type SurfaceAdjacency } from '../core/analysis';
import { analysisMethods, type Config } from '../core/config';
import type { GpuContext } from '../gpu/context';
import { analysisRecord } from '../core/analysis';
import { analysisCellTable, cellRecordsOf, cellTable, type CellTable, type ResultCellTables } from './cellTables';
import type { StackLayer, SurfaceFamily } from './family';
import { analyzeLabStackReusing } from './labStackReuse';
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
  /** With `cellTables`: every cell list as columns, and the records' cell lists left empty. */
  readonly tables?: ResultCellTables;
}

/**
 * Moves the converged sites along the normal onto every surface of the stack, labels each
 * surface with a jump flood (no Lloyd: the sites stay where the seeded surface put them), and
 * computes the scutoid statistics from the label adjacency and, where the surface has one, the
 * exact adjacency.
 */
export async function analyzeStack<C extends Config, G, S, L extends StackLayer, P>(
  family: SurfaceFamily<C, G, S, L, P>,
  config: C,
  seeded: SeededSurface<G, S>,
  context: GpuContext,
  signal?: AbortSignal,
  cellTables = false,
): Promise<SheetStack> {
  const start = performance.now();
  const { geometry } = seeded;
  family.checkSheet(config, geometry);
  const layers = family.stack(config, geometry);
  // The methods are the ones core/config/analysisMethods.ts describes (the sweep's columns
  // read the same description): labels and/or exact on the GPU engine, exact on the exact one.
  const methods = analysisMethods(config, seeded.engine.name);
  const labelsAsked = methods.includes('labels');
  const labeller = family.labeller(context, config, geometry, seeded.engine);
  try {
    const projected: P[] = [];
    const labelImages: LabelImage[] = [];
    const labelled: SurfaceAdjacency[] = [];
    for (const layer of layers) {
      throwIfAborted(signal);
      const sites = family.project(geometry, layer, seeded.sites);
      projected.push(sites);
      // The exact engine makes no label textures (seeded.labels null), and where only the exact
      // method is asked for no surface but the seeded one needs any: those label images are
      // drawn on the CPU, only when a view reads them.
      if (seeded.labels === null || (!labelsAsked && layer.role !== 'seeded')) {
        labelImages.push(lazyLabels(family.labelFrame(geometry, layer), () => family.exactLabels(geometry, layer, sites)));
        continue;
      }
      let labels = seeded.labels;
      if (layer.role !== 'seeded') {
        labels = labeller.label(layer, sites);
        await yieldToEventLoop();
      }
      labelImages.push({ ...family.labelFrame(geometry, layer), labels });
      labelled.push(family.labelAdjacency(config, geometry, layer, labels, config.cells));
    }

    // The protocol: which cells are valid, how intercalations are counted (docs/protocols.md).
    const invalid = family.protocolInvalid(config, geometry, seeded.sites);
    // The lab's analysis carries the sums of layers shared with the previous run's stack (the
    // same seeded surface at a smaller ratio): the same numbers, see labStackReuse.ts.
    const analyze = (surfaces: SurfaceAdjacency[]) => (invalid ? analyzeLabStackReusing(surfaces, invalid) : analyzeSurfaces(surfaces));
    const analyses: AnalysisRecord[] = [];
    const analysisTables: ResultCellTables['analyses'] = [];
    // With cell tables, the per-cell statistics stay columns and the record's list is empty.
    const record = (method: 'labels' | 'exact', minContactLength: number, analysis: ReturnType<typeof analyze>) => {
      if (!cellTables) {
        // Per-cell records built on first read (a sweep reads only the summary).
        const cells = once(() => analysisRecord(method, minContactLength, analysis, config.sheet.protocol).cells);
        return {
          method,
          protocol: config.sheet.protocol,
          minContactLength,
          summary: analysis.summary,
          get cells() {
            return cells();
          },
        };
      }
      analysisTables.push(analysisCellTable(analysis.cells));
      return { method, protocol: config.sheet.protocol, minContactLength, summary: analysis.summary, cells: [] };
    };
    if (methods.includes('labels')) {
      const minContact = family.minContactLengths(config, geometry, layers, 'labels');
      const inputs = minContact ? labelled.map((surface, k) => withMinBoundaryLength(surface, minContact.perLayer[k])) : labelled;
      analyses.push(record('labels', minContact?.reported ?? 0, analyze(inputs)));
    }
    let exactSurfaces: SurfaceAdjacency[] | null = null;
    if (methods.includes('exact')) {
      exactSurfaces = layers.map((layer, k) => family.exactAdjacency(config, geometry, layer, seeded.sites, projected[k]));
      const minContact = family.minContactLengths(config, geometry, layers, 'exact');
      const inputs = minContact ? exactSurfaces.map((surface, k) => withMinBoundaryLength(surface, minContact.perLayer[k])) : exactSurfaces;
      analyses.push(record('exact', minContact?.reported ?? 0, analyze(inputs)));
    }
    const adjacencyMs = performance.now() - start;

    const section = family.resultSection(config, geometry, seeded, labeller);
    // Cells and their contacts: exact where only the exact method ran, else from the label images.
    const cellSurfaces = !labelsAsked && exactSurfaces ? exactSurfaces : labelled;
    // Tables and records built on first read (a sweep reads only the analyses: a table per layer
    // per run was a twentieth of a sweep's time); none with cell tables (the columns are the cells).
    const tableOf = layers.map((layer, k) =>
      once((): CellTable =>
        cellTable(cellSurfaces[k], (position, coordinates) => family.cellPlacements(config, layer, seeded.sites, projected[k], position, coordinates)),
      ),
    );
    const cellsOf = (k: number) => once(() => (cellTables ? [] : cellRecordsOf(tableOf[k]())));
    const surfaces: SurfaceRecord[] = layers.slice(1).map((layer, index) => {
      const cells = cellsOf(index + 1);
      return {
        name: layer.name,
        role: layer.role === 'layer' ? 'layer' : 'other',
        offset: layer.offset,
        ratio: layer.ratio,
        grid: { ...labelImages[index + 1].grid },
        get cells() {
          return cells();
        },
      };
    });
    const seededCells = cellsOf(0);
    const tables = cellTables ? tableOf.map((table) => table()) : [];
    const resultTables = cellTables ? { tables: { cells: tables[0], surfaces: tables.slice(1), analyses: analysisTables } } : {};
    return {
      get seededCells() {
        return seededCells();
      },
      surfaces,
      analyses,
      labelImages,
      ...section,
      adjacencyMs,
      ...resultTables,
    };
  } finally {
    labeller.dispose();
  }
}

/** `compute()` on the first call, the same value after. */
function once<T>(compute: () => T): () => T {
  let value: { v: T } | null = null;
  return () => (value ??= { v: compute() }).v;
}

/** A label image whose labels are computed on first read (and kept). */
function lazyLabels(frame: Omit<LabelImage, 'labels'>, compute: () => Int32Array): LabelImage {
  let labels: Int32Array | null = null;
  return {
    ...frame,
    get labels() {
      labels ??= compute();
      return labels;
    },
  };
}
