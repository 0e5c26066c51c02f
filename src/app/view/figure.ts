/**
 * A figure PNG at a chosen resolution: width in mm and dots per inch give the pixel size, the
 * PNG's pHYs chunk records the DPI and tEXt chunks the provenance. Planes and tubes: the unrolled
 * surfaces as exact polygons with legend and a µm scale bar (the SVG export, rasterized). Closed
 * surfaces cannot be unrolled: the 3D view rendered at that size with the legend under it and no
 * scale bar (a perspective view has no single scale; the Description says so).
 */
import { provenanceText } from '../model/cellRows';
import { withPngDpi, withPngText } from '../model/pngText';
import { unrolledSvg } from '../model/svg';
import { SIDE_COLORS, SIDE_LABELS } from '../../view/sideColors';
import type { SheetView3D } from '../../view/sheetView3d';
import type { ViewStack } from '../../view/stack';

export interface FigureOptions {
  dpi: number;
  widthMm: number;
}

/** Longest side allowed, px: bounds the canvas before it is allocated. */
const MAX_FIGURE_PIXELS = 8192;

export function figureSize(options: FigureOptions, aspect: number): { width: number; height: number } {
  const { dpi, widthMm } = options;
  if (!(dpi >= 72 && dpi <= 1200)) throw new Error(`Figure DPI ${dpi}: choose 72 to 1200.`);
  if (!(widthMm >= 20 && widthMm <= 500)) throw new Error(`Figure width ${widthMm} mm: choose 20 to 500 mm.`);
  const width = Math.round((widthMm / 25.4) * dpi);
  const height = Math.round(width / aspect);
  if (Math.max(width, height) > MAX_FIGURE_PIXELS) {
    throw new Error(`Figure of ${width} x ${height} px: over ${MAX_FIGURE_PIXELS} px; lower the DPI or the width.`);
  }
  return { width, height };
}

export async function figurePng(stack: ViewStack, view: SheetView3D | null, options: FigureOptions): Promise<Uint8Array> {
  const canvas = stack.closed ? closedFigure(view, options) : await unrolledFigure(stack, options);
  const blob = await new Promise<Blob>((resolve, reject) =>
    canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('the figure could not be encoded'))), 'image/png'),
  );
  const png = new Uint8Array(await blob.arrayBuffer());
  const what = stack.closed
    ? `3D view of a tissue-sheet result at ${options.dpi} dpi (perspective: no scale bar)`
    : `unrolled surfaces of a tissue-sheet result at ${options.dpi} dpi, exact cells, scale bar in µm`;
  return withPngText(withPngDpi(png, options.dpi), provenanceText(stack, what));
}

async function unrolledFigure(stack: ViewStack, options: FigureOptions): Promise<HTMLCanvasElement> {
  return rasterizeSvg(unrolledSvg(stack, { widthMm: options.widthMm }), options);
}

/** An SVG drawn on a white canvas of the size `options` give (width in mm at dpi, the SVG's aspect). */
async function rasterizeSvg(svg: string, options: FigureOptions): Promise<HTMLCanvasElement> {
  const box = /viewBox="([^"]+)"/.exec(svg)![1].split(' ').map(Number);
  const { width, height } = figureSize(options, box[2] / box[3]);
  const url = URL.createObjectURL(new Blob([svg], { type: 'image/svg+xml' }));
  try {
    const image = new Image(width, height);
    image.src = url;
    await image.decode();
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    const context = canvas.getContext('2d')!;
    context.fillStyle = '#ffffff';
    context.fillRect(0, 0, width, height);
    context.drawImage(image, 0, 0, width, height);
    return canvas;
  } finally {
    URL.revokeObjectURL(url);
  }
}

/** A chart's SVG as a PNG at the chosen DPI and width: pHYs records the DPI, tEXt the provenance. */
export async function svgPng(svg: string, options: FigureOptions, text: [string, string][]): Promise<Uint8Array> {
  const canvas = await rasterizeSvg(svg, options);
  const blob = await new Promise<Blob>((resolve, reject) =>
    canvas.toBlob((b) => (b ? resolve(b) : reject(new Error('the figure could not be encoded'))), 'image/png'),
  );
  return withPngText(withPngDpi(new Uint8Array(await blob.arrayBuffer()), options.dpi), text);
}

function closedFigure(view: SheetView3D | null, options: FigureOptions): HTMLCanvasElement {
  if (!view) throw new Error('There is no 3D view to save: this browser does not provide WebGL.');
  const { width } = figureSize(options, 1);
  const viewHeight = Math.round(width * 0.75);
  const legendHeight = Math.round(width * 0.08);
  figureSize(options, width / (viewHeight + legendHeight));
  const picture = view.renderAt(width, viewHeight);
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = viewHeight + legendHeight;
  const context = canvas.getContext('2d')!;
  context.fillStyle = '#ffffff';
  context.fillRect(0, 0, canvas.width, canvas.height);
  context.drawImage(picture, 0, 0);
  const font = legendHeight / 3;
  context.font = `${font}px sans-serif`;
  context.textBaseline = 'middle';
  const items: [string, string][] = [...SIDE_LABELS.map((label, k) => [SIDE_COLORS[k], `${label}`] as [string, string]), ['#141414', 'scutoid (striped)']];
  const step = width / (items.length + 1.5);
  items.forEach(([color, text], k) => {
    const x = font + k * step;
    const y = viewHeight + legendHeight / 2;
    context.fillStyle = color;
    context.fillRect(x, y - font / 2, font, font);
    context.fillStyle = '#000';
    context.fillText(text, x + font * 1.3, y);
  });
  return canvas;
}
