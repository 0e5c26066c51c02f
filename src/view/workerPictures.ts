/**
 * The views' pictures of a result drawn in the pipeline's worker (src/view/viewWorker.ts), so the
 * page's main thread does not draw them after every result: on planes and tubes the exact cells
 * of every surface (exactCells.ts) for the 3D view's textures and for the unrolled diagrams, on
 * closed surfaces, in drafts (a slider being dragged) and above MAX_POLYGON_CELLS cells the painted label
 * images (paintSurface). Drawn on
 * software canvases there (an accelerated canvas would rasterize in the GPU process, which also
 * draws the page's frames) and sent as transferred ImageBitmaps / RGBA bytes.
 *
 * In the worker `drawPictures` draws them; on the page `rememberPictures` keeps them beside the
 * result's label images, and `workerPicture` / `workerRgba` hand them to the views when they were
 * drawn with the same options (highlight, picked cell), else the views draw as before.
 */
import type { LabelImage, SheetOutput } from '../run';
import { drawExactCells, drawnByTexels, exactScale } from './exactCells';
import { flipRows, paintSurface } from './sideColors';
import { viewStack, type ViewSurface } from './stack';

/** How each view draws a planar surface's exact cells (the one place these options live). */
export const PICTURE_LAYOUT = {
  /** The 3D view's texture: canvas row 0 is y = 0. */
  texture: (surface: ViewSurface) => ({ scale: exactScale(surface), flipY: false }),
  /** The unrolled diagram: y = 0 at the bottom. */
  unrolled: (surface: ViewSurface) => ({ scale: exactScale(surface, 2), flipY: true }),
} as const;
export type PictureKind = keyof typeof PICTURE_LAYOUT;

/** What the page asks the worker to draw with (the run's `present` options). */
export interface PictureRequest {
  readonly highlightScutoids: boolean;
  /** Picked cell, -1: none. */
  readonly selected: number;
  /**
   * Draft pictures for a result shown during a drag: the label images painted (paintSurface, one
   * pixel per texel, plain CPU work, 16 times fewer pixels than the 3D view's full texture), so
   * a picture follows the slider on a software GPU; the drag's last value is drawn again in full
   * when it ends.
   */
  readonly draft?: boolean;
}

/** The worker's pictures of one result, per surface in stack order. */
interface Pictures extends PictureRequest {
  readonly texture: (ImageBitmap | null)[];
  readonly unrolled: (ImageBitmap | null)[];
  readonly rgba: (Uint8ClampedArray | null)[];
}

export function isPictureRequest(value: unknown): value is PictureRequest {
  const v = value as PictureRequest | null;
  return typeof v === 'object' && v !== null && typeof v.highlightScutoids === 'boolean' && typeof v.selected === 'number';
}

/** In the worker: every picture of `output` the views would draw; buffers to transfer. */
export function drawPictures(output: SheetOutput, request: PictureRequest): { presented: Pictures; transfer: Transferable[] } {
  const stack = viewStack(output);
  const options = { highlightScutoids: request.highlightScutoids, valid: stack.valid, scutoid: stack.scutoid, selected: request.selected };
  const draw = (surface: ViewSurface, kind: PictureKind): ImageBitmap => {
    const canvas = new OffscreenCanvas(1, 1);
    // A software canvas: rasterized here, on the worker's thread.
    canvas.getContext('2d', { willReadFrequently: true });
    drawExactCells(canvas, surface, { ...options, ...PICTURE_LAYOUT[kind](surface) });
    return canvas.transferToImageBitmap();
  };
  // Exact polygons on planes and tubes, unless a draft or too many cells (exactCells.ts, MAX_POLYGON_CELLS).
  const byPolygons = (s: ViewSurface) => !stack.closed && !request.draft && !drawnByTexels(s);
  const texture = stack.surfaces.map((s) => (byPolygons(s) ? draw(s, 'texture') : null));
  const rgba = stack.surfaces.map((s) => (byPolygons(s) ? null : paintSurface(s, options)));
  // Very many cells (not a draft): the unrolled picture too, flipped here, so the page only copies it.
  const unrolled = stack.surfaces.map((s, k) =>
    byPolygons(s) ? draw(s, 'unrolled') : !stack.closed && !request.draft ? flippedBitmap(rgba[k]!, s.image.grid.width, s.image.grid.height) : null,
  );
  const transfer: Transferable[] = [];
  for (const bitmap of [...texture, ...unrolled]) if (bitmap) transfer.push(bitmap);
  for (const bytes of rgba) if (bytes) transfer.push(bytes.buffer as ArrayBuffer);
  return { presented: { ...request, texture, unrolled, rgba }, transfer };
}

/** An ImageBitmap of `rgba` (row 0 = y 0) with y = 0 at the bottom (the unrolled view). */
function flippedBitmap(rgba: Uint8ClampedArray, width: number, height: number): ImageBitmap {
  const canvas = new OffscreenCanvas(width, height);
  canvas.getContext('2d', { willReadFrequently: true })!.putImageData(new ImageData(flipRows(rgba, width, height), width, height), 0, 0);
  return canvas.transferToImageBitmap();
}

interface Kept extends PictureRequest {
  texture: ImageBitmap | null;
  unrolled: ImageBitmap | null;
  rgba: Uint8ClampedArray | null;
}
const kept = new WeakMap<LabelImage, Kept>();

/** On the page: keeps the worker's pictures of `output` for the views. */
export function rememberPictures(output: SheetOutput, presented: unknown): void {
  const pictures = presented as Pictures | undefined;
  if (!isPictureRequest(pictures) || !Array.isArray(pictures.texture)) return;
  output.labelImages.forEach((image, k) =>
    kept.set(image, {
      highlightScutoids: pictures.highlightScutoids,
      selected: pictures.selected,
      texture: pictures.texture[k] ?? null,
      unrolled: pictures.unrolled[k] ?? null,
      rgba: pictures.rgba[k] ?? null,
    }),
  );
}

function matching(surface: ViewSurface, options: { highlightScutoids?: boolean; selected?: number }): Kept | null {
  const known = kept.get(surface.image);
  if (!known || known.highlightScutoids !== (options.highlightScutoids ?? true) || known.selected !== (options.selected ?? -1)) return null;
  return known;
}

/**
 * The worker's picture of `surface` for view `kind`, when drawn with these options: its exact
 * cells (an ImageBitmap), or in a draft its painted label image (ImageData; the unrolled one
 * flipped, y = 0 at the bottom).
 */
export function workerPicture(
  surface: ViewSurface,
  kind: PictureKind,
  options: { highlightScutoids?: boolean; selected?: number },
): ImageBitmap | ImageData | null {
  const known = matching(surface, options);
  const bitmap = known?.[kind] ?? null;
  if (bitmap && bitmap.width > 0) return bitmap;
  const rgba = known ? workerRgba(surface, options) : null;
  if (!rgba) return null;
  const { width, height } = surface.image.grid;
  return new ImageData(kind === 'unrolled' ? flipRows(rgba, width, height) : new Uint8ClampedArray(rgba), width, height);
}

/** The worker's paintSurface bytes of `surface` (closed surfaces, drafts), when painted with these options. */
export function workerRgba(surface: ViewSurface, options: { highlightScutoids?: boolean; selected?: number }): Uint8ClampedArray | null {
  const rgba = matching(surface, options)?.rgba ?? null;
  const { width, height } = surface.image.grid;
  return rgba && rgba.length === width * height * 4 ? rgba : null;
}
