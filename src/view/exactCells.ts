/**
 * Planes and tubes drawn from their exact cells (cellPolygons.ts) instead of texels: each cell's
 * polygon filled with its side colour on a 2D canvas at a chosen scale, border cells faded,
 * scutoids striped, a picked cell white, borders as dark lines. Smooth at any zoom up to the
 * canvas size; used for the 3D view's textures and the unrolled canvases.
 * Canvas row 0 is y = 0 unless `flipY` (the unrolled view puts y = 0 at the bottom).
 */
import { surfacePolygons } from './cellPolygons';
import { SELECTED_RGB, SIDE_COLORS, sideColorIndex, type PaintOptions } from './sideColors';
import type { ViewSurface } from './stack';

/** Texture side limit: large enough for smooth borders, small enough for software GPUs. */
const MAX_SIDE = 2048;

/**
 * Above this many cells the pictures drawn on the page (an opened result, which the worker did
 * not draw) are the painted label image, one pixel per texel (paintSurface), not the cells'
 * polygons: 100,000 filled and stroked polygons took the main thread ~10 s on a software
 * renderer (issue 27), and at that count a cell is a few pixels of the picture anyway.
 */
const MAX_POLYGON_CELLS = 20_000;

/** Whether the page draws `surface` by its texels (see MAX_POLYGON_CELLS). */
export function drawnByTexels(surface: ViewSurface): boolean {
  return surface.cells.length > MAX_POLYGON_CELLS;
}

/** Pixels per texel for a surface's exact drawing (at least 1, at most MAX_SIDE on a side). */
export function exactScale(surface: ViewSurface, target = 4): number {
  const { width, height } = surface.image.grid;
  return Math.max(1, Math.min(target, MAX_SIDE / Math.max(width, height)));
}

export function drawExactCells(
  canvas: HTMLCanvasElement | OffscreenCanvas,
  surface: ViewSurface,
  options: PaintOptions & { scale: number; flipY?: boolean },
): void {
  const { grid } = surface.image;
  const { scale } = options;
  canvas.width = Math.round(grid.width * scale);
  canvas.height = Math.round(grid.height * scale);
  const context = canvas.getContext('2d') as CanvasRenderingContext2D | null;
  if (!context) throw new Error('no 2D canvas context to draw the cells');
  context.fillStyle = '#282828';
  context.fillRect(0, 0, canvas.width, canvas.height);
  const h = canvas.height;
  const stripe = Math.max(4, Math.round(Math.min(grid.width, grid.height) / 24)) * scale;
  const hatch = stripePattern(context, stripe);
  const shifts = grid.periodicX ? [-grid.width, 0, grid.width] : [0];
  context.lineJoin = 'round';
  context.lineWidth = Math.max(1, scale * 0.6);
  context.strokeStyle = 'rgba(20,20,20,0.9)';
  for (const cell of surfacePolygons(surface).cells) {
    const p = cell.polygon;
    if (p.length < 6) continue;
    const id = cell.id;
    const selected = id === options.selected;
    const faded = options.valid && !options.valid[id];
    const base = selected ? `rgb(${SELECTED_RGB.join(',')})` : SIDE_COLORS[sideColorIndex(surface.sides[id] ?? 0)];
    for (const shift of shifts) {
      context.beginPath();
      for (let k = 0; k < p.length; k += 2) {
        const x = (p[k] + shift) * scale;
        const y = options.flipY ? h - p[k + 1] * scale : p[k + 1] * scale;
        if (k === 0) context.moveTo(x, y);
        else context.lineTo(x, y);
      }
      context.closePath();
      context.fillStyle = base;
      context.fill();
      if (faded && !selected) {
        context.fillStyle = 'rgba(235,235,235,0.67)';
        context.fill();
      }
      if ((options.highlightScutoids ?? true) && options.scutoid?.[id] && !selected && hatch) {
        context.fillStyle = hatch;
        context.fill();
      }
      context.stroke();
    }
  }
}

/** Diagonal dark stripes (one per `period` px) over a transparent background. */
function stripePattern(context: CanvasRenderingContext2D, period: number): CanvasPattern | null {
  const size = Math.max(4, Math.round(period));
  const tile = new OffscreenCanvas(size, size);
  const t = tile.getContext('2d');
  if (!t) return null;
  t.strokeStyle = '#141414';
  t.lineWidth = Math.max(1, size / 5);
  t.beginPath();
  for (const o of [-size, 0, size]) {
    t.moveTo(o, size);
    t.lineTo(o + size, 0);
  }
  t.stroke();
  return context.createPattern(tile, 'repeat');
}
