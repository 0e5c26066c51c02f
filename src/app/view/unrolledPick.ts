/**
 * The picked cell on the unrolled diagrams of a plane or tube (issue 27): its exact outline
 * (view/cellOutline.ts) drawn white, with its border, over the canvas's picture in a small patch,
 * and the patch put back when the pick changes, so a pick costs the cell's area in pixels
 * whatever the cell count (repainting every picture took seconds at 100,000 cells).
 */
import { cellOutline, outlineCells, polygonBounds } from '../../view/cellOutline';
import { SELECTED_RGB } from '../../view/sideColors';
import type { ViewSurface } from '../../view/stack';

interface Patch {
  x: number;
  y: number;
  pixels: ImageData;
}
/** The pixels under each canvas's drawn outline, to put back. */
const patches = new WeakMap<HTMLCanvasElement, Patch[]>();

/** Pixel rectangles (x, y, w, h) the outline covers on a canvas, one per periodic copy drawn. */
function patchRects(
  polygon: ArrayLike<number>,
  grid: { width: number; height: number; periodicX: boolean },
  canvas: { width: number; height: number },
  margin: number,
): { shift: number; rect: [number, number, number, number] }[] {
  if (polygon.length < 6) return [];
  const sx = canvas.width / grid.width;
  const sy = canvas.height / grid.height;
  const [minX, minY, maxX, maxY] = polygonBounds(polygon);
  const out: { shift: number; rect: [number, number, number, number] }[] = [];
  for (const shift of grid.periodicX ? [-grid.width, 0, grid.width] : [0]) {
    // Row 0 of the canvas is the top: y = 0 at the bottom.
    const x0 = Math.max(0, Math.floor((minX + shift) * sx - margin));
    const x1 = Math.min(canvas.width, Math.ceil((maxX + shift) * sx + margin));
    const y0 = Math.max(0, Math.floor(canvas.height - maxY * sy - margin));
    const y1 = Math.min(canvas.height, Math.ceil(canvas.height - minY * sy + margin));
    if (x1 > x0 && y1 > y0) out.push({ shift, rect: [x0, y0, x1 - x0, y1 - y0] });
  }
  return out;
}

/** Puts back what the last outline on `canvas` covered. */
function clearUnrolledPick(canvas: HTMLCanvasElement): void {
  const context = canvas.getContext('2d', { willReadFrequently: true });
  for (const patch of (patches.get(canvas) ?? []).reverse()) context?.putImageData(patch.pixels, patch.x, patch.y);
  patches.delete(canvas);
}

/** Draws cell `id` (-1: none) white on `canvas`, the unrolled picture of `surface` (y = 0 at the bottom). */
export function drawUnrolledPick(canvas: HTMLCanvasElement, surface: ViewSurface, id: number): void {
  clearUnrolledPick(canvas);
  if (id < 0 || id >= surface.cells.length) return;
  const context = canvas.getContext('2d', { willReadFrequently: true });
  if (!context) return;
  const { grid } = surface.image;
  const polygon = cellOutline(grid, outlineCells(surface.cells), id);
  const sx = canvas.width / grid.width;
  const sy = canvas.height / grid.height;
  const lineWidth = Math.max(1, sx * 0.6);
  const saved: Patch[] = [];
  for (const { shift, rect } of patchRects(polygon, grid, canvas, lineWidth + 2)) {
    saved.push({ x: rect[0], y: rect[1], pixels: context.getImageData(...rect) });
    context.beginPath();
    for (let k = 0; k < polygon.length; k += 2) {
      const x = (polygon[k] + shift) * sx;
      const y = canvas.height - polygon[k + 1] * sy;
      if (k === 0) context.moveTo(x, y);
      else context.lineTo(x, y);
    }
    context.closePath();
    context.fillStyle = `rgb(${SELECTED_RGB.join(',')})`;
    context.fill();
    context.lineJoin = 'round';
    context.lineWidth = lineWidth;
    context.strokeStyle = 'rgba(20,20,20,0.9)';
    context.stroke();
  }
  patches.set(canvas, saved);
}
