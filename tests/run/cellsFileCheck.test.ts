/**
 * A side file's tables are checked before anything reads them (src/run/cellsFileCheck.ts, run by
 * decodeCellsFile): a well-formed file decodes to the tables it was written from; each broken
 * structure (a neighbour id of no cell, offsets that decrease or run far past the list, a column
 * of the wrong type or length, tables of different counts) is refused naming the file, the table
 * and the column.
 */
import { describe, expect, it } from 'vitest';
import {
  cellsFileLayout,
  decodeCellsFile,
  type AnalysisCellTable,
  type CellsFileRecord,
  type CellTable,
  type ResultCellTables,
} from '../../src/run/cellTables';

/** Three cells in a row: 0-1, 1-2. */
function cells(): CellTable {
  return {
    count: 3,
    position: Float64Array.from({ length: 9 }, (_, k) => k + 0.5),
    surface: Float64Array.from({ length: 6 }, (_, k) => k / 4),
    area: Float64Array.of(10, 11, 12),
    touchesBorder: Uint8Array.of(1, 0, 1),
    neighbourOffsets: Int32Array.of(0, 1, 3, 4),
    neighbourIds: Int32Array.of(1, 0, 2, 1),
    neighbourLengths: Float64Array.of(2, 2, 3, 3),
  };
}

function analysis(): AnalysisCellTable {
  return {
    count: 3,
    valid: Uint8Array.of(0, 1, 0),
    scutoid: Uint8Array.of(0, 1, 0),
    won: Int32Array.of(0, 1, 0),
    lost: Int32Array.of(0, 0, 0),
    transitions: Int32Array.of(0, 1, 0),
    neighbours3D: Int32Array.of(1, 3, 1),
    sides: Int32Array.of(1, 2, 1, 1, 3, 1),
  };
}

function file(tables: ResultCellTables): { record: CellsFileRecord; bytes: Uint8Array } {
  const { record, chunks } = cellsFileLayout(tables, 'r.cells.bin');
  const bytes = new Uint8Array(record.bytes);
  let at = 0;
  for (const chunk of chunks) {
    bytes.set(chunk, at);
    at += chunk.byteLength;
  }
  return { record, bytes };
}

const tables = (): ResultCellTables => ({ cells: cells(), surfaces: [cells()], analyses: [analysis()] });

/** The file's bytes with one int32 of a column of the first table replaced. */
function withInt(name: string, index: number, value: number): () => ResultCellTables {
  const { record, bytes } = file(tables());
  const column = record.tables[0].columns[name];
  new DataView(bytes.buffer).setInt32(column.offset + 4 * index, value, true);
  return () => decodeCellsFile(record, bytes);
}

/** The file's bytes with one value of a column of table `t` replaced (int32, uint8 or float64 as the column is). */
function withValue(t: number, name: string, index: number, value: number): () => ResultCellTables {
  const { record, bytes } = file(tables());
  const column = record.tables[t].columns[name] as { offset: number; type: string };
  const view = new DataView(bytes.buffer);
  if (column.type === 'uint8') view.setUint8(column.offset + index, value);
  else if (column.type === 'int32') view.setInt32(column.offset + 4 * index, value, true);
  else view.setFloat64(column.offset + 8 * index, value, true);
  return () => decodeCellsFile(record, bytes);
}

describe('the structure of a side file', () => {
  it('flags other than 0 and 1, negative counts and positions that are not finite are refused', () => {
    expect(withValue(2, 'valid', 0, 7)).toThrow('r.cells.bin: analyses[0].cells.valid[0] is 7, not 0 or 1');
    expect(withValue(0, 'touchesBorder', 1, 2)).toThrow('cells.touchesBorder[1] is 2, not 0 or 1');
    expect(withValue(2, 'sides', 3, -5)).toThrow('analyses[0].cells.sides[3] is -5, not a count');
    expect(withValue(2, 'won', 1, -1)).toThrow('analyses[0].cells.won[1] is -1, not a count');
    expect(withValue(1, 'position', 4, Infinity)).toThrow('surfaces[0].cells.position[4] is Infinity, not a finite number');
    expect(withValue(0, 'surface', 0, NaN)).toThrow('cells.surface[0] is NaN, not a finite number');
  });

  it('areas and contact lengths that are negative or not finite are refused; zero is a measure', () => {
    expect(withValue(0, 'area', 2, -1e300)).toThrow('r.cells.bin: cells.area[2] is -1e+300, not a finite measure >= 0');
    expect(withValue(1, 'area', 0, NaN)).toThrow('surfaces[0].cells.area[0] is NaN, not a finite measure >= 0');
    expect(withValue(0, 'neighbourLengths', 3, Infinity)).toThrow('cells.neighbourLengths[3] is Infinity, not a finite measure >= 0');
    expect(withValue(1, 'neighbourLengths', 1, -2)).toThrow('surfaces[0].cells.neighbourLengths[1] is -2, not a finite measure >= 0');
    expect(withValue(0, 'area', 1, 0)).not.toThrow();
  });

  it('a well-formed file decodes to its tables; an empty one too', () => {
    const { record, bytes } = file(tables());
    const decoded = decodeCellsFile(record, bytes);
    expect(Array.from(decoded.cells.neighbourIds)).toEqual([1, 0, 2, 1]);
    expect(Array.from(decoded.analyses[0].sides)).toEqual([1, 2, 1, 1, 3, 1]);
    const empty: CellTable = {
      ...cells(),
      count: 0,
      position: new Float64Array(0),
      surface: new Float64Array(0),
      area: new Float64Array(0),
      touchesBorder: new Uint8Array(0),
      neighbourOffsets: Int32Array.of(0),
      neighbourIds: new Int32Array(0),
      neighbourLengths: new Float64Array(0),
    };
    const none = file({ cells: empty, surfaces: [], analyses: [] });
    expect(decodeCellsFile(none.record, none.bytes).cells.count).toBe(0);
  });

  it('a neighbour id of no cell, and offsets that do not start at 0, decrease or run past the list, are refused', () => {
    expect(withInt('neighbourIds', 0, 3)).toThrow('r.cells.bin: cells.neighbourIds[0] is 3, not a cell of the 3');
    expect(withInt('neighbourIds', 2, -1)).toThrow(/neighbourIds\[2\] is -1/);
    expect(withInt('neighbourOffsets', 0, 1)).toThrow('cells.neighbourOffsets starts at 1, not 0');
    expect(withInt('neighbourOffsets', 2, 0)).toThrow('cells.neighbourOffsets decreases at cell 1');
    // An offset of 2^31 - 1 made a reader loop over 2 billion entries: now refused at once.
    expect(withInt('neighbourOffsets', 3, 2 ** 31 - 1)).toThrow('cells.neighbourIds holds 4 values where 2147483647 are expected');
  });

  it('a column of the wrong type or length, or tables of different counts, are refused', () => {
    const { record, bytes } = file(tables());
    const edited = (edit: (r: CellsFileRecord) => void) => {
      const copy = JSON.parse(JSON.stringify(record)) as CellsFileRecord;
      edit(copy);
      return () => decodeCellsFile(copy, bytes);
    };
    expect(edited((r) => ((r.tables[0].columns.area as { type: string }).type = 'int32'))).toThrow('cells.area must be float64');
    expect(edited((r) => ((r.tables[1].columns.area as { length: number }).length = 2))).toThrow('surfaces[0].cells.area holds 2 values where 3 are expected');
    expect(edited((r) => ((r.tables[2] as { count: number }).count = 2))).toThrow("analyses[0].cells has 2 cells where the file's cells table has 3");
    expect(edited((r) => ((r.tables[2].columns.sides as { length: number }).length = 5))).toThrow(
      'analyses[0].cells.sides holds 5 values, not a whole number of surfaces of 3 cells',
    );
    expect(edited((r) => ((r.tables[0] as { count: number }).count = 1.5))).toThrow('cells: count 1.5 is not a whole number of cells');
  });
});
