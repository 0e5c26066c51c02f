/**
 * The sheet as the views see it: one entry per surface of the stack [seeded, layers..., other],
 * each with its label image, its cells and the number of sides of every cell there, plus the
 * per-cell flags (valid, scutoid) of the analysis shown. Pure data; no DOM.
 */
import { headlineMethod } from '../core/config/analysisMethods';
import { surfaceLayout } from '../core/config/surfaceLayout';
import type { AnalysisRecord, CellRecord, LabelImage, SheetOutput, SheetResult } from '../run';
import { analysisColumns } from '../run/lazyRecords';

export interface ViewSurface {
  readonly index: number;
  /** "basal", "apical" or "layer k". */
  readonly name: string;
  readonly role: 'seeded' | 'layer' | 'other';
  /** µm along the seeded surface's normal. */
  readonly offset: number;
  /** R / R_seeded on a tube, 1 on a plane, sqrt(area / seeded area) on a closed surface. */
  readonly ratio: number;
  readonly image: LabelImage;
  readonly cells: readonly CellRecord[];
  /** Sides of every cell on this surface (from the analysis shown). */
  readonly sides: Int32Array;
}

export interface ViewStack {
  readonly result: SheetResult;
  readonly analysis: AnalysisRecord | null;
  readonly surfaces: ViewSurface[];
  /** 1 for cells counted in the statistics. */
  readonly valid: Uint8Array;
  /** 1 for scutoids. */
  readonly scutoid: Uint8Array;
  /**
   * Closed surfaces (sphere, ellipsoid, mesh): label images are n x 6n cube-map atlases. Read
   * from the result's closed-surface record or its config's layout (core/config/surfaceLayout.ts).
   */
  readonly closed: boolean;
}

/**
 * The analysis the page and the element report (the headline %, the flags, the sides): the one
 * the result's headline comes from (core/analysis/headline.ts: the exact method wherever it
 * ran, else the labels method). A result file written before headlines existed: the same rule.
 */
export function primaryAnalysis(result: SheetResult): AnalysisRecord | null {
  const analyses = result.analyses ?? [];
  const method = result.headline?.method ?? headlineMethod(analyses.map((a) => a.method));
  return analyses.find((a) => a.method === method) ?? analyses[0] ?? null;
}

/** Which adjacency method a number comes from, in words. */
export function methodCaption(analysis: AnalysisRecord | null): string {
  if (!analysis) return 'no analysis';
  const protocol = analysis.protocol === 'lab' ? "; the lab's protocol (docs/protocols.md)" : '';
  if (analysis.method === 'exact') return `exact adjacency (Voronoi cells computed exactly, no pixels${protocol})`;
  const threshold = Number.isFinite(analysis.minContactLength) ? `, contacts < ${analysis.minContactLength.toFixed(2)} µm ignored` : '';
  return `label adjacency (touching pixels${threshold}; the exact method was not asked for: sheet.adjacency "labels"${protocol})`;
}

export function analysisByMethod(result: SheetResult, method: 'labels' | 'exact'): AnalysisRecord | null {
  return (result.analyses ?? []).find((a) => a.method === method) ?? null;
}

export function viewStack(output: SheetOutput): ViewStack {
  const { result, labelImages } = output;
  const analysis = primaryAnalysis(result);
  const n = result.cells.length;
  const records = result.surfaces ?? [];
  // A large opened result's analysis as columns (run/lazyRecords.ts): read without making records.
  const columns = analysisColumns(analysis?.cells);
  const surfaces: ViewSurface[] = labelImages.map((image, k) => {
    const record = k === 0 ? null : records[k - 1];
    const cells = k === 0 ? result.cells : (record?.cells ?? []);
    const sides = columns && columns.count === n ? columns.sides.slice(k * n, (k + 1) * n) : new Int32Array(n);
    for (let i = 0; i < n && !(columns && columns.count === n); i++) {
      const fromAnalysis = analysis?.cells[i]?.sides[k];
      sides[i] = fromAnalysis ?? cells[i]?.neighbours.length ?? 0;
    }
    return {
      index: k,
      name: image.name,
      role: k === 0 ? 'seeded' : (record?.role ?? 'other'),
      offset: record?.offset ?? 0,
      ratio: record?.ratio ?? 1,
      image,
      cells,
      sides,
    };
  });
  const valid = new Uint8Array(n);
  const scutoid = new Uint8Array(n);
  if (columns && columns.count === n) {
    valid.set(columns.valid);
    scutoid.set(columns.scutoid);
  }
  for (let i = 0; i < n && !(columns && columns.count === n); i++) {
    const stats = analysis?.cells[i];
    valid[i] = stats ? (stats.valid ? 1 : 0) : result.cells[i]?.touchesBorder ? 0 : 1;
    scutoid[i] = stats?.scutoid ? 1 : 0;
  }
  return { result, analysis, surfaces, valid, scutoid, closed: result.closed !== undefined || !surfaceLayout(result.config).flatPicture };
}
