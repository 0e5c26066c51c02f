import type { SurfaceAdjacency } from './adjacency';

/**
 * Neighbour sets as ascending ranges of Int32Arrays (a CSR row, sorted and deduplicated): the
 * set operations the scutoid statistics count with, allocation-free. Shared by analyzeSurfaces
 * and the sweep's carried lab analysis (src/run/labStackReuse.ts).
 */

/** The mean of n values summing to `sum`; NaN for none. */
export const mean = (sum: number, n: number): number => (n > 0 ? sum / n : NaN);

/** Sorted ranges a[a0, a1), b[b0, b1): |a \ b|. */
export function differenceSize(a: Int32Array, a0: number, a1: number, b: Int32Array, b0: number, b1: number): number {
  let i = a0;
  let j = b0;
  let n = 0;
  while (i < a1) {
    if (j >= b1 || a[i] < b[j]) {
      n++;
      i++;
    } else if (a[i] > b[j]) j++;
    else {
      i++;
      j++;
    }
  }
  return n;
}

/** Sorted, deduplicated ranges a[a0, a1), b[b0, b1): |a ∩ b| (so |a \ b| = |a| - |a ∩ b|, in one pass for both sides). */
export function intersectionSize(a: Int32Array, a0: number, a1: number, b: Int32Array, b0: number, b1: number): number {
  let i = a0;
  let j = b0;
  let n = 0;
  while (i < a1 && j < b1) {
    const x = a[i];
    const y = b[j];
    if (x < y) i++;
    else if (x > y) j++;
    else {
      n++;
      i++;
      j++;
    }
  }
  return n;
}

/** Sorted, deduplicated a[0, an) and b[b0, b1): their union written to out (sorted); its size. */
export function unionInto(a: Int32Array, an: number, b: Int32Array, b0: number, b1: number, out: Int32Array): number {
  let i = 0;
  let j = b0;
  let n = 0;
  while (i < an || j < b1) {
    if (j >= b1 || (i < an && a[i] < b[j])) out[n++] = a[i++];
    else if (i >= an || b[j] < a[i]) out[n++] = b[j++];
    else {
      out[n++] = a[i++];
      j++;
    }
  }
  return n;
}

/** Adds the elements of a \ b (ascending ranges) not yet in `into`. */
export function addDifference(a: Int32Array, a0: number, a1: number, b: Int32Array, b0: number, b1: number, into: number[]): void {
  let j = b0;
  for (let k = a0; k < a1; k++) {
    const v = a[k];
    while (j < b1 && b[j] < v) j++;
    if (j < b1 && b[j] === v) continue;
    if (!into.includes(v)) into.push(v);
  }
}

/** How many elements of a \ b (ascending ranges) are not in `into` (which is not changed). */
export function newDifference(a: Int32Array, a0: number, a1: number, b: Int32Array, b0: number, b1: number, into: readonly number[]): number {
  let j = b0;
  let n = 0;
  for (let k = a0; k < a1; k++) {
    const v = a[k];
    while (j < b1 && b[j] < v) j++;
    if (j < b1 && b[j] === v) continue;
    if (!into.includes(v)) n++;
  }
  return n;
}

/** Every list of a CSR adjacency strictly ascending and without the cell itself: already its neighbour sets. */
export function isCanonical(adj: SurfaceAdjacency): boolean {
  // The arrays in locals: a sweep checks every layer it analyzes once, 200 cells by ~36 layers a run.
  const { count, offsets, neighbours } = adj;
  for (let i = 0; i < count; i++) {
    const from = offsets[i];
    const to = offsets[i + 1];
    for (let k = from; k < to; k++) {
      const v = neighbours[k];
      if (v === i || (k > from && v <= neighbours[k - 1])) return false;
    }
  }
  return true;
}
