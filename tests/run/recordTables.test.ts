/**
 * Records back into columns (run/recordTables.ts, issue 27): a JSON's records sent to the page
 * as columns must come back, made when read (lazyRecords.ts), as the very records of the file;
 * a record the columns cannot hold exactly gives null (the records are then sent as they are).
 */
import { describe, expect, it } from 'vitest';
import { withCellRecords } from '../../src/run/cellTables';
import { withLazyCellRecords } from '../../src/run/lazyRecords';
import { analysisTableOfRecords, cellTableOfRecords, resultCellTables, tableBuffers } from '../../src/run/recordTables';
import { runLayeredTube } from './layeredTube';
import type { SheetResult } from '../../src/run';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();

describe('recordTables', () => {
  it("a result file's records, through columns and back, are the file's (JSON for JSON)", async () => {
    const output = await runLayeredTube(context);
    // As a file holds it: the records written out and parsed back.
    const text = JSON.stringify(withCellRecords(output.result, output.tables!));
    const file = JSON.parse(text) as SheetResult;
    const tables = resultCellTables(file)!;
    expect(tables).not.toBeNull();
    expect(tables.surfaces.length).toBe(file.surfaces.length);
    const stripped = {
      ...file,
      cells: null,
      surfaces: file.surfaces.map((s) => ({ ...s, cells: null })),
      analyses: file.analyses.map((a) => ({ ...a, cells: null })),
    };
    expect(JSON.stringify(withLazyCellRecords(stripped as unknown as SheetResult, tables))).toBe(text);
    // The engine's own columns, independently: the same numbers.
    expect(Array.from(tables.cells.neighbourIds)).toEqual(Array.from(output.tables!.cells.neighbourIds));
    expect(Array.from(tables.analyses[0].sides)).toEqual(Array.from(output.tables!.analyses[0].sides));
    // Every column's buffer once, none shared between columns.
    const columns = [tables.cells, ...tables.surfaces, ...tables.analyses].flatMap((t) => Object.values(t).filter((v) => ArrayBuffer.isView(v)));
    expect(tableBuffers(tables).length).toBe(columns.length);
  });

  it('gives null for records the columns cannot hold exactly', () => {
    const cell = { id: 0, position: [1, 2, 3], surface: [4, 5], area: 6, neighbours: [{ id: 1, length: 0.5 }], touchesBorder: false };
    const other = { ...cell, id: 1, neighbours: [{ id: 0, length: 0.5 }] };
    expect(cellTableOfRecords([cell, other] as never)).not.toBeNull();
    expect(cellTableOfRecords([{ ...cell, note: 'extra' }, other] as never)).toBeNull();
    expect(cellTableOfRecords([other, cell] as never)).toBeNull();
    expect(cellTableOfRecords([{ ...cell, touchesBorder: 1 }, other] as never)).toBeNull();
    expect(cellTableOfRecords([{ ...cell, neighbours: [{ id: 1.5, length: 0.5 }] }, other] as never)).toBeNull();
    const stats = { id: 0, valid: true, scutoid: false, won: 1, lost: 0, transitions: 1, neighbours3D: 7, sides: [6, 7] };
    expect(analysisTableOfRecords([stats] as never)).not.toBeNull();
    expect(analysisTableOfRecords([stats, { ...stats, id: 1, sides: [6] }] as never)).toBeNull();
    expect(analysisTableOfRecords([{ ...stats, won: 2 ** 40 }] as never)).toBeNull();
  });
});
