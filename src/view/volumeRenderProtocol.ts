/** Messages between the page and the worker that draws a measured volume (volumeRenderWorker.ts, app/view/volumeView.ts). */
import type { DrawnCell, Orbit, RowName, VolumeLayout } from './volumeRenderer';
import type { CellShape, DrawnSurface } from './volumeSurfaces';

export type ToVolumeRenderer =
  | { readonly type: 'init'; readonly canvas: OffscreenCanvas; readonly width: number; readonly height: number }
  | { readonly type: 'size'; readonly width: number; readonly height: number }
  | { readonly type: 'show'; readonly cells: DrawnCell[]; readonly surfaces: DrawnSurface[]; readonly stripe: number }
  /** The model of the same geometry (after `show`; a new `show` removes it). */
  | { readonly type: 'model'; readonly cells: DrawnCell[]; readonly surfaces: DrawnSurface[]; readonly stripe: number }
  | { readonly type: 'layout'; readonly layout: VolumeLayout }
  | { readonly type: 'orbit'; readonly orbit: Orbit }
  | { readonly type: 'select'; readonly row: RowName; readonly cell: number }
  | { readonly type: 'shape'; readonly shape: CellShape | null }
  | { readonly type: 'pick'; readonly request: number; readonly x: number; readonly y: number }
  /** The views as shown (one or both rows) as a PNG, drawn afresh. */
  | { readonly type: 'png'; readonly request: number };

export type FromVolumeRenderer =
  | { readonly type: 'shown'; readonly orbit: Orbit }
  /** The model drawn: distinct cells on its basal and apical surfaces. */
  | { readonly type: 'modelShown'; readonly cells: number[] }
  | { readonly type: 'picked'; readonly request: number; readonly hit: { readonly row: RowName; readonly cell: number; readonly surface: number } | null }
  | { readonly type: 'png'; readonly request: number; readonly png: Blob }
  /** After each frame drawn (tests and the page wait for it). */
  | { readonly type: 'drawn'; readonly frame: number }
  | { readonly type: 'error'; readonly message: string };
