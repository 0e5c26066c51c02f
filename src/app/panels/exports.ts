/**
 * Downloads: the result JSON (the same document the CLI writes), the per-cell CSV, the sweep
 * CSV, a PNG of the 3D view and the cells as a PLY mesh. Each carries its provenance: version,
 * seed and the full configuration (CSV and PLY comment lines, PNG tEXt chunks). File names carry the seed and the
 * surface, so several exports of a session stay apart.
 */
import { cellCsv, provenanceLines } from '../model/cellRows';
import { withPngText } from '../model/pngText';
import { cellsPly } from '../model/ply';
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
}

function baseName(stack: ViewStack): string {
  const { config } = stack.result;
  return `tissue-sheet-${config.surface.kind}-seed${config.seed}`;
}

export function bindExports(root: HTMLElement, sources: ExportSources): void {
  const actions: Record<string, () => Promise<void> | void> = {
    json: () => withStack((s) => download(`${baseName(s)}.json`, JSON.stringify(s.result, null, 2), 'application/json')),
    cells: () => withStack((s) => download(`${baseName(s)}-cells.csv`, cellCsv(s), 'text/csv')),
    ply: () => withStack((s) => download(`${baseName(s)}-cells.ply`, cellsPly(s), 'application/octet-stream')),
    png: async () => {
      // An empty view is refused: a blank picture would pass for a result.
      const stack = sources.stack();
      if (!stack) throw new Error('Nothing to save yet: the view is empty until a run has finished.');
      const png = new Uint8Array(await (await sources.viewPng()).arrayBuffer());
      const { result } = stack;
      const tagged = withPngText(png, [
        ['Software', `${result.software.name} ${result.software.version}`],
        ['Description', provenanceLines(stack, '3D view of a tissue-sheet result').join('\n')],
        ['tissue-sheet:version', result.software.version],
        ['tissue-sheet:seed', String(result.seed)],
        ['tissue-sheet:config', JSON.stringify(result.config)],
      ]);
      download(`${baseName(stack)}-view.png`, new Blob([tagged as BlobPart], { type: 'image/png' }));
    },
    sweep: () => {
      const csv = sources.sweepCsv();
      if (!csv) throw new Error('Run a sweep first: there is no sweep CSV yet.');
      download('tissue-sheet-sweep.csv', csv, 'text/csv');
    },
  };
  const withStack = (action: (stack: ViewStack) => void) => {
    const stack = sources.stack();
    if (!stack) throw new Error('Nothing to export yet: run a sheet first.');
    action(stack);
  };
  for (const button of root.querySelectorAll<HTMLButtonElement>('[data-export]')) {
    button.addEventListener('click', async () => {
      try {
        await actions[button.dataset.export!]?.();
      } catch (error) {
        sources.onError((error as Error).message);
      }
    });
  }
}
