/**
 * Messages between the page and the worker that opens a result with its cells side file
 * (openWorker.ts, openClient.ts; issue 27).
 */
import type { CellsFileRecord } from '../../run/cellTables';
import type { LabelImage } from '../../run';

export interface ToOpenWorker {
  readonly id: number;
  /** The result JSON, parsed (small: its cell lists are null). */
  readonly data: unknown;
  readonly record: CellsFileRecord;
  /** The side file, read in the worker. */
  readonly side: Blob;
  /** Names for messages: "RESULT.json". */
  readonly name: string;
  /** The pictures' scutoid stripes. */
  readonly highlightScutoids: boolean;
}

export type FromOpenWorker =
  | { readonly type: 'progress'; readonly id: number; readonly line: string; readonly fraction: number }
  | {
      readonly type: 'opened';
      readonly id: number;
      /** "result" (drawn from its cells) or "result-rerun" (a closed surface: run again). */
      readonly kind: 'result' | 'result-rerun';
      /** The checked result without its cell lists (null), which `bytes` holds as columns. */
      readonly result: unknown;
      /** The side file's bytes (transferred back: the page makes the records from them). */
      readonly bytes: ArrayBuffer;
      /** Label images, one per surface (kind "result"). */
      readonly labelImages: LabelImage[];
      /** The pictures (view/workerPictures.ts), for rememberPictures. */
      readonly presented: unknown;
    }
  | { readonly type: 'error'; readonly id: number; readonly message: string };
