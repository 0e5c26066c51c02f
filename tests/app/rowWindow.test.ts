import { describe, expect, it } from 'vitest';
import { ALL_ROWS_UP_TO, rowWindow, scrollToRow } from '../../src/app/model/rowWindow';

/** Rows a viewport [top, top + height) overlaps, by brute force over every row. */
function overlapped(count: number, rowHeight: number, top: number, height: number): number[] {
  const rows: number[] = [];
  for (let i = 0; i < count; i++) if (i * rowHeight < top + height && (i + 1) * rowHeight > top) rows.push(i);
  return rows;
}

describe('rowWindow (the cell table as a virtual list)', () => {
  it('a short table is shown whole', () => {
    expect(rowWindow(ALL_ROWS_UP_TO, 22, 5000, 360)).toEqual({ start: 0, end: ALL_ROWS_UP_TO, before: 0, after: 0 });
  });

  it('100,000 rows: every row in view is in the window, the window is bounded, the spacers fill the rest', () => {
    const count = 100_000;
    for (const [rowHeight, viewport] of [
      [22, 360],
      [19.5, 800],
      [30, 0],
    ]) {
      for (const top of [0, 1, 21.9, 4321, 1_000_000, count * rowHeight - viewport, count * rowHeight + 50]) {
        const w = rowWindow(count, rowHeight, top, viewport, 20);
        for (const i of overlapped(count, rowHeight, top, viewport)) {
          expect(i).toBeGreaterThanOrEqual(w.start);
          expect(i).toBeLessThan(w.end);
        }
        expect(w.end - w.start).toBeLessThanOrEqual(Math.ceil(viewport / rowHeight) + 1 + 40);
        expect(w.start).toBeGreaterThanOrEqual(0);
        expect(w.end).toBeLessThanOrEqual(count);
        expect(w.before + (w.end - w.start) * rowHeight + w.after).toBeCloseTo(count * rowHeight, 6);
      }
    }
  });

  it('scrolling to a row brings it fully into view and moves no more than needed', () => {
    for (const [index, top] of [
      [0, 500],
      [10, 0],
      [500, 220],
      [40, 800],
    ]) {
      const next = scrollToRow(index, 22, top, 360);
      expect(index * 22).toBeGreaterThanOrEqual(next);
      expect((index + 1) * 22).toBeLessThanOrEqual(next + 360);
      if (index * 22 >= top && (index + 1) * 22 <= top + 360) expect(next).toBe(top);
    }
  });
});
