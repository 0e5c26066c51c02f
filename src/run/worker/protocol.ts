import type { Config } from '../../core/config';
import type { GrayImage } from '../../core/density';
import type { IterationRecord } from '../../gpu/lloyd';
import type { MeshFile } from '../closedMesh';
import type { SheetOutput } from '../result';

/**
 * Messages between the page and the pipeline worker. Everything is structured-cloneable; errors
 * travel as their name, message and (for config errors) field, and are rebuilt on the page so
 * that callers see the same ConfigError, GpuCapabilityError or AbortError as on the main thread.
 */
export type ToWorker =
  | {
      readonly type: 'run';
      readonly id: number;
      readonly config: Config;
      readonly densityImage?: GrayImage;
      readonly meshFile?: MeshFile;
      /** false: send the result without label images (see RunOptions.views). */
      readonly views?: boolean;
      /** Options of the worker's Presenter (servePipeline.ts); absent: nothing presented. */
      readonly present?: unknown;
    }
  | { readonly type: 'cancel'; readonly id: number };

export interface SerializedError {
  readonly name: string;
  readonly message: string;
  readonly field?: string;
}

export type FromWorker =
  /** The worker could not create a WebGL2 context on an OffscreenCanvas: run on the page. */
  | { readonly type: 'unavailable'; readonly id: number; readonly reason: string }
  | { readonly type: 'iteration'; readonly id: number; readonly record: IterationRecord; readonly maxIterations: number }
  /** `presented`: what the worker's Presenter made of the output, when the run asked for it. */
  | { readonly type: 'result'; readonly id: number; readonly output: SheetOutput; readonly presented?: unknown }
  | { readonly type: 'error'; readonly id: number; readonly error: SerializedError };
