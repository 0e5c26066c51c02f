/**
 * The worker that opens a result with its cells side file (issue 27), so the page's main thread
 * never holds a task of seconds: it reads and decodes the side file, checks the result as the
 * page does (model/project.ts openParsed), builds each surface's label image from the exact
 * cells of its sites (view/exactLabels.ts: PlanarVoronoi and rasterizeCells, ~1 s per surface at
 * 100,000 cells) and paints the views' pictures (view/workerPictures.ts). What comes back is small or
 * transferred: the result without its cell lists, the side file's bytes, the label images and
 * the pictures; the page reads the cell records from the bytes (run/lazyRecords.ts).
 *
 * It then holds the opened result (its records and a copy of its label images), or a large result
 * the page made itself and handed over (`hold`), for what would
 * block the page's thread again: the pictures with the scutoid highlight toggled, and the
 * exports built from the cells (exportFiles.ts: a PLY, SVG or project of 25,000 cells took the
 * page's thread 1-2.5 s), sent back as Blobs.
 */
import { decodeCellsFile, withCellRecords, type CellsFileRecord } from '../../run/cellTables';
import type { SheetOutput, SheetResult } from '../../run';
import { openParsed, parseFileJson, type OpenedFile } from './project';
import { resultCellTables, tableBuffers } from '../../run/recordTables';
import { withLazyCellRecords } from '../../run/lazyRecords';
import type { ExportMessage, FromOpenWorker, OpenJsonMessage, OpenMessage, PicturesMessage, ToOpenWorker } from './openProtocol';
import { drawPictures } from '../../view/workerPictures';
import { EXPORT_FILES, exportText, heldStack, withoutCells } from './exportFiles';

interface OpenWorkerScope {
  postMessage(message: FromOpenWorker, options?: StructuredSerializeOptions): void;
}
const scope = self as unknown as OpenWorkerScope;
const post = (message: FromOpenWorker, transfer: Transferable[] = []) => scope.postMessage(message, { transfer });

/** The result last opened (by request `opened`), with copies of the label images sent to the page. */
let held: { opened: number; output: SheetOutput } | null = null;

self.onmessage = async (event: MessageEvent<ToOpenWorker>) => {
  const message = event.data;
  try {
    if (message.type === 'open') await open(message);
    else if (message.type === 'open-json') await openJson(message);
    else if (message.type === 'hold')
      held = { opened: message.id, output: { result: withLazyCellRecords(message.result, message.tables), labelImages: message.labelImages } };
    else if (message.type === 'pictures') pictures(message);
    else exported(message);
  } catch (error) {
    post({ type: 'error', id: message.id, message: error instanceof Error ? error.message : String(error) });
  }
};

function heldOutput(message: PicturesMessage | ExportMessage): SheetOutput {
  if (!held || held.opened !== message.opened) throw new Error('the worker no longer holds this result');
  return held.output;
}

function pictures(message: PicturesMessage): void {
  const { presented, transfer } = drawPictures(heldOutput(message), { highlightScutoids: message.highlightScutoids, selected: -1 });
  post({ type: 'pictures', id: message.id, presented }, transfer);
}

function exported(message: ExportMessage): void {
  const text = exportText(heldStack(message.shown, heldOutput(message)), message.request);
  post({ type: 'exported', id: message.id, file: new Blob([text], { type: EXPORT_FILES[message.request.kind].type }) });
}

async function open(message: OpenMessage): Promise<void> {
  held = null;
  const { id, data, record, side, name } = message;
  const progress = (line: string, fraction: number) => post({ type: 'progress', id, line, fraction });
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
  const stripped = withoutCells(checked);
  if (opened.kind === 'result-rerun') {
    post({ type: 'opened', id, kind: 'result-rerun', result: stripped, bytes: bytes.buffer, labelImages: [], presented: undefined }, [bytes.buffer]);
    return;
  }
  progress('Painting the pictures…', 0.7);
  const { presented, transfer } = drawPictures(opened.output, { highlightScutoids: message.highlightScutoids, selected: -1 });
  const labelImages = opened.output.labelImages;
  // Kept with copies of the label images (the page gets these ones, transferred).
  held = { opened: id, output: { result: checked, labelImages: labelImages.map((image) => ({ ...image, labels: image.labels.slice() })) } };
  post({ type: 'opened', id, kind: 'result', result: stripped, bytes: bytes.buffer, labelImages, presented }, [
    bytes.buffer,
    ...labelImages.map((image) => image.labels.buffer as ArrayBuffer),
    ...transfer,
  ]);
}

/**
 * A large project or result JSON (cells inline): parsed and checked here, its records sent back
 * as transferred columns (run/recordTables.ts), its label images and pictures as for a side file.
 */
async function openJson(message: OpenJsonMessage): Promise<void> {
  held = null;
  const { id, name } = message;
  post({ type: 'progress', id, line: `Reading ${name}…`, fraction: 0.05 });
  const data = parseFileJson(await message.file.text(), name);
  post({ type: 'progress', id, line: 'Checking it…', fraction: 0.2 });
  const opened: OpenedFile = openParsed(data, name);
  const result = opened.kind === 'result-rerun' ? opened.result : opened.output.result;
  const tables = resultCellTables(result);
  const columns = tables ? tableBuffers(tables) : [];
  const reply = {
    type: 'opened' as const,
    id,
    kind: opened.kind,
    result: withoutCells(result),
    ...(tables ? { tables } : { records: result }),
    ...(opened.kind === 'project' ? { view: opened.view, sections: opened.sections } : {}),
  };
  if (opened.kind === 'result-rerun') {
    post({ ...reply, labelImages: [], presented: undefined }, columns);
    return;
  }
  post({ type: 'progress', id, line: 'Painting the pictures…', fraction: 0.7 });
  const highlightScutoids = opened.kind === 'project' ? opened.view.highlightScutoids : message.highlightScutoids;
  const { presented, transfer } = drawPictures(opened.output, { highlightScutoids, selected: -1 });
  const labelImages = opened.output.labelImages;
  held = { opened: id, output: { result, labelImages: labelImages.map((image) => ({ ...image, labels: image.labels.slice() })) } };
  post({ ...reply, labelImages, presented }, [...columns, ...labelImages.map((image) => image.labels.buffer as ArrayBuffer), ...transfer]);
}
