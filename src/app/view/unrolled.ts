/**
 * The unrolled diagrams: one 2D canvas per surface of the stack, side by side: planes and tubes
 * as their exact cells (src/view/exactCells.ts, smooth borders), closed surfaces from the label
 * images (cells coloured by sides, scutoids striped, border cells faded). A click on a cell
 * picks it (`onPick`); the picked cell is drawn white on every surface. Widths keep the
 * surfaces' true proportions, so a tube's outer surface is drawn wider than its inner one.
 *
 * Closed surfaces cannot be unrolled: their label images are cube maps (n x 6n atlases, face f
 * in rows f n .. f n + n - 1), drawn as a strip of the six faces +X, -X, +Y, -Y, +Z, -Z (each
 * face as stored: i to the right, j down), one strip per surface.
 */
import { FACE_NAMES } from '../../core/cubemap/cubemap';
import { drawExactCells, drawnByTexels } from '../../view/exactCells';
import { PICTURE_LAYOUT, workerPicture, workerRgba } from '../../view/workerPictures';
import { flipRows, paintSurface } from '../../view/sideColors';
import type { ViewStack, ViewSurface } from '../../view/stack';
import { drawUnrolledPick } from './unrolledPick';

export interface UnrolledOptions {
  /** Picked cell (-1: none). */
  selected?: number;
  onPick?(surface: number, cell: number): void;
}

export function drawUnrolled(container: HTMLElement, stack: ViewStack, highlightScutoids: boolean, options: UnrolledOptions = {}): void {
  container.replaceChildren();
  container.classList.toggle('closed', stack.closed);
  if (stack.closed) {
    const note = document.createElement('p');
    note.id = 'unrolled-note';
    note.className = 'small';
    note.textContent = `A closed surface cannot be unrolled: each surface is shown as its cube-map label image, the six faces ${FACE_NAMES.join(', ')} side by side (GL cube-map order and orientation).`;
    container.append(note);
  }
  for (const surface of stack.surfaces) {
    const { width, height } = surface.image.grid;
    const figure = document.createElement('figure');
    figure.className = stack.closed ? 'unrolled cube' : 'unrolled';
    const canvas = document.createElement('canvas');
    canvas.dataset.surface = surface.name;
    canvas.setAttribute('role', 'img');
    // A software canvas: pictures are copied in, never drawn, and an accelerated canvas's
    // uploads took the (software) GPU process ~90 ms per result, delaying the page's frames.
    const context = () => canvas.getContext('2d', { willReadFrequently: true });
    // Planes and tubes: the picked cell is a patch over the picture (unrolledPick.ts).
    const paint = { highlightScutoids, valid: stack.valid, scutoid: stack.scutoid, selected: stack.closed ? (options.selected ?? -1) : -1 };
    if (stack.closed) {
      const rgba = workerRgba(surface, paint) ?? paintSurface(surface, paint);
      const n = width;
      canvas.width = 6 * n;
      canvas.height = n;
      canvas.setAttribute('aria-label', `cube-map labels of the ${surface.name} surface, 6 faces of ${n} x ${n} texels`);
      context()?.putImageData(new ImageData(cubeStrip(rgba, n), 6 * n, n), 0, 0);
    } else {
      // Drawn in the pipeline's worker when it could (workerPictures.ts).
      // Very many cells: the painted label image (exactCells.ts, MAX_POLYGON_CELLS), y = 0 at the bottom.
      const picture =
        workerPicture(surface, 'unrolled', paint) ??
        (drawnByTexels(surface) ? new ImageData(flipRows(paintSurface(surface, paint), width, height), width, height) : null);
      if (picture) {
        canvas.width = picture.width;
        canvas.height = picture.height;
        if (picture instanceof ImageData) context()?.putImageData(picture, 0, 0);
        else context()?.drawImage(picture, 0, 0);
      } else drawExactCells(canvas, surface, { ...paint, ...PICTURE_LAYOUT.unrolled(surface) });
      canvas.setAttribute('aria-label', `unrolled ${surface.name} surface, exact cells, ${width} x ${height} texels`);
      drawUnrolledPick(canvas, surface, options.selected ?? -1);
    }
    canvas.addEventListener('click', (event) => {
      const cell = cellAt(canvas, surface, stack.closed, event);
      if (cell >= 0) options.onPick?.(surface.index, cell);
    });
    const caption = document.createElement('figcaption');
    caption.textContent = captionOf(surface, stack.closed);
    figure.append(canvas, caption);
    container.append(figure);
  }
}

/**
 * Shows cell `id` (-1: none) picked on the unrolled planes or tubes of `stack` drawn in
 * `container`, without redrawing their pictures; false for closed surfaces (redraw them).
 */
export function pickUnrolled(container: HTMLElement, stack: ViewStack, id: number): boolean {
  if (stack.closed) return false;
  const canvases = container.querySelectorAll<HTMLCanvasElement>('figure.unrolled canvas');
  if (canvases.length !== stack.surfaces.length) return false;
  canvases.forEach((canvas, k) => drawUnrolledPick(canvas, stack.surfaces[k], id));
  return true;
}

/** The cell under a click on a surface's canvas (its label image's texel), -1 for none. */
function cellAt(canvas: HTMLCanvasElement, surface: ViewSurface, closed: boolean, event: MouseEvent): number {
  const box = canvas.getBoundingClientRect();
  const fx = (event.clientX - box.left) / box.width;
  const fy = (event.clientY - box.top) / box.height;
  const { width, height } = surface.image.grid;
  if (fx < 0 || fx >= 1 || fy < 0 || fy >= 1) return -1;
  if (closed) {
    // Strip of six n x n faces: column f n + i, row j -> atlas row f n + j.
    const n = width;
    const column = Math.floor(fx * 6 * n);
    const face = Math.floor(column / n);
    const j = Math.floor(fy * n);
    return surface.image.labels[(face * n + j) * n + (column - face * n)] ?? -1;
  }
  const x = Math.floor(fx * width);
  const y = height - 1 - Math.floor(fy * height);
  return surface.image.labels[y * width + x] ?? -1;
}

function captionOf(surface: ViewSurface, closed: boolean): string {
  const offset = surface.offset !== 0 ? `, ${surface.offset.toFixed(1)} µm` : '';
  const ratio = surface.ratio !== 1 ? `, ${closed ? 'size ratio' : 'ratio'} ${surface.ratio.toFixed(2)}` : '';
  return `${surface.name}${surface.role === 'seeded' ? ' (seeded)' : ''}${offset}${ratio}`;
}

/** The n x 6n atlas (face f in rows f n ..) as a 6n x n strip (face f in columns f n ..). */
function cubeStrip(rgba: Uint8ClampedArray, n: number): Uint8ClampedArray<ArrayBuffer> {
  const out = new Uint8ClampedArray(rgba.length);
  for (let f = 0; f < 6; f++) {
    for (let j = 0; j < n; j++) {
      const from = (f * n + j) * n * 4;
      const to = (j * 6 * n + f * n) * 4;
      out.set(rgba.subarray(from, from + 4 * n), to);
    }
  }
  return out;
}
