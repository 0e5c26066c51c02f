/**
 * The result's cells as columns (runSheet's cellTables option, what `tissue-sheet run` writes to
 * its side file): the same values as the records of a run without it, for every engine and
 * surface kind that has cell lists, and what the exact pipeline reuses between surfaces.
 */
import { describe, expect, it } from 'vitest';
import { validateConfig } from '../../src/core/config';
import { analysisCellRecordsOf, cellRecordsOf } from '../../src/run/cellTables';
import { SheetRunner } from '../../src/run/runSheet';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();

const configs = {
  'exact tube with a layer': {
    surface: { kind: 'tube', radius: 40, length: 300 },
    resolution: 128,
    cells: 50,
    engine: 'exact',
    lloyd: { maxIterations: 3 },
    sheet: { surfaceRatio: 2, layers: 1 },
  },
  'exact torus': {
    surface: { kind: 'plane', width: 200, height: 150, periodicX: true, periodicY: true },
    resolution: 128,
    cells: 60,
    engine: 'exact',
    lloyd: { maxIterations: 3 },
    sheet: { thickness: 4 },
  },
  'GPU tube, both methods': {
    surface: { kind: 'tube', radius: 40, length: 300 },
    resolution: 128,
    cells: 40,
    engine: 'gpu',
    lloyd: { maxIterations: 2 },
    sheet: { surfaceRatio: 1.5, adjacency: 'both' },
  },
  'GPU sphere (cube map)': { surface: { kind: 'sphere', radius: 30 }, resolution: 32, cells: 30, lloyd: { maxIterations: 1 }, sheet: { thickness: 3 } },
  'exact tube, lab protocol': {
    surface: { kind: 'tube', radius: 40, length: 300 },
    resolution: 128,
    cells: 50,
    engine: 'exact',
    lloyd: { maxIterations: 2 },
    sheet: { surfaceRatio: 2, protocol: 'lab' },
  },
};

describe('runSheet(..., {cellTables: true})', () => {
  for (const [name, input] of Object.entries(configs)) {
    it(`${name}: empty lists, and columns that give the records of a run without them`, async () => {
      const config = validateConfig(input);
      const plain = (await new SheetRunner(context).run(config)).result;
      const output = await new SheetRunner(context).run(config, { cellTables: true });
      const tables = output.tables!;
      expect(output.result.cells).toEqual([]);
      expect(output.result.surfaces.every((s) => s.cells.length === 0)).toBe(true);
      expect(output.result.analyses.every((a) => a.cells.length === 0)).toBe(true);
      expect(cellRecordsOf(tables.cells)).toEqual(plain.cells);
      expect(tables.surfaces.map(cellRecordsOf)).toEqual(plain.surfaces.map((s) => s.cells));
      expect(tables.analyses.map(analysisCellRecordsOf)).toEqual(plain.analyses.map((a) => a.cells));
      expect(output.result.analyses.map((a) => a.summary)).toEqual(plain.analyses.map((a) => a.summary));
    });
  }

  it("a plane's other surface shares the seeded surface's exact adjacency (computed once)", async () => {
    const config = validateConfig(configs['exact torus']);
    const { tables } = await new SheetRunner(context).run(config, { cellTables: true });
    const [seeded, other] = [tables!.cells, tables!.surfaces[0]];
    expect(other.neighbourIds).toBe(seeded.neighbourIds);
    expect(other.area).toBe(seeded.area);
    expect(Array.from(other.position.filter((_, k) => k % 3 === 2))).toEqual(new Array(60).fill(4));
  });
});
