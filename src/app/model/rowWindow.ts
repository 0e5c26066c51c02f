/**
 * Which rows of a long table are in the DOM (issue 27: the per-cell table of a 100,000-cell
 * result was 100,000 rows, built in ~1.7 s on the main thread): the rows in view plus `overscan`
 * on each side, with the heights of the rows left out above and below (spacers that keep the
 * scroll bar true). Rows have one fixed height. Pure.
 */

/** Tables up to this many rows are shown whole (find in page works on them). */
export const ALL_ROWS_UP_TO = 1000;

export interface RowWindow {
  /** First row in the DOM. */
  readonly start: number;
  /** One past the last row in the DOM. */
  readonly end: number;
  /** Height (px) of the rows above `start` and below `end`. */
  readonly before: number;
  readonly after: number;
}

export function rowWindow(count: number, rowHeight: number, scrollTop: number, viewport: number, overscan = 20): RowWindow {
  if (count <= ALL_ROWS_UP_TO || !(rowHeight > 0)) return { start: 0, end: count, before: 0, after: 0 };
  const first = Math.floor(Math.max(0, scrollTop) / rowHeight);
  const shown = Math.ceil(Math.max(0, viewport) / rowHeight) + 1;
  const start = Math.max(0, Math.min(count, first - overscan));
  const end = Math.max(start, Math.min(count, first + shown + overscan));
  return { start, end, before: start * rowHeight, after: (count - end) * rowHeight };
}

/** The scrollTop that brings row `index` into a viewport of `viewport` px (unchanged when it is in view). */
export function scrollToRow(index: number, rowHeight: number, scrollTop: number, viewport: number): number {
  const top = index * rowHeight;
  if (top < scrollTop) return top;
  if (top + rowHeight > scrollTop + viewport) return top + rowHeight - viewport;
  return scrollTop;
}
