/**
 * The page's side of the worker that opens a result with its cells side file (openWorker.ts,
 * issue 27): hands it the parsed JSON and the side file (a Blob: read there), reports its
 * progress, and reads the cells from the bytes it sends back, each record made when first read
 * (run/lazyRecords.ts), so opening a 100,000-cell result holds the main thread for no task over
 * ~50 ms. A newer request supersedes an older one; a worker that dies fails the request and is
 * replaced next time.
 *
 * The worker keeps the result it opened last: while that result is on screen (`holds`), the
 * pictures of another scutoid highlight (`pictures`) and the exports built from its cells
 * (`exportFile`) are made there.
 */
import { decodeCellsFile, type CellsFileRecord } from '../../run/cellTables';
import type { LabelImage, SheetOutput, SheetResult } from '../../run';
import { resultColumns, withLazyCellRecords } from '../../run/lazyRecords';
import { rememberPictures } from '../../view/workerPictures';
import type { ViewStack } from '../../view/stack';
import type { OpenedFile } from './project';
import type { FromOpenWorker, ToOpenWorker } from './openProtocol';
import { requestWorker } from '../../view/workerRequest';
import { withoutCells, type ExportRequest } from './exportFiles';

export interface OpenRequest {
  data: unknown;
  record: CellsFileRecord;
  side: Blob;
  name: string;
  highlightScutoids: boolean;
  /** A line for the status and the fraction done (0..1). */
  onProgress?(line: string, fraction: number): void;
}

type Reply = Extract<FromOpenWorker, { type: 'opened' | 'pictures' | 'exported' | 'error' }>;

export class ResultOpener {
  private worker: Worker | null = null;
  /** The last id given (every message has its own). */
  private lastId = 0;
  /** The latest open and pictures requests (an older one is superseded). */
  private latestOpen = 0;
  private latestPictures = 0;
  /** The result the worker holds: the open request's id and the label images the page got. */
  private held: { opened: number; images: readonly LabelImage[] } | null = null;

  constructor(private readonly createWorker: () => Worker = () => new Worker(new URL('./openWorker.ts', import.meta.url), { type: 'module' })) {}

  async open(request: OpenRequest): Promise<OpenedFile> {
    const id = ++this.lastId;
    this.latestOpen = id;
    this.held = null;
    const progress = request.onProgress ?? (() => {});
    const message: ToOpenWorker = {
      type: 'open',
      id,
      data: request.data,
      record: request.record,
      side: request.side,
      name: request.name,
      highlightScutoids: request.highlightScutoids,
    };
    const opened = await this.ask(message, request.name, () => id === this.latestOpen, progress);
    const bytes = opened.type === 'opened' ? opened.bytes : undefined;
    return this.received(id, opened, (result) => withLazyCellRecords(result, decodeCellsFile(request.record, new Uint8Array(bytes!))));
  }

  /**
   * A large project or result JSON with its cells inline, read and parsed in the worker (a
   * 25,000-cell project held the main thread ~0.5 s in JSON.parse and checks, issue 27).
   */
  async openJson(file: Blob, name: string, highlightScutoids: boolean, onProgress?: (line: string, fraction: number) => void): Promise<OpenedFile> {
    const id = ++this.lastId;
    this.latestOpen = id;
    this.held = null;
    const opened = await this.ask({ type: 'open-json', id, file, name, highlightScutoids }, name, () => id === this.latestOpen, onProgress);
    return this.received(id, opened, (result) =>
      opened.type === 'opened' && opened.tables ? withLazyCellRecords(result, opened.tables) : (opened as { records: SheetResult }).records,
    );
  }

  /** The page's file from the worker's reply; `withCells` gives the result its cell lists. */
  private async received(id: number, opened: Reply, withCells: (stripped: SheetResult) => SheetResult): Promise<OpenedFile> {
    if (opened.type !== 'opened') throw new Error(opened.type === 'error' ? opened.message : `unexpected reply ${opened.type}`);
    // Records made when read (run/lazyRecords.ts): the page reads a few of 300,000.
    const result = withCells(opened.result as SheetResult);
    if (opened.kind === 'result-rerun') return { kind: 'result-rerun', result };
    const output: SheetOutput = { result, labelImages: opened.labelImages };
    rememberPictures(output, opened.presented);
    this.held = { opened: id, images: opened.labelImages };
    // The worker's reply ends its task here; the page draws the result in the next ones.
    await new Promise((resolve) => setTimeout(resolve, 0));
    if (opened.kind === 'project') return { kind: 'project', output, view: opened.view!, sections: opened.sections };
    return { kind: 'result', output, drawnFrom: 'cells' };
  }

  /**
   * Whether the worker holds the result `stack` shows, handing it over first where the page made
   * it (a run of over 20,000 cells, its records lazy over columns: cloning the columns and label
   * images is one short task, where its pictures and exports would hold the page for seconds).
   */
  holdShown(stack: ViewStack): boolean {
    if (this.holds(stack)) return true;
    const tables = resultColumns(stack.result);
    if (!tables) return false;
    const id = ++this.lastId;
    const labelImages = stack.surfaces.map((surface) => surface.image);
    const message: ToOpenWorker = { type: 'hold', id, result: withoutCells(stack.result), tables, labelImages };
    (this.worker ??= this.createWorker()).postMessage(message);
    this.held = { opened: id, images: labelImages };
    return true;
  }

  /** Whether the worker holds the result `stack` shows (the one opened last, still on screen). */
  holds(stack: ViewStack): boolean {
    const held = this.held;
    return held !== null && held.images.length === stack.surfaces.length && stack.surfaces.every((s, k) => s.image === held.images[k]);
  }

  /**
   * The pictures of `stack` (held) with the scutoid stripes on or off, drawn in the worker and
   * kept for the views (workerPictures.ts); false when it does not hold it or a newer request
   * came (the views then draw as before).
   */
  async pictures(stack: ViewStack, highlightScutoids: boolean): Promise<boolean> {
    const held = this.held;
    if (!held || !this.holds(stack)) return false;
    const id = ++this.lastId;
    this.latestPictures = id;
    const reply = await this.ask({ type: 'pictures', id, opened: held.opened, highlightScutoids }, 'the pictures', () => id === this.latestPictures).catch(
      () => null,
    );
    if (reply?.type !== 'pictures' || !this.holds(stack)) return false;
    rememberPictures({ result: stack.result, labelImages: [...held.images] }, reply.presented);
    return true;
  }

  /** The export `request` of `stack` (held), built in the worker; null when it does not hold it. */
  async exportFile(stack: ViewStack, request: ExportRequest): Promise<Blob | null> {
    const held = this.held;
    if (!held || !this.holds(stack)) return null;
    const id = ++this.lastId;
    const reply = await this.ask(
      { type: 'export', id, opened: held.opened, shown: withoutCells(stack.result), request },
      `the ${request.kind} export`,
      () => true,
    );
    if (reply.type === 'exported') return reply.file;
    // The worker let go of it (a newer file is being opened): built on the page, as before.
    if (reply.type === 'error' && /no longer holds/.test(reply.message)) return null;
    throw new Error(reply.type === 'error' ? reply.message : `unexpected reply ${reply.type}`);
  }

  private async ask(message: ToOpenWorker, name: string, isLatest: () => boolean, progress?: (line: string, fraction: number) => void): Promise<Reply> {
    const worker = (this.worker ??= this.createWorker());
    let answer: Reply | null = null;
    await requestWorker<FromOpenWorker>({
      worker,
      id: message.id,
      message,
      isLatest,
      superseded: () => new Error('superseded by a newer request'),
      crashed: (details) => new Error(`${name}: the worker opening it stopped (${details})`),
      onCrash: () => {
        if (this.worker === worker) this.worker = null;
        this.held = null;
      },
      handle: (data, finish) => {
        if (data.type === 'progress') progress?.(data.line, data.fraction);
        else {
          answer = data;
          finish.done();
        }
      },
    });
    return answer!;
  }
}
