/**
 * A result's per-cell records back into columns (cellTables.ts), the inverse of
 * withCellRecords: a large project or result JSON opened in a worker (app/model/openWorker.ts,
 * issue 27) is sent to the page as transferred columns, the page making records when read
 * (lazyRecords.ts), instead of 300,000 records cloned on its thread. Exact or nothing: every
 * record must come back from its columns as the same JSON (a file's extra field or an
 * unexpected value gives null, and the caller sends the records themselves).
 */
import type { AnalysisRecord, CellRecord, SheetResult } from './result';
import { analysisCellRecordsRange, cellRecordsRange, type AnalysisCellTable, type CellTable, type ResultCellTables } from './cellTables';

/** The columns of `records`, or null when one does not come back the same from them. */
export function cellTableOfRecords(records: readonly CellRecord[]): CellTable | null {
  const n = records.length;
  const offsets = new Int32Array(n + 1);
  records.forEach((cell, i) => (offsets[i + 1] = offsets[i] + (Array.isArray(cell?.neighbours) ? cell.neighbours.length : 0)));
  const table: CellTable = {
    count: n,
    position: new Float64Array(3 * n),
    surface: new Float64Array(2 * n),
    area: new Float64Array(n),
    touchesBorder: new Uint8Array(n),
    neighbourOffsets: offsets,
    neighbourIds: new Int32Array(offsets[n]),
    neighbourLengths: new Float64Array(offsets[n]),
  };
  for (let i = 0; i < n; i++) {
    const cell = records[i];
    if (cell?.id !== i || !Array.isArray(cell.position) || !Array.isArray(cell.surface)) return null;
    table.position.set(cell.position, 3 * i);
    table.surface.set(cell.surface, 2 * i);
    table.area[i] = cell.area;
    table.touchesBorder[i] = cell.touchesBorder ? 1 : 0;
    cell.neighbours.forEach((contact, k) => {
      table.neighbourIds[offsets[i] + k] = contact.id;
      table.neighbourLengths[offsets[i] + k] = contact.length;
    });
  }
  return sameRecords(records, (i) => cellRecordsRange(table, i, i + 1)[0]) ? table : null;
}

/** The columns of an analysis's per-cell records, or null (see cellTableOfRecords). */
export function analysisTableOfRecords(records: AnalysisRecord['cells']): AnalysisCellTable | null {
  const n = records.length;
  const surfaces = n > 0 && Array.isArray(records[0]?.sides) ? records[0].sides.length : 0;
  const table: AnalysisCellTable = {
    count: n,
    valid: new Uint8Array(n),
    scutoid: new Uint8Array(n),
    won: new Int32Array(n),
    lost: new Int32Array(n),
    transitions: new Int32Array(n),
    neighbours3D: new Int32Array(n),
    sides: new Int32Array(surfaces * n),
  };
  for (let i = 0; i < n; i++) {
    const c = records[i];
    if (c?.id !== i || !Array.isArray(c.sides) || c.sides.length !== surfaces) return null;
    table.valid[i] = c.valid ? 1 : 0;
    table.scutoid[i] = c.scutoid ? 1 : 0;
    table.won[i] = c.won;
    table.lost[i] = c.lost;
    table.transitions[i] = c.transitions;
    table.neighbours3D[i] = c.neighbours3D;
    c.sides.forEach((sides, k) => (table.sides[k * n + i] = sides));
  }
  return sameRecords(records, (i) => analysisCellRecordsRange(table, i, i + 1)[0]) ? table : null;
}

/** Every per-cell list of `result` as columns, or null when one does not round-trip exactly. */
export function resultCellTables(result: SheetResult): ResultCellTables | null {
  const cells = cellTableOfRecords(result.cells);
  const surfaces = result.surfaces.map((s) => cellTableOfRecords(s.cells));
  const analyses = result.analyses.map((a) => analysisTableOfRecords(a.cells));
  if (!cells || surfaces.some((t) => !t) || analyses.some((t) => !t)) return null;
  return { cells, surfaces: surfaces as CellTable[], analyses: analyses as AnalysisCellTable[] };
}

/** The buffers of `tables`' columns, each once (to transfer). */
export function tableBuffers(tables: ResultCellTables): ArrayBuffer[] {
  const buffers = new Set<ArrayBuffer>();
  for (const table of [tables.cells, ...tables.surfaces, ...tables.analyses]) {
    for (const column of Object.values(table)) if (ArrayBuffer.isView(column)) buffers.add(column.buffer as ArrayBuffer);
  }
  return [...buffers];
}

function sameRecords(records: readonly unknown[], remade: (i: number) => unknown): boolean {
  for (let i = 0; i < records.length; i++) if (JSON.stringify(records[i]) !== JSON.stringify(remade(i))) return false;
  return true;
}
