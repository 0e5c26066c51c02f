/**
 * What the page says about a picked cell: its id, valid and scutoid flags, its sides on every
 * surface, and the neighbours it wins and loses between the seeded surface and the other one
 * (ids). Planes and tubes: neighbours from the exact cells (the adjacency the headline uses);
 * closed surfaces: the result's neighbours (label images). The analysis' own won / lost counts
 * (accumulated over layers under the lab protocol) are shown beside them. Every line names the
 * method that made its numbers, and where the neighbour ids come from another method than the
 * flags, the panel says so (issue 26: never mixed silently).
 */
import { exactCell, outlineCells } from '../../view/cellOutline';
import type { ViewStack, ViewSurface } from '../../view/stack';

interface CellSummary {
  id: number;
  valid: boolean;
  scutoid: boolean;
  sides: { surface: string; sides: number }[];
  /** Ids, ascending. */
  won: number[];
  lost: number[];
  neighbourSource: 'exact' | 'labels';
  /** The method of the flags and sides (the analysis shown), or null without an analysis. */
  flagsMethod: 'exact' | 'labels' | null;
}

function neighbourIds(stack: ViewStack, surface: ViewSurface, id: number): number[] {
  // The cell's own exact polygon (cellOutline.ts): the same neighbours as the whole surface's
  // exact cells, at a pick's cost whatever the cell count (issue 27).
  if (!stack.closed) return id >= 0 && id < surface.cells.length ? exactCell(surface.image.grid, outlineCells(surface.cells), id).neighbours : [];
  return (surface.cells[id]?.neighbours ?? []).map((n) => n.id).sort((a, b) => a - b);
}

function cellSummary(stack: ViewStack, id: number): CellSummary {
  const first = stack.surfaces[0];
  const last = stack.surfaces[stack.surfaces.length - 1];
  const seeded = new Set(neighbourIds(stack, first, id));
  const other = new Set(neighbourIds(stack, last, id));
  return {
    id,
    valid: stack.valid[id] === 1,
    scutoid: stack.scutoid[id] === 1,
    sides: stack.surfaces.map((s) => ({ surface: s.name, sides: s.sides[id] })),
    won: [...other].filter((n) => !seeded.has(n)).sort((a, b) => a - b),
    lost: [...seeded].filter((n) => !other.has(n)).sort((a, b) => a - b),
    neighbourSource: stack.closed ? 'labels' : 'exact',
    flagsMethod: stack.analysis?.method ?? null,
  };
}

/** The panel's lines for cell `id` of `stack` (see the module's comment). */
export function cellInfoLines(stack: ViewStack, id: number): string[] {
  const s = cellSummary(stack, id);
  const stats = stack.analysis?.cells[id];
  const first = stack.surfaces[0].name;
  const last = stack.surfaces[stack.surfaces.length - 1].name;
  // Without an analysis the flags are the border test and the sides the result's neighbours.
  const flagsBy = s.flagsMethod ? `${s.flagsMethod} method` : `${s.neighbourSource} neighbours, no analysis`;
  const lines = [
    `Cell ${s.id}: ${s.valid ? 'valid' : 'border cell (not counted)'}, ${s.scutoid ? 'scutoid' : 'not a scutoid'} (${flagsBy}).`,
    `Sides (${flagsBy}): ${s.sides.map((x) => `${x.surface} ${x.sides}`).join(', ')}.`,
    `Neighbours won from ${first} to ${last}: ${cells(s.won)}; lost: ${cells(s.lost)} (${s.neighbourSource} method).`,
  ];
  if (s.flagsMethod && s.flagsMethod !== s.neighbourSource)
    lines.push(
      `These neighbour ids are the ${s.neighbourSource} method's; the flags and sides above are the ${s.flagsMethod} method's: the two methods can disagree on a cell.`,
    );
  if (stats)
    lines.push(
      `Analysis (${stack.analysis!.method} method): ${stats.won} won, ${stats.lost} lost, ${stats.transitions} transitions, ${stats.neighbours3D} 3D neighbours.`,
    );
  return lines;
}

/** One <p> per line of text (the cell descriptions of the 3D, measured and volume views). */
export function paragraphs(lines: readonly string[]): HTMLParagraphElement[] {
  return lines.map((line) => {
    const p = document.createElement('p');
    p.textContent = line;
    return p;
  });
}

export function renderCellInfo(container: HTMLElement, stack: ViewStack | null, id: number): void {
  container.replaceChildren();
  if (!stack || id < 0 || id >= stack.result.cells.length) {
    container.textContent = 'Click a cell in the 3D view or the unrolled surfaces, or type its id, to see its neighbours.';
    return;
  }
  const s = cellSummary(stack, id);
  container.append(...paragraphs(cellInfoLines(stack, id)));
  container.dataset.cell = String(id);
  container.dataset.won = s.won.join(' ');
  container.dataset.lost = s.lost.join(' ');
}

/**
 * The hover tooltip's text for the cell under the pointer: its id, the surface it is on, its sides
 * on every surface (from the analysis shown) and whether it is a scutoid or a border cell.
 */
export function hoverText(stack: ViewStack, picked: { surface: number; cell: number }): string {
  const id = picked.cell;
  const on = stack.surfaces[picked.surface]?.name ?? '';
  const sides = stack.surfaces.map((s) => `${s.name} ${s.sides[id]}`).join(', ');
  const flag = stack.valid[id] !== 1 ? 'border cell (not counted)' : stack.scutoid[id] === 1 ? 'scutoid' : 'not a scutoid';
  return `Cell ${id} (on ${on}) · sides ${sides} · ${flag}${stack.analysis ? ` (${stack.analysis.method} method)` : ''}`;
}

/** Neighbour ids in words that cannot be read as counts: "cell 51", "cells 7, 12 (2)", "none". */
function cells(ids: readonly number[]): string {
  if (ids.length === 0) return 'none';
  return ids.length === 1 ? `cell #${ids[0]}` : `cells #${ids.join(', #')} (${ids.length})`;
}
