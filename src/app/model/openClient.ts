/**
 * The page's side of the worker that opens a result with its cells side file (openWorker.ts,
 * issue 27): hands it the parsed JSON and the side file (a Blob: read there), reports its
 * progress, and reads the cells from the bytes it sends back, each record made when first read
 * (run/lazyRecords.ts), so opening a 100,000-cell result holds the main thread for no task over
 * ~50 ms. A newer request supersedes an older one; a worker that dies fails the request and is
 * replaced next time.
 */
import { decodeCellsFile, type CellsFileRecord } from '../../run/cellTables';
import type { SheetOutput, SheetResult } from '../../run';
import { withLazyCellRecords } from '../../run/lazyRecords';
import { rememberPictures } from '../../view/workerPictures';
import type { OpenedFile } from './project';
import type { FromOpenWorker, ToOpenWorker } from './openProtocol';
import { requestWorker } from '../../view/workerRequest';

export interface OpenRequest {
  data: unknown;
  record: CellsFileRecord;
  side: Blob;
  name: string;
  highlightScutoids: boolean;
  /** A line for the status and the fraction done (0..1). */
  onProgress?(line: string, fraction: number): void;
}

export class ResultOpener {
  private worker: Worker | null = null;
  private latest = 0;

  constructor(private readonly createWorker: () => Worker = () => new Worker(new URL('./openWorker.ts', import.meta.url), { type: 'module' })) {}

  async open(request: OpenRequest): Promise<OpenedFile> {
    const id = ++this.latest;
    const progress = request.onProgress ?? (() => {});
    const opened = await this.ask(id, request, progress);
    if (opened.type !== 'opened') throw new Error(opened.message);
    // Records made when read (run/lazyRecords.ts): the page reads a few of 300,000.
    const result = withLazyCellRecords(opened.result as SheetResult, decodeCellsFile(request.record, new Uint8Array(opened.bytes)));
    if (opened.kind === 'result-rerun') return { kind: 'result-rerun', result };
    const output: SheetOutput = { result, labelImages: opened.labelImages };
    rememberPictures(output, opened.presented);
    // The worker's reply ends its task here; the page draws the result in the next ones.
    await new Promise((resolve) => setTimeout(resolve, 0));
    return { kind: 'result', output, drawnFrom: 'cells' };
  }

  private async ask(id: number, request: OpenRequest, progress: (line: string, fraction: number) => void) {
    const worker = (this.worker ??= this.createWorker());
    let answer: Extract<FromOpenWorker, { type: 'opened' | 'error' }> | null = null;
    const message: ToOpenWorker = {
      id,
      data: request.data,
      record: request.record,
      side: request.side,
      name: request.name,
      highlightScutoids: request.highlightScutoids,
    };
    await requestWorker<FromOpenWorker>({
      worker,
      id,
      message,
      isLatest: () => id === this.latest,
      superseded: () => new Error('superseded by a newer file'),
      crashed: (details) => new Error(`${request.name}: the worker opening it stopped (${details})`),
      onCrash: () => {
        if (this.worker === worker) this.worker = null;
      },
      handle: (data, finish) => {
        if (data.type === 'progress') progress(data.line, data.fraction);
        else {
          answer = data;
          finish.done();
        }
      },
    });
    return answer!;
  }
}
