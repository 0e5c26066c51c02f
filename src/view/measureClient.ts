/**
 * The page's side of the measuring worker (measureWorker.ts): reads the chosen files (File ->
 * ArrayBuffer, asynchronously), hands them to the worker, and reports progress, the measured
 * result with its pictures, then the model comparison. A newer request supersedes an older one
 * (its late messages are ignored).
 */
import type { MeasuredResult, ModelComparison } from '../core/measure';
import type { LayerPicture } from './measurePicture';
import type { FromMeasureWorker, MeasureRequestOptions, ToMeasureWorker } from './measureProtocol';
import { requestWorker } from './workerRequest';

/** Largest file read (as the CLI): 1 GiB. */
const MAX_MEASURE_FILE_BYTES = 2 ** 30;

/** A problem with one input file: shown as "FILE: problem". */
export class MeasureFileError extends Error {
  constructor(
    readonly file: string | null,
    message: string,
  ) {
    super(message);
    this.name = 'MeasureFileError';
  }
}

/**
 * A chosen file's bytes, checked for size first. The browser refuses to read a dropped folder
 * or a file moved or deleted since it was chosen (a NotFoundError naming no file): said as that
 * file's problem.
 */
export async function readChosenFile(file: File): Promise<ArrayBuffer> {
  if (file.size > MAX_MEASURE_FILE_BYTES) throw new MeasureFileError(file.name, `${file.name}: ${file.size} bytes is over the limit of 1 GiB per file`);
  try {
    return await file.arrayBuffer();
  } catch {
    throw new MeasureFileError(file.name, `${file.name}: could not be read (a folder, or a file moved or deleted since it was chosen); choose the file again`);
  }
}

export interface MeasureCallbacks {
  onProgress?(line: string): void;
  /** The measured tissue (the comparison follows in onCompared when asked for). */
  onMeasured?(result: MeasuredResult, pictures: LayerPicture[]): void;
  onCompared?(comparison: ModelComparison | null, note: string | null): void;
}

export class MeasureClient {
  private worker: Worker | null = null;
  private latest = 0;

  constructor(private readonly createWorker: () => Worker = () => new Worker(new URL('./measureWorker.ts', import.meta.url), { type: 'module' })) {}

  /**
   * Measures `files` (basal first). Resolves once the result (and the comparison, when asked)
   * has been delivered; rejects with MeasureFileError for a bad file, or when superseded.
   */
  async measure(files: readonly File[], options: MeasureRequestOptions, callbacks: MeasureCallbacks = {}): Promise<void> {
    const id = ++this.latest;
    const buffers = await Promise.all(files.map(readChosenFile));
    if (id !== this.latest) throw new MeasureFileError(null, 'superseded by a newer measurement');
    const message: ToMeasureWorker = { type: 'measure', id, files: files.map((f, k) => ({ name: f.name, bytes: buffers[k] })), options };
    const worker = this.start();
    return requestWorker<FromMeasureWorker>({
      worker,
      id,
      message,
      transfer: buffers,
      isLatest: () => id === this.latest,
      superseded: () => new MeasureFileError(null, 'superseded by a newer measurement'),
      crashed: (details) => new MeasureFileError(null, `the measuring worker stopped (${details})`),
      onCrash: () => {
        if (this.worker === worker) this.worker = null;
      },
      handle: (data, finish) => {
        if (data.type === 'progress') callbacks.onProgress?.(data.line);
        else if (data.type === 'measured') {
          callbacks.onMeasured?.(data.result, data.pictures);
          if (options.realizations <= 0) finish.done();
        } else if (data.type === 'compared') {
          callbacks.onCompared?.(data.comparison, data.note);
          finish.done();
        } else finish.fail(new MeasureFileError(data.file, data.message));
      },
    });
  }

  private start(): Worker {
    this.worker ??= this.createWorker();
    return this.worker;
  }
}
