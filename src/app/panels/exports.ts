/**
 * Downloads: the result JSON (the same document the CLI writes), the per-cell CSV, the sweep
 * CSV, a PNG of the 3D view, the cells as a PLY mesh and as a legacy VTK file (ParaView), the
 * unrolled surfaces as SVG, a figure PNG at a chosen DPI and width (legend, scale bar), and a
 * project file (result, label images, view state); and opening a project or a CLI result JSON. Each carries its provenance: version,
 * seed and the full configuration (CSV and PLY comment lines, PNG tEXt chunks). File names carry the seed and the
 * surface, so several exports of a session stay apart. The files built from the cells come from
 * model/exportFiles.ts: here, or for a large result opened with its side file in the worker that
 * holds it (model/openClient.ts; issue 27), the same bytes.
 */
import { cellCsv, provenanceText } from '../model/cellRows';
import { withPngText } from '../model/pngText';
import { EXPORT_FILES, exportText, type ExportRequest } from '../model/exportFiles';
import type { OpenedFile, ViewState } from '../model/project';
import { openSections, prepareSections, savedSections } from '../model/projectSections';
import { openFiles, type SideFileOpener, type WholeFileOpener } from '../model/resultFiles';
import { ResultOpener } from '../model/openClient';
import { figurePng, figureSize } from '../view/figure';
import type { SheetView3D } from '../../view/sheetView3d';
import type { ViewStack } from '../../view/stack';

export function download(name: string, data: Blob | string, type = 'text/plain'): void {
  const blob = typeof data === 'string' ? new Blob([data], { type }) : data;
  const url = URL.createObjectURL(blob);
  const link = document.createElement('a');
  link.href = url;
  link.download = name;
  document.body.append(link);
  link.click();
  link.remove();
  setTimeout(() => URL.revokeObjectURL(url), 10_000);
}

export interface ExportSources {
  stack(): ViewStack | null;
  sweepCsv(): string;
  viewPng(): Promise<Blob>;
  onError(message: string): void;
  /** The 3D view (a closed surface's figure is rendered from it), null without WebGL. */
  view(): SheetView3D | null;
  viewState(): ViewState;
  /** Shows an opened project or result file; `note` says where it came from. */
  onOpen(file: OpenedFile, name: string): Promise<void> | void;
  /** Where opening a large file stands: a line and the fraction done (0..1). */
  onOpenProgress?(line: string, fraction: number): void;
}

/** The export buttons this module adds beside the page's own (index.html has the first five). */
const MORE_EXPORTS: [key: string, text: string, title: string][] = [
  ['vtk', 'Cells as VTK', 'Legacy VTK polygons (ParaView, VisIt) with cell_id, surface, sides, scutoid, valid per cell'],
  ['svg', 'Unrolled SVG', 'The unrolled surfaces as exact cell polygons in µm, with legend and scale bar'],
  ['figure', 'Figure PNG', 'The unrolled surfaces (closed surfaces: the 3D view) with legend and scale bar, at the DPI and width chosen'],
  ['project', 'Save project', 'The result, the pictures and the view (camera, surfaces, cut, picked cell) in one file'],
];

function addControls(root: HTMLElement): { dpi: HTMLSelectElement; width: HTMLInputElement; file: HTMLInputElement } {
  for (const [key, text, title] of MORE_EXPORTS) {
    const button = document.createElement('button');
    button.type = 'button';
    button.dataset.export = key;
    button.textContent = text;
    button.title = title;
    root.append(button);
  }
  const figure = document.createElement('div');
  figure.className = 'figure-options';
  const dpi = document.createElement('select');
  dpi.id = 'figure-dpi';
  for (const value of [150, 300, 600]) dpi.append(new Option(`${value} dpi`, String(value), value === 300, value === 300));
  const width = document.createElement('input');
  width.id = 'figure-width';
  width.type = 'number';
  width.min = '20';
  width.max = '500';
  width.step = '1';
  width.value = '180';
  const dpiLabel = document.createElement('label');
  dpiLabel.append('Figure resolution ', dpi);
  const widthLabel = document.createElement('label');
  widthLabel.append('width (mm) ', width);
  const openLabel = document.createElement('label');
  openLabel.className = 'open-file';
  const file = document.createElement('input');
  file.type = 'file';
  file.id = 'open-file';
  // A big result is two files (RESULT.json + RESULT.cells.bin): both chosen together.
  file.accept = '.json,application/json,.bin';
  file.multiple = true;
  openLabel.title = 'A project, a result JSON, or a result JSON with its .cells.bin side file (choose both)';
  openLabel.append('Open project or result JSON ', file);
  figure.append(dpiLabel, ' ', widthLabel, ' ', openLabel);
  root.append(figure);
  return { dpi, width, file };
}

function baseName(stack: ViewStack): string {
  const { config } = stack.result;
  return `tissue-sheet-${config.surface.kind}-seed${config.seed}`;
}

/** Binds the export buttons and the file opener; returns the worker client holding an opened large result (null without workers). */
export function bindExports(root: HTMLElement, sources: ExportSources): ResultOpener | null {
  const more = addControls(root);
  // A result with its cells side file opens in a worker (model/openWorker.ts, issue 27).
  const opener = typeof Worker === 'undefined' ? null : new ResultOpener();
  const openSide: SideFileOpener | undefined = opener
    ? (data, record, side, name) =>
        opener.open({
          data,
          record,
          side: side as File,
          name,
          highlightScutoids: sources.viewState().highlightScutoids,
          onProgress: (line, fraction) => sources.onOpenProgress?.(`Opening ${name}: ${line}`, fraction),
        })
    : undefined;
  const openWhole: WholeFileOpener | undefined = opener
    ? (json, name) =>
        opener.openJson(json as File, name, sources.viewState().highlightScutoids, (line, fraction) =>
          sources.onOpenProgress?.(`Opening ${name}: ${line}`, fraction),
        )
    : undefined;
  more.file.addEventListener('change', async () => {
    const chosen = [...(more.file.files ?? [])];
    more.file.value = '';
    if (chosen.length === 0) return;
    try {
      const { file, name } = await openFiles(chosen, openSide, openWhole);
      await sources.onOpen(file, name);
      if (file.kind === 'project') await openSections(file.sections, name);
    } catch (error) {
      // The progress line ("Opening ...: Decoding ...") would read as a hang.
      sources.onOpenProgress?.(`Not opened (${chosen.map((f) => f.name).join(' + ')}); the result on screen is as it was.`, 0);
      sources.onError((error as Error).message);
    }
  });
  const actions: Record<string, () => Promise<void> | void> = {
    json: () => built({ kind: 'json' }),
    cells: () => withStack((s) => download(`${baseName(s)}-cells.csv`, cellCsv(s), 'text/csv')),
    ply: () => built({ kind: 'ply' }),
    png: async () => {
      // An empty view is refused: a blank picture would pass for a result.
      const stack = sources.stack();
      if (!stack) throw new Error('Nothing to save yet: the view is empty until a run has finished.');
      const png = new Uint8Array(await (await sources.viewPng()).arrayBuffer());
      const tagged = withPngText(png, provenanceText(stack, '3D view of a tissue-sheet result'));
      download(`${baseName(stack)}-view.png`, new Blob([tagged as BlobPart], { type: 'image/png' }));
    },
    vtk: () => built({ kind: 'vtk' }),
    svg: () => {
      const widthMm = Number(more.width.value);
      figureSize({ dpi: 300, widthMm }, 1); // the width is checked as for the PNG (20 to 500 mm)
      return built({ kind: 'svg', widthMm });
    },
    figure: async () => {
      const stack = sources.stack();
      if (!stack) throw new Error('Nothing to save yet: the view is empty until a run has finished.');
      const dpi = Number(more.dpi.value);
      const png = await figurePng(stack, sources.view(), { dpi, widthMm: Number(more.width.value) });
      download(`${baseName(stack)}-figure-${dpi}dpi.png`, new Blob([png as BlobPart], { type: 'image/png' }));
    },
    project: async () => {
      await prepareSections();
      await built({ kind: 'project', view: sources.viewState(), sections: savedSections(), savedAt: new Date().toISOString() });
    },
    sweep: () => {
      const csv = sources.sweepCsv();
      if (!csv) throw new Error('Run a sweep first: there is no sweep CSV yet.');
      download('tissue-sheet-sweep.csv', csv, 'text/csv');
    },
  };
  const withStack = <T>(action: (stack: ViewStack) => T): T => {
    const stack = sources.stack();
    if (!stack) throw new Error('Nothing to export yet: run a sheet first.');
    return action(stack);
  };
  // A file built from the cells: in the worker holding a large result (opened, or made here), else here.
  const built = (request: ExportRequest) =>
    withStack(async (s) => {
      const { type, suffix } = EXPORT_FILES[request.kind];
      const file = (opener?.holdShown(s) ? await opener.exportFile(s, request) : null) ?? exportText(s, request);
      download(`${baseName(s)}${suffix}`, file, type);
    });
  for (const button of root.querySelectorAll<HTMLButtonElement>('[data-export]')) {
    button.addEventListener('click', async () => {
      try {
        await actions[button.dataset.export!]?.();
      } catch (error) {
        sources.onError((error as Error).message);
      }
    });
  }
  return opener;
}
