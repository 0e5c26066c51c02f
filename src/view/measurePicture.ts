/**
 * Pictures of a measured tissue's layers (docs/measure.md, docs/app.md "Measure a tissue"),
 * drawn with the simulated surfaces' rules (sideColors.ts): each cell coloured by its number of
 * sides on that layer, boundaries dark, scutoids striped, excluded cells faded, background
 * (label 0) dark grey. Pure (no DOM): runs in the measuring worker, so the page only uploads
 * the bytes.
 *
 * Large layers are reduced first (nearest pixel, one integer step in both directions) to at most
 * `maxSide` pixels per side: the picture of an 8k x 8k layer would be 256 MB of RGBA.
 */
import type { LabelPixels, MeasuredCellRecord } from '../core/measure';
import { cellRgb, SELECTED_RGB, writePixel } from './sideColors';

/** One layer's labels at picture resolution: raw labels (0 = background), row 0 = top. */
export interface LayerLabels {
  readonly width: number;
  readonly height: number;
  /** Image pixels per picture pixel (1 = full resolution). */
  readonly step: number;
  readonly labels: Uint16Array;
}

export interface LayerPicture extends LayerLabels {
  readonly name: string;
  /** RGBA, row 0 = top (ImageData order). */
  readonly rgba: Uint8ClampedArray<ArrayBuffer>;
}

/** Picture pixels per side at most (a 1024 x 1024 picture is 4 MB of RGBA). */
const MAX_PICTURE_SIDE = 1024;

/** The labels of `pixels` reduced to at most `maxSide` per side (nearest pixel: labels never blend). */
export function reduceLabels(pixels: LabelPixels, maxSide = MAX_PICTURE_SIDE): LayerLabels {
  const step = Math.max(1, Math.ceil(Math.max(pixels.width, pixels.height) / maxSide));
  const width = Math.ceil(pixels.width / step);
  const height = Math.ceil(pixels.height / step);
  const labels = new Uint16Array(width * height);
  const data = pixels.data;
  for (let y = 0; y < height; y++) {
    const from = y * step * pixels.width;
    for (let x = 0; x < width; x++) labels[y * width + x] = data[from + x * step];
  }
  return { width, height, step, labels };
}

/** Per raw label: sides on each layer, valid, scutoid (the result's cells, indexed by label). */
export interface CellsByLabel {
  readonly sides: Uint8Array[];
  readonly valid: Uint8Array;
  readonly scutoid: Uint8Array;
}

export function cellsByLabel(cells: readonly MeasuredCellRecord[], layers: number): CellsByLabel {
  const space = 1 + cells.reduce((m, c) => Math.max(m, c.label), 0);
  const sides = Array.from({ length: layers }, () => new Uint8Array(space));
  const valid = new Uint8Array(space);
  const scutoid = new Uint8Array(space);
  for (const c of cells) {
    for (let k = 0; k < layers; k++) sides[k][c.label] = Math.min(255, c.sides[k] ?? 0);
    valid[c.label] = c.valid ? 1 : 0;
    scutoid[c.label] = c.scutoid ? 1 : 0;
  }
  return { sides, valid, scutoid };
}

const BACKGROUND = [40, 40, 40] as const;
/** Every stripe-th diagonal of a scutoid. */
const SCUTOID_STRIPE = [20, 20, 20] as const;

/** Whether picture pixel (x, y) lies on a cell boundary (its right or lower neighbour differs). */
function isLayerBoundary(layer: LayerLabels, periodicX: boolean, x: number, y: number): boolean {
  const { width, height, labels } = layer;
  const id = labels[y * width + x];
  const right = x + 1 < width ? x + 1 : periodicX ? 0 : x;
  if (labels[y * width + right] !== id) return true;
  return y + 1 < height && labels[(y + 1) * width + x] !== id;
}

/** RGBA of layer `k` (ImageData order), painted like a simulated surface (sideColors.ts). */
export function paintLayer(layer: LayerLabels, k: number, cells: CellsByLabel, periodicX: boolean): Uint8ClampedArray<ArrayBuffer> {
  const { width, height, labels } = layer;
  const out = new Uint8ClampedArray(width * height * 4);
  const sides = cells.sides[k];
  const stripe = Math.max(4, Math.round(Math.min(width, height) / 24));
  /** Pixel (x, y)'s colour, of cell `label`, before its boundary is darkened. */
  const colourAt = (label: number, x: number, y: number): readonly number[] => {
    if (label === 0 || label >= sides.length) return BACKGROUND;
    const valid = cells.valid[label] !== 0;
    return valid && cells.scutoid[label] && (x + y) % stripe === 0 ? SCUTOID_STRIPE : cellRgb(sides[label], valid);
  };
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const index = y * width + x;
      const [r, g, b] = colourAt(labels[index], x, y);
      writePixel(out, index, r, g, b, isLayerBoundary(layer, periodicX, x, y));
    }
  }
  return out;
}

/** A copy of a painted layer with cell `label` drawn white (its boundary stays dark): the picked cell. */
export function withSelected(picture: LayerPicture, label: number, periodicX: boolean): Uint8ClampedArray<ArrayBuffer> {
  const out = picture.rgba.slice();
  if (label <= 0) return out;
  const { width, height, labels } = picture;
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const index = y * width + x;
      if (labels[index] !== label || isLayerBoundary(picture, periodicX, x, y)) continue;
      out[index * 4] = SELECTED_RGB[0];
      out[index * 4 + 1] = SELECTED_RGB[1];
      out[index * 4 + 2] = SELECTED_RGB[2];
    }
  }
  return out;
}
