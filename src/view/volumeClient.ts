/**
 * The page's side of the volume-measuring worker (volumeWorker.ts): reads the chosen file
 * (File -> ArrayBuffer, asynchronously), hands it to the worker, reports progress, the measured
 * volume with its drawn surfaces, then the model (and its drawing); asks for a picked cell's 3D shape. A newer
 * measurement supersedes an older one (its late messages are ignored).
 */
import type { VolumeComparison, VolumeMeasuredResult, VolumeModelDrawing } from '../core/measure';
import { MeasureFileError, readChosenFile } from './measureClient';
import type { FromVolumeWorker, ToVolumeWorker, VolumeRequestOptions } from './volumeProtocol';
import type { CellShape, DrawnSurface } from './volumeSurfaces';
import { requestWorker } from './workerRequest';

export interface VolumeCallbacks {
  onProgress?(line: string): void;
  onMeasured?(result: VolumeMeasuredResult, surfaces: DrawnSurface[]): void;
  /** The model (or null and why), and its first realization to draw (or null and why). */
  onCompared?(comparison: VolumeComparison | null, note: string, drawing: VolumeModelDrawing | null, drawingNote: string): void;
}

export class VolumeClient {
  private worker: Worker | null = null;
  private latest = 0;

  constructor(private readonly createWorker: () => Worker = () => new Worker(new URL('./volumeWorker.ts', import.meta.url), { type: 'module' })) {}

  /** Measures one 3D TIFF; resolves once the result (and the model, when asked) has been delivered. */
  async measure(file: File, options: VolumeRequestOptions, callbacks: VolumeCallbacks = {}): Promise<void> {
    const id = ++this.latest;
    const bytes = await readChosenFile(file);
    if (id !== this.latest) throw new MeasureFileError(null, 'superseded by a newer measurement');
    const message: ToVolumeWorker = { type: 'measure', id, file: { name: file.name, bytes }, options };
    return this.exchange(id, message, [bytes], (data, done) => {
      if (data.type === 'progress') callbacks.onProgress?.(data.line);
      else if (data.type === 'measured') {
        callbacks.onMeasured?.(data.result, data.surfaces);
        if (options.realizations <= 0 && !options.saved) done();
      } else if (data.type === 'compared') {
        callbacks.onCompared?.(data.comparison, data.note, data.drawing, data.drawingNote);
        done();
      }
    });
  }

  /** The 3D shape of a cell (0-based id) of the volume measured last. */
  async cellShape(cell: number): Promise<CellShape> {
    const id = ++this.latest;
    let shape: CellShape | null = null;
    await this.exchange(id, { type: 'cell', id, cell }, [], (data, done) => {
      if (data.type === 'cell') {
        shape = data.shape;
        done();
      }
    });
    return shape!;
  }

  private exchange(
    id: number,
    message: ToVolumeWorker,
    transfer: Transferable[],
    handle: (data: Exclude<FromVolumeWorker, { type: 'error' }>, done: () => void) => void,
  ): Promise<void> {
    const worker = (this.worker ??= this.createWorker());
    return requestWorker<FromVolumeWorker>({
      worker,
      id,
      message,
      transfer,
      isLatest: () => id === this.latest,
      superseded: () => new MeasureFileError(null, 'superseded by a newer measurement'),
      crashed: (details) => new MeasureFileError(null, `the volume-measuring worker stopped (${details})`),
      onCrash: () => {
        if (this.worker === worker) this.worker = null;
      },
      handle: (data, finish) => {
        if (data.type === 'error') finish.fail(new MeasureFileError(data.file, data.message));
        else handle(data, finish.done);
      },
    });
  }
}
