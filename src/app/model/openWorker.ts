/**
 * The worker that opens a result with its cells side file (issue 27), so the page's main thread
 * never holds a task of seconds: it reads and decodes the side file, checks the result as the
 * page does (model/project.ts openParsed), builds each surface's label image from the exact
 * cells of its sites (view/exactLabels.ts: PlanarVoronoi and rasterizeCells, ~1 s per surface at
 * 100,000 cells) and paints the views' pictures (view/workerPictures.ts). What comes back is small or
 * transferred: the result without its cell lists, the side file's bytes, the label images and
 * the pictures; the page reads the cell records from the bytes (run/lazyRecords.ts).
 */
import { decodeCellsFile, withCellRecords, type CellsFileRecord } from '../../run/cellTables';
import type { SheetResult } from '../../run';
import { openParsed } from './project';
import type { FromOpenWorker, ToOpenWorker } from './openProtocol';
import { drawPictures } from '../../view/workerPictures';

interface OpenWorkerScope {
  postMessage(message: FromOpenWorker, options?: StructuredSerializeOptions): void;
}
const scope = self as unknown as OpenWorkerScope;
const post = (message: FromOpenWorker, transfer: Transferable[] = []) => scope.postMessage(message, { transfer });

self.onmessage = async (event: MessageEvent<ToOpenWorker>) => {
  const { id, data, record, side, name } = event.data;
  const progress = (line: string, fraction: number) => post({ type: 'progress', id, line, fraction });
  try {
    progress(`Reading ${record.path}…`, 0.05);
    const bytes = new Uint8Array(await side.arrayBuffer());
    let result: SheetResult;
    try {
      progress(`Decoding ${record.path}…`, 0.15);
      result = withCellRecords(data as SheetResult & { cellsFile: CellsFileRecord }, decodeCellsFile(record, bytes));
    } catch (error) {
      throw new Error(`${name} with ${record.path}: ${(error as Error).message}`);
    }
    progress('Drawing the exact cells of every surface…', 0.3);
    const opened = openParsed(result, name);
    if (opened.kind === 'project') throw new Error(`${name}: a project file has no cells side file.`);
    const checked = opened.kind === 'result' ? opened.output.result : opened.result;
    const stripped = {
      ...checked,
      cells: null,
      surfaces: checked.surfaces.map((s) => ({ ...s, cells: null })),
      analyses: checked.analyses.map((a) => ({ ...a, cells: null })),
    };
    if (opened.kind === 'result-rerun') {
      post({ type: 'opened', id, kind: 'result-rerun', result: stripped, bytes: bytes.buffer, labelImages: [], presented: undefined }, [bytes.buffer]);
      return;
    }
    progress('Painting the pictures…', 0.7);
    const { presented, transfer } = drawPictures(opened.output, { highlightScutoids: event.data.highlightScutoids, selected: -1 });
    const labelImages = opened.output.labelImages;
    post({ type: 'opened', id, kind: 'result', result: stripped, bytes: bytes.buffer, labelImages, presented }, [
      bytes.buffer,
      ...labelImages.map((image) => image.labels.buffer as ArrayBuffer),
      ...transfer,
    ]);
  } catch (error) {
    post({ type: 'error', id, message: error instanceof Error ? error.message : String(error) });
  }
};
