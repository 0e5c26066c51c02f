/** The JSON form of a scutoid analysis, shared by simulated results and measured tissue. */
import type { ScutoidAnalysis, ScutoidSummary } from './scutoids';

/** Per-cell statistics over the stack [seeded, layers..., other]. */
export interface CellStatisticsRecord {
  readonly id: number;
  /** Not a border cell on any surface: counted in the statistics. */
  readonly valid: boolean;
  /** Valid, and its neighbour set is not the same on every surface. */
  readonly scutoid: boolean;
  /** Neighbours on the last surface that are not on the first, and the other way round. */
  readonly won: number;
  readonly lost: number;
  /** Apico-basal transitions, counted surface to surface through the layers. */
  readonly transitions: number;
  /** Size of the union of the neighbour sets over all surfaces. */
  readonly neighbours3D: number;
  /** Sides on each surface, in stack order. */
  readonly sides: number[];
}

/** Scutoid statistics over the stack [seeded, layers..., other] from one adjacency method. */
export interface AnalysisRecord {
  /**
   * "labels": adjacent texels of the label images; "exact": the exact Voronoi diagram (Delaunay
   * of the unrolled sites on planes and tubes, the restricted Voronoi diagram on closed surfaces).
   */
  readonly method: 'labels' | 'exact';
  /** Which rules decided valid cells and counted transitions (docs/protocols.md). */
  readonly protocol: 'default' | 'lab';
  /** Contacts shorter than this (µm) were ignored (0: every contact counts, the planar exact method). */
  readonly minContactLength: number;
  /** Includes `perSurface`: polygon distribution, Lewis and Aboav-Weaire per surface. */
  readonly summary: ScutoidSummary;
  readonly cells: CellStatisticsRecord[];
}

/** The JSON form of a scutoid analysis: per-cell records instead of typed arrays. */
export function analysisRecord(
  method: 'labels' | 'exact',
  minContactLength: number,
  analysis: ScutoidAnalysis,
  protocol: 'default' | 'lab' = 'default',
): AnalysisRecord {
  const c = analysis.cells;
  const cells = cellStatisticsRecords(c, (id) => c.sides.map((perSurface) => perSurface[id]));
  return { method, protocol, minContactLength, summary: analysis.summary, cells };
}

/** The per-cell scalar columns a record list is made from (flags 1 or 0). */
export interface CellStatisticsColumns {
  readonly valid: ArrayLike<number>;
  readonly scutoid: ArrayLike<number>;
  readonly won: ArrayLike<number>;
  readonly lost: ArrayLike<number>;
  readonly transitions: ArrayLike<number>;
  readonly neighbours3D: ArrayLike<number>;
}

/**
 * One record per cell of the columns, `sidesOf` giving a cell's sides on each surface; cells
 * `from` to `to` - 1 only when given (the page builds a large result's records in slices).
 */
export function cellStatisticsRecords(c: CellStatisticsColumns, sidesOf: (id: number) => number[], from = 0, to = c.valid.length): CellStatisticsRecord[] {
  return Array.from({ length: Math.max(0, to - from) }, (_, k) => {
    const id = from + k;
    return {
      id,
      valid: c.valid[id] === 1,
      scutoid: c.scutoid[id] === 1,
      won: c.won[id],
      lost: c.lost[id],
      transitions: c.transitions[id],
      neighbours3D: c.neighbours3D[id],
      sides: sidesOf(id),
    };
  });
}
