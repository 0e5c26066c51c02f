/**
 * Contacts between labels in one layer, counted as 4-connected pixel edges (docs/measure.md,
 * "Definitions"): pairs (x, y)-(x+1, y) and (x, y)-(x, y+1) holding two different non-zero
 * labels; with periodicX also (width-1, y)-(0, y). Rows never wrap.
 *
 * One pass over the rows reading two rows at a time; nothing image-sized is allocated. Per-label
 * tables are indexed by the raw label (at most 2^16 entries), so labels need not be dense.
 */
import { BORDER_X_END, BORDER_X_START, BORDER_Y_END, BORDER_Y_START } from '../border';
import type { LabelPixels } from './labelImage';

/** The border bits (core/border.ts) by the image edge they name; the top row is y = 0. */
export const BORDER_NAMES: ReadonlyArray<[number, string]> = [
  [BORDER_X_START, 'left'],
  [BORDER_X_END, 'right'],
  [BORDER_Y_START, 'top'],
  [BORDER_Y_END, 'bottom'],
];

/** Pair key of labels a < b (both < 2^16). */
export const pairKey = (a: number, b: number): number => (a < b ? a * 65536 + b : b * 65536 + a);

export interface LayerContacts {
  readonly width: number;
  readonly height: number;
  /** Size of the label tables (2^bitsPerSample). */
  readonly labelSpace: number;
  /** Pixels per raw label (index 0: background). */
  readonly pixels: Uint32Array;
  /** BORDER_* bits per raw label. */
  readonly border: Uint8Array;
  /** Edge counts per pair of raw labels, keyed by pairKey(a, b) with a < b. */
  readonly edges: Map<number, number>;
  /** Number of distinct non-zero labels. */
  readonly labels: number;
}

export function countContacts(image: LabelPixels, periodicX: boolean): LayerContacts {
  const { width, height, data } = image;
  const labelSpace = 2 ** image.bitsPerSample;
  const pixels = new Uint32Array(labelSpace);
  const border = new Uint8Array(labelSpace);
  const edges = new Map<number, number>();
  // Consecutive edges along a boundary usually join the same pair: remember the last key.
  let lastKey = -1;
  let lastCount = 0;
  const add = (a: number, b: number) => {
    const key = pairKey(a, b);
    if (key === lastKey) {
      lastCount++;
      return;
    }
    if (lastKey >= 0) edges.set(lastKey, (edges.get(lastKey) ?? 0) + lastCount);
    lastKey = key;
    lastCount = 1;
  };

  for (let y = 0; y < height; y++) {
    const row = y * width;
    const below = y + 1 < height ? row + width : -1;
    for (let x = 0; x < width; x++) {
      const a = data[row + x];
      if (a === 0) continue;
      pixels[a]++;
      if (x + 1 < width) {
        const r = data[row + x + 1];
        if (r !== a && r !== 0) add(a, r);
      }
      if (below >= 0) {
        const d = data[below + x];
        if (d !== a && d !== 0) add(a, d);
      }
    }
    const first = data[row];
    const last = data[row + width - 1];
    if (periodicX) {
      if (width > 1 && first !== last && first !== 0 && last !== 0) add(last, first);
    } else {
      border[first] |= BORDER_X_START;
      border[last] |= BORDER_X_END;
    }
  }
  if (lastKey >= 0) edges.set(lastKey, (edges.get(lastKey) ?? 0) + lastCount);
  for (let x = 0; x < width; x++) {
    border[data[x]] |= BORDER_Y_START;
    border[data[(height - 1) * width + x]] |= BORDER_Y_END;
  }
  border[0] = 0;
  let labels = 0;
  for (let v = 1; v < labelSpace; v++) if (pixels[v] > 0) labels++;
  return { width, height, labelSpace, pixels, border, edges, labels };
}
