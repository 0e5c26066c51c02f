/**
 * Messages between the page and the measuring worker (measureWorker.ts, measureClient.ts).
 * Files travel as transferred ArrayBuffers; pictures come back the same way.
 */
import type { MeasuredResult, ModelComparison } from '../core/measure';
import type { LayerPicture } from './measurePicture';

export interface MeasureRequestOptions {
  /** µm per pixel; absent: from the files' metadata. */
  readonly pixelSize?: number;
  readonly periodicX: boolean;
  /** µm; absent: the default of docs/measure.md. */
  readonly minContact?: number;
  /** Compare with the Voronoi model (the CLI's --compare) over this many realizations; 0: no comparison. */
  readonly realizations: number;
  readonly seed: number;
  /** Picture pixels per side at most. */
  readonly maxPictureSide?: number;
}

export type ToMeasureWorker = {
  readonly type: 'measure';
  readonly id: number;
  readonly files: { readonly name: string; readonly bytes: ArrayBuffer }[];
  readonly options: MeasureRequestOptions;
};

export type FromMeasureWorker =
  | { readonly type: 'progress'; readonly id: number; readonly line: string }
  | { readonly type: 'measured'; readonly id: number; readonly result: MeasuredResult; readonly pictures: LayerPicture[] }
  /** The comparison, or null with the reason it was not made. */
  | { readonly type: 'compared'; readonly id: number; readonly comparison: ModelComparison | null; readonly note: string | null }
  /** `file` is set for a problem with an input file (MeasureInputError). */
  | { readonly type: 'error'; readonly id: number; readonly file: string | null; readonly message: string };
