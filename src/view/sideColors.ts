/**
 * Colours of cells by number of sides, and the painting of a label image into RGBA texels:
 * cell colour by sides, dark boundaries, scutoids striped, border cells (excluded from the
 * statistics) faded. Shared by the 3D view, the unrolled diagrams, the legend and the element.
 */
import type { ViewSurface } from './stack';

/** Side classes 3..9 and 10+, as in the polygon distribution. */
export const SIDE_LABELS = ['3', '4', '5', '6', '7', '8', '9', '10+'] as const;
/**
 * Colour-blind-safe: the Okabe-Ito palette (Okabe & Ito 2008, "Color Universal Design") with a
 * dark grey for 10+; every pair stays apart (CIE76 ΔE >= 15) under simulated protanopia,
 * deuteranopia and tritanopia (Machado et al. 2009), checked in e2e/app-publish.spec.ts.
 * Hexagons, the commonest class, get the light yellow.
 */
export const SIDE_COLORS = ['#cc79a7', '#0072b2', '#56b4e9', '#f0e442', '#e69f00', '#d55e00', '#009e73', '#4d4d4d'] as const;
const NO_CELL = [40, 40, 40] as const;

export const RGB = SIDE_COLORS.map((hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16)));

/** Colour index of a cell with `sides` sides (fewer than 3 share the "3" colour). */
export function sideColorIndex(sides: number): number {
  return Math.max(0, Math.min(sides, 10) - 3);
}

/** A cell's colour by its sides; one not counted in the statistics (not valid) faded two thirds of the way to light grey. */
export function cellRgb(sides: number, valid: boolean): readonly number[] {
  const rgb = RGB[sideColorIndex(sides)];
  return valid ? rgb : rgb.map((v) => (v + 2 * 235) / 3);
}

export interface PaintOptions {
  /** Stripe scutoids (default true). */
  highlightScutoids?: boolean;
  /** 1 for cells counted in the statistics; others are faded. */
  valid?: Uint8Array;
  scutoid?: Uint8Array;
  /** A picked cell, drawn white (its border stays dark) on every surface; -1 or absent: none. */
  selected?: number;
}

/** Fill of a picked cell: white is in no side class, so it cannot be read as one. */
export const SELECTED_RGB = [255, 255, 255] as const;

/**
 * RGBA bytes of a surface's label image, row-major with row 0 = y 0 (the DataTexture and
 * ImageData layouts differ only in that ImageData's row 0 is the top; callers flip).
 */
export function paintSurface(surface: ViewSurface, options: PaintOptions = {}): Uint8ClampedArray {
  const { labels, grid } = surface.image;
  const { width, height } = grid;
  const out = new Uint8ClampedArray(width * height * 4);
  const highlight = options.highlightScutoids ?? true;
  const stripe = Math.max(4, Math.round(Math.min(width, height) / 24));
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      const index = y * width + x;
      const id = labels[index];
      let r: number, g: number, b: number;
      if (id < 0) [r, g, b] = NO_CELL;
      else {
        [r, g, b] = cellRgb(surface.sides[id] ?? 0, !options.valid || !!options.valid[id]);
        if (id === options.selected) [r, g, b] = SELECTED_RGB;
        else if (highlight && options.scutoid?.[id] && (x + y) % stripe === 0) {
          r = 20;
          g = 20;
          b = 20;
        }
      }
      writePixel(out, index, r, g, b, isBoundary(labels, width, height, grid.periodicX, x, y, id));
    }
  }
  return out;
}

/** Writes an opaque RGBA pixel, darkened to a quarter on a cell boundary. */
export function writePixel(out: Uint8Array | Uint8ClampedArray, index: number, r: number, g: number, b: number, boundary: boolean): void {
  const shade = boundary ? 0.25 : 1;
  out[index * 4] = r * shade;
  out[index * 4 + 1] = g * shade;
  out[index * 4 + 2] = b * shade;
  out[index * 4 + 3] = 255;
}

function isBoundary(labels: Int32Array, width: number, height: number, periodicX: boolean, x: number, y: number, id: number): boolean {
  const right = x + 1 < width ? x + 1 : periodicX ? 0 : x;
  if (labels[y * width + right] !== id) return true;
  if (y + 1 < height && labels[(y + 1) * width + x] !== id) return true;
  return false;
}

/** Copies row-major bytes with row 0 = y 0 into ImageData order (row 0 = top). */
export function flipRows(rgba: Uint8ClampedArray, width: number, height: number): Uint8ClampedArray<ArrayBuffer> {
  const out = new Uint8ClampedArray(rgba.length);
  const row = width * 4;
  for (let y = 0; y < height; y++) out.set(rgba.subarray(y * row, (y + 1) * row), (height - 1 - y) * row);
  return out;
}
