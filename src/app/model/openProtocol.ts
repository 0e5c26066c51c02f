/**
 * Messages between the page and the worker that opens a result with its cells side file
 * (openWorker.ts, openClient.ts; issue 27), and then holds it for the pictures of another
 * scutoid highlight and for the exports built from its cells.
 */
import type { CellsFileRecord, ResultCellTables } from '../../run/cellTables';
import type { ViewState } from './project';
import type { LabelImage, SheetResult } from '../../run';
import type { ExportRequest } from './exportFiles';

export type ToOpenWorker = OpenMessage | OpenJsonMessage | HoldMessage | PicturesMessage | ExportMessage;

/**
 * A large result the page made itself (a run of over 20,000 cells, its records lazy over
 * columns): held from now on as if opened by this message's id, for its pictures and exports.
 */
interface HoldMessage {
  readonly type: 'hold';
  readonly id: number;
  /** The result without its cell lists, and its columns. */
  readonly result: SheetResult;
  readonly tables: ResultCellTables;
  readonly labelImages: LabelImage[];
}

/** A large project or result JSON with its cells inline, read and parsed in the worker. */
export interface OpenJsonMessage {
  readonly type: 'open-json';
  readonly id: number;
  readonly file: Blob;
  readonly name: string;
  /** The pictures' scutoid stripes (a project's own view state wins). */
  readonly highlightScutoids: boolean;
}

export interface OpenMessage {
  readonly type: 'open';
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

/** Requests about the result opened by request `opened` (refused when the worker holds another). */
interface HeldMessage {
  readonly id: number;
  readonly opened: number;
}

/** The pictures of the held result with these scutoid stripes (no picked cell: an overlay). */
export interface PicturesMessage extends HeldMessage {
  readonly type: 'pictures';
  readonly highlightScutoids: boolean;
}

/** An export of the held result as the page shows it (`shown`: its result without cell lists). */
export interface ExportMessage extends HeldMessage {
  readonly type: 'export';
  readonly shown: SheetResult;
  readonly request: ExportRequest;
}

export type FromOpenWorker =
  | { readonly type: 'progress'; readonly id: number; readonly line: string; readonly fraction: number }
  | {
      readonly type: 'opened';
      readonly id: number;
      /** "result" (drawn from its cells), "result-rerun" (a closed surface: run again) or "project". */
      readonly kind: 'result' | 'result-rerun' | 'project';
      /** The checked result without its cell lists (null), which `bytes` or `tables` hold as columns. */
      readonly result: unknown;
      /** The side file's bytes (transferred back: the page makes the records from them). */
      readonly bytes?: ArrayBuffer;
      /** Or the columns of a JSON's records (run/recordTables.ts), transferred. */
      readonly tables?: ResultCellTables;
      /** Or, where those would not round-trip exactly, the records themselves (cloned). */
      readonly records?: SheetResult;
      /** A project's view state and other sections. */
      readonly view?: ViewState;
      readonly sections?: unknown;
      /** Label images, one per surface (kind "result"). */
      readonly labelImages: LabelImage[];
      /** The pictures (view/workerPictures.ts), for rememberPictures. */
      readonly presented: unknown;
    }
  | { readonly type: 'pictures'; readonly id: number; readonly presented: unknown }
  /** The export's file (a Blob: passed by reference, never copied on the page's thread). */
  | { readonly type: 'exported'; readonly id: number; readonly file: Blob }
  | { readonly type: 'error'; readonly id: number; readonly message: string };
