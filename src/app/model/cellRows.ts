/**
 * The per-cell rows shown in the page's table and written to the per-cell CSV: one source, so
 * the file and the screen always agree.
 */
import { formatCsv } from '../../core/sweep';
import type { ViewStack } from '../../view/stack';

export interface CellTable {
  header: string[];
  rows: (string | number)[][];
}

export function cellTable(stack: ViewStack): CellTable {
  const names = stack.surfaces.map((s) => s.name.replace(/\s+/g, '_'));
  const header = [
    'id',
    'valid',
    'scutoid',
    ...names.map((n) => `sides_${n}`),
    'won',
    'lost',
    'transitions',
    'neighbours3D',
    'area_um2',
    // Closed surfaces: the site's parameter direction as longitude / latitude.
    ...(stack.closed ? ['longitude_deg', 'latitude_deg'] : ['u_um', 'v_um']),
  ];
  const rows = stack.result.cells.map((cell, i) => {
    const stats = stack.analysis?.cells[i];
    return [
      cell.id,
      stack.valid[i],
      stack.scutoid[i],
      ...stack.surfaces.map((s) => s.sides[i]),
      stats?.won ?? '',
      stats?.lost ?? '',
      stats?.transitions ?? '',
      stats?.neighbours3D ?? '',
      round(cell.area, 3),
      round(cell.surface[0], 3),
      round(cell.surface[1], 3),
    ];
  });
  return { header, rows };
}

export function cellCsv(stack: ViewStack): string {
  const { header, rows } = cellTable(stack);
  return formatCsv(header, rows);
}

function round(value: number, digits: number): number {
  const f = 10 ** digits;
  return Math.round(value * f) / f;
}
