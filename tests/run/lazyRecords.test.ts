/**
 * A large opened result's records made when read (issue 27): the same lists as withCellRecords
 * makes all at once, seen as arrays by every way the page and the exports read them.
 */
import { describe, expect, it } from 'vitest';
import { withCellRecords } from '../../src/run/cellTables';
import { analysisColumns, lazyRecords, resultColumns, withLazyCellRecords } from '../../src/run/lazyRecords';
import { runLayeredTube } from './layeredTube';
import { viewStack } from '../../src/view/stack';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();

describe('lazyRecords', () => {
  it('is an array to every reader; each record is made once, when first read', () => {
    let made = 0;
    const list = lazyRecords(5, (i) => {
      made++;
      return { id: i, twice: 2 * i };
    });
    expect(made).toBe(0);
    expect(Array.isArray(list)).toBe(true);
    expect(list.length).toBe(5);
    expect(list[3]).toEqual({ id: 3, twice: 6 });
    expect(list[3]).toBe(list[3]);
    expect(made).toBe(1);
    expect(list[5]).toBeUndefined();
    expect(3 in list).toBe(true);
    expect(5 in list).toBe(false);
    const plain = [0, 1, 2, 3, 4].map((i) => ({ id: i, twice: 2 * i }));
    expect(list.map((r) => r.twice)).toEqual(plain.map((r) => r.twice));
    expect([...list]).toEqual(plain);
    expect(JSON.stringify(list)).toBe(JSON.stringify(plain));
    expect(Object.keys(list)).toEqual(Object.keys(plain));
    expect(list.filter((r) => r.id % 2 === 0).map((r) => r.id)).toEqual([0, 2, 4]);
    expect(made).toBe(5);
  });

  it("a run's side-file columns: the lists withCellRecords makes, and the analysis's columns", async () => {
    const output = await runLayeredTube(context);
    const eager = withCellRecords(output.result, output.tables!);
    const lazy = withLazyCellRecords(output.result, output.tables!);
    expect(JSON.parse(JSON.stringify(lazy))).toEqual(JSON.parse(JSON.stringify(eager)));
    expect(lazy.surfaces[1].cells[7]).toEqual(eager.surfaces[1].cells[7]);
    expect(analysisColumns(lazy.analyses[0].cells)).toBe(output.tables!.analyses[0]);
    expect(analysisColumns(eager.analyses[0].cells)).toBeNull();
    // The columns behind the result, also for a copy of it with another headline (the page's
    // mean over realizations), so the page can hand them to the worker that holds large results.
    expect(resultColumns(lazy)).toBe(output.tables);
    expect(resultColumns({ ...lazy, headline: null })).toBe(output.tables);
    expect(resultColumns(eager)).toBeNull();
    const rebuilt = withLazyCellRecords(
      { ...lazy, cells: [], surfaces: lazy.surfaces.map((s) => ({ ...s, cells: [] })), analyses: lazy.analyses.map((a) => ({ ...a, cells: [] })) },
      resultColumns(lazy)!,
    );
    expect(JSON.stringify(rebuilt)).toBe(JSON.stringify(eager));
    // The views read the analysis's columns (no records made): the same sides and flags.
    const images = [0, 1, 2].map((k) => ({ name: `s${k}`, grid: output.result.grid, labels: new Int32Array(1) }));
    const fromColumns = viewStack({ result: lazy, labelImages: images });
    const fromRecords = viewStack({ result: eager, labelImages: images });
    expect(fromColumns.surfaces.map((s) => Array.from(s.sides))).toEqual(fromRecords.surfaces.map((s) => Array.from(s.sides)));
    expect(Array.from(fromColumns.valid)).toEqual(Array.from(fromRecords.valid));
    expect(Array.from(fromColumns.scutoid)).toEqual(Array.from(fromRecords.scutoid));
    expect(fromColumns.scutoid.some((f) => f === 1)).toBe(true);
  });
});
