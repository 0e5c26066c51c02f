/**
 * The per-cell table in the results panel as a virtual list (issue 27): only the rows in view
 * (model/rowWindow.ts) are in the DOM, between two spacer rows as tall as the rows left out, and
 * are rebuilt one frame after each scroll. Rows come from model/cellRows.ts one at a time (the
 * CSV export writes the same rows). The box scrolls with the keyboard (it takes the focus); the
 * table says its full row count to assistive technology (aria-rowcount, aria-rowindex).
 */
import { cellRow, cellTableHeader } from '../model/cellRows';
import { rowWindow, scrollToRow } from '../model/rowWindow';
import type { ViewStack } from '../../view/stack';
import { tableRow } from './tableRow';

/** Row height (px) until one has been measured (the table's CSS fixes it: no wrapping). */
const DEFAULT_ROW_PX = 22;
/** The viewport assumed while the box is closed (its details collapsed): its CSS max-height. */
const DEFAULT_VIEWPORT_PX = 360;

interface State {
  stack: ViewStack;
  body: HTMLTableSectionElement;
  rowHeight: number;
  drawn: string;
  frame: number;
  /** The picked cell's row (-1: none), marked and scrolled to. */
  selected: number;
}
const states = new WeakMap<HTMLElement, State>();

/** Shows `stack`'s cells in `box` (a scrolling element), replacing what it showed. */
export function renderCellTable(box: HTMLElement, stack: ViewStack): void {
  const count = stack.result.cells.length;
  const header = cellTableHeader(stack);
  const table = document.createElement('table');
  table.className = 'cells';
  table.setAttribute('aria-rowcount', String(count + 1));
  const head = document.createElement('thead');
  const headRow = tableRow(header, true);
  headRow.setAttribute('aria-rowindex', '1');
  head.append(headRow);
  const body = document.createElement('tbody');
  table.append(head, body);
  box.replaceChildren(table);
  box.tabIndex = 0;
  box.setAttribute('aria-label', `Per-cell table, ${count} cells`);
  const known = states.get(box);
  const state: State = { stack, body, rowHeight: known?.rowHeight ?? DEFAULT_ROW_PX, drawn: '', frame: 0, selected: known?.selected ?? -1 };
  if (!known) {
    box.addEventListener('scroll', () => schedule(box), { passive: true });
    // Opening the collapsed details gives the box its height: draw what is now in view.
    box.closest('details')?.addEventListener('toggle', () => schedule(box));
  }
  states.set(box, state);
  box.scrollTop = 0;
  drawRows(box, state);
}

/** Marks cell `id`'s row as the picked one (-1: none) and scrolls the table to it. */
export function selectCellRow(box: HTMLElement, id: number): void {
  const state = states.get(box);
  if (!state) return;
  state.selected = id;
  if (id >= 0 && id < state.stack.result.cells.length && box.clientHeight > 0) {
    const head = box.querySelector('thead')?.getBoundingClientRect().height ?? 0;
    box.scrollTop = scrollToRow(id, state.rowHeight, Math.max(0, box.scrollTop - head), box.clientHeight - head) + head;
  }
  state.drawn = '';
  drawRows(box, state);
}

function schedule(box: HTMLElement): void {
  const state = states.get(box);
  if (!state || state.frame) return;
  state.frame = requestAnimationFrame(() => {
    state.frame = 0;
    if (states.get(box) === state) drawRows(box, state);
  });
}

/** Puts the rows in view (and the spacers) in the body, when the window changed. */
function drawRows(box: HTMLElement, state: State): void {
  const { stack, body } = state;
  const count = stack.result.cells.length;
  const viewport = box.clientHeight || DEFAULT_VIEWPORT_PX;
  const { start, end, before, after } = rowWindow(count, state.rowHeight, box.scrollTop, viewport);
  const key = `${start}:${end}`;
  if (key === state.drawn) return;
  state.drawn = key;
  const rows: HTMLTableRowElement[] = [];
  if (before > 0) rows.push(spacer(before, 'before'));
  for (let i = start; i < end; i++) {
    const cells = cellRow(stack, i);
    const tr = tableRow(cells);
    tr.setAttribute('aria-rowindex', String(i + 2));
    if (cells[2] === 1) tr.className = 'scutoid';
    else if (cells[1] === 0) tr.className = 'border';
    if (i === state.selected) {
      tr.classList.add('picked');
      tr.setAttribute('aria-selected', 'true');
    }
    rows.push(tr);
  }
  if (after > 0) rows.push(spacer(after, 'after'));
  body.replaceChildren(...rows);
  // The real row height, once rows are laid out (the box open): the spacers follow it.
  const measured = rows.find((r) => !r.classList.contains('spacer'))?.getBoundingClientRect().height ?? 0;
  if (count > 0 && measured > 0 && Math.abs(measured - state.rowHeight) > 0.5) {
    state.rowHeight = measured;
    state.drawn = '';
    drawRows(box, state);
  }
}

/** A row as tall as `height` px of rows left out; hidden from assistive technology. */
function spacer(height: number, which: 'before' | 'after'): HTMLTableRowElement {
  const tr = document.createElement('tr');
  tr.className = `spacer ${which}`;
  tr.setAttribute('aria-hidden', 'true');
  const td = document.createElement('td');
  td.colSpan = 1000;
  tr.style.height = `${height}px`;
  tr.append(td);
  return tr;
}
