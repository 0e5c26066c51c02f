/**
 * Messages between the page and the volume-measuring worker (volumeWorker.ts, volumeClient.ts).
 * The file travels as a transferred ArrayBuffer; the drawn surfaces (the tissue's, the model's)
 * come back the same way.
 */
import type { VolumeComparison, VolumeMeasuredResult, VolumeModelDrawing } from '../core/measure';
import type { CellShape, DrawnSurface } from './volumeSurfaces';

export interface VolumeRequestOptions {
  /** µm along width, height and between pages; absent: from the file's metadata (else refused, asking for it). */
  readonly voxelSize?: { readonly x: number; readonly y: number; readonly z: number };
  readonly apical: 'lumen' | 'outside';
  /** µm; absent: the default of docs/measure.md. */
  readonly minContact?: number;
  /** Voxels with this label are lumen. */
  readonly lumenLabel?: number;
  readonly quartetFilter: boolean;
  /** Model realizations (the CLI's --compare --realizations); 0: no model. */
  readonly realizations: number;
  readonly seed: number;
  /** A saved comparison (a project file, with realizations 0): not re-run, its model drawn again. */
  readonly saved?: VolumeComparison;
}

export type ToVolumeWorker =
  | {
      readonly type: 'measure';
      readonly id: number;
      readonly file: { readonly name: string; readonly bytes: ArrayBuffer };
      readonly options: VolumeRequestOptions;
    }
  /** The 3D shape of cell `cell` (0-based id) of the last measured volume. */
  | { readonly type: 'cell'; readonly id: number; readonly cell: number };

export type FromVolumeWorker =
  | { readonly type: 'progress'; readonly id: number; readonly line: string }
  | { readonly type: 'measured'; readonly id: number; readonly result: VolumeMeasuredResult; readonly surfaces: DrawnSurface[] }
  /**
   * The model of the same geometry, or null with the reason there is none; and its first
   * realization to draw (typed arrays, transferred), or null with `drawingNote` saying why.
   */
  | {
      readonly type: 'compared';
      readonly id: number;
      readonly comparison: VolumeComparison | null;
      readonly note: string;
      readonly drawing: VolumeModelDrawing | null;
      readonly drawingNote: string;
    }
  | { readonly type: 'cell'; readonly id: number; readonly shape: CellShape }
  /** `file` is set for a problem with the input file (MeasureInputError). */
  | { readonly type: 'error'; readonly id: number; readonly file: string | null; readonly message: string };
