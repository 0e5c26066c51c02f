/**
 * The text of each export of the result on screen that is built from its cells (result JSON,
 * PLY, VTK, unrolled SVG, project), in one place for the page's main thread and the worker that
 * holds a large opened result (openWorker.ts, issue 27: a 100,000-cell PLY or project took the
 * main thread seconds). Pure: what depends on the page (the view state, the project's other
 * sections, the time saved) comes in the request, so both threads write the same bytes.
 */
import type { SheetResult } from '../../run';
import { viewStack, type ViewStack } from '../../view/stack';
import { cellsPly } from './ply';
import { projectJson, type ViewState } from './project';
import { unrolledSvg } from './svg';
import { cellsVtk } from './vtk';

export type ExportKind = 'json' | 'ply' | 'vtk' | 'svg' | 'project';

export interface ExportRequest {
  readonly kind: ExportKind;
  /** The SVG's printed width (mm). */
  readonly widthMm?: number;
  /** A project's view state, other sections and time saved (ISO). */
  readonly view?: ViewState;
  readonly sections?: Record<string, unknown>;
  readonly savedAt?: string;
}

/** Each export's media type and file name after the result's base name. */
export const EXPORT_FILES: Record<ExportKind, { type: string; suffix: string }> = {
  json: { type: 'application/json', suffix: '.json' },
  ply: { type: 'application/octet-stream', suffix: '-cells.ply' },
  vtk: { type: 'application/octet-stream', suffix: '-cells.vtk' },
  svg: { type: 'image/svg+xml', suffix: '-unrolled.svg' },
  project: { type: 'application/json', suffix: '.tissue-sheet.json' },
};

export function exportText(stack: ViewStack, request: ExportRequest): string {
  switch (request.kind) {
    case 'json':
      return JSON.stringify(stack.result, null, 2);
    case 'ply':
      return cellsPly(stack);
    case 'vtk':
      return cellsVtk(stack);
    case 'svg':
      return unrolledSvg(stack, { widthMm: request.widthMm });
    case 'project':
      if (!request.view) throw new Error('a project export needs the view state');
      return projectJson({ result: stack.result, labelImages: stack.surfaces.map((s) => s.image) }, request.view, request.sections, request.savedAt);
  }
}

/** `result` without its cell lists (null): what the page sends of the result on screen. */
export function withoutCells(result: SheetResult): SheetResult {
  return {
    ...result,
    cells: null,
    surfaces: result.surfaces.map((s) => ({ ...s, cells: null })),
    analyses: result.analyses.map((a) => ({ ...a, cells: null })),
  } as unknown as SheetResult;
}

/**
 * In the worker: the stack of the page's result `shown` (its cell lists null: withoutCells; the
 * page may have changed its headline since) with the cell lists of the result the worker holds,
 * in the page's key order, so that JSON.stringify writes what the page would.
 */
export function heldStack(shown: SheetResult, held: { result: SheetResult; labelImages: ViewStack['surfaces'][number]['image'][] }): ViewStack {
  const result: SheetResult = {
    ...shown,
    cells: held.result.cells,
    surfaces: shown.surfaces.map((s, k) => ({ ...s, cells: held.result.surfaces[k].cells })),
    analyses: shown.analyses.map((a, k) => ({ ...a, cells: held.result.analyses[k].cells })),
  };
  return viewStack({ result, labelImages: held.labelImages });
}
