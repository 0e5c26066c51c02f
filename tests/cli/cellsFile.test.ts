/**
 * Large results: the per-cell lists in a binary side file (README, "Result JSON"), read back
 * by the project's reader into exactly the JSON a small run writes; the up-front refusal of a
 * run whose cells do not fit the memory budget.
 */
import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { errorLine, exitCodeFor } from '../../src/cli/errors';
import { cellsFilePath, MAX_CELL_RECORDS_IN_JSON } from '../../src/cli/output';
import { checkRunnable, computeBudget } from '../../src/cli/prepare';
import { validateConfig } from '../../src/core/config';
import { readResultFile } from '../../src/node/resultFile';
import { CELLS_FILE_FORMAT, decodeCellsFile, type CellsFileRecord } from '../../src/run/cellTables';

const bin = join(__dirname, 'fromSource.mjs');
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-cells-'));
const cli = (args: string[]) => spawnSync(process.execPath, [bin, ...args], { encoding: 'utf8', env: process.env });

function writeJson(name: string, value: unknown): string {
  const path = join(dir, name);
  writeFileSync(path, JSON.stringify(value));
  return path;
}

/** The result without its timings (they differ between two runs). */
function withoutTimings(result: Record<string, unknown>): unknown {
  return JSON.parse(JSON.stringify(result, (key, value) => (key === 'timings' || /Ms$/.test(key) ? undefined : value)));
}

const tube = {
  surface: { kind: 'tube', radius: 40, length: 400 },
  resolution: 128,
  cells: 40,
  seed: 4,
  engine: 'exact',
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 1.8, layers: 1 },
};
const plane = {
  surface: { kind: 'plane', width: 200, height: 160, periodicX: true, periodicY: true },
  resolution: 128,
  cells: 60,
  engine: 'exact',
  lloyd: { maxIterations: 3 },
  sheet: { thickness: 5 },
};

describe('tissue-sheet run --cells-file', () => {
  it('writes the cells to RESULT.cells.bin; read back, the result equals the JSON-only one bit for bit', () => {
    const config = writeJson('tube.json', tube);
    const plain = join(dir, 'plain.json');
    const split = join(dir, 'split.json');
    expect(cli(['run', config, '--out', plain]).status).toBe(0);
    const run = cli(['run', config, '--out', split, '--cells-file']);
    expect(run.status, run.stderr).toBe(0);
    expect(run.stderr).toContain(cellsFilePath(split));

    const json = JSON.parse(readFileSync(split, 'utf8'));
    expect(json.cells).toBeNull();
    expect(json.surfaces.map((s: { cells: unknown }) => s.cells)).toEqual([null, null]);
    expect(json.analyses.map((a: { cells: unknown }) => a.cells)).toEqual([null]);
    expect(json.cellsFile.path).toBe('split.cells.bin');
    expect(json.cellsFile.format).toBe(CELLS_FILE_FORMAT);
    expect(json.cellsFile.tables.map((t: { of: string }) => t.of)).toEqual(['cells', 'surfaces[0].cells', 'surfaces[1].cells', 'analyses[0].cells']);
    expect(readFileSync(cellsFilePath(split)).subarray(0, 8).toString('latin1')).toBe('TSCELLS1');

    const { result, tables } = readResultFile(split, { records: true });
    expect(tables!.cells.count).toBe(40);
    expect(withoutTimings(result as unknown as Record<string, unknown>)).toEqual(withoutTimings(JSON.parse(readFileSync(plain, 'utf8'))));
    // A result written as JSON alone reads back as it is.
    expect(readResultFile(plain).tables).toBeNull();
  });

  it("a plane's two surfaces share their adjacency: those columns are written once", () => {
    const out = join(dir, 'plane.json');
    expect(cli(['run', writeJson('plane-config.json', plane), '--out', out, '--cells-file']).status).toBe(0);
    const record = JSON.parse(readFileSync(out, 'utf8')).cellsFile as CellsFileRecord;
    const [seeded, other] = record.tables;
    for (const name of ['neighbourOffsets', 'neighbourIds', 'neighbourLengths', 'area']) expect(other.columns[name].offset).toBe(seeded.columns[name].offset);
    expect(other.columns.position.offset).not.toBe(seeded.columns.position.offset); // z differs
    const { tables } = readResultFile(out);
    expect(Array.from(tables!.surfaces[0].position.filter((_, k) => k % 3 === 2))).toEqual(new Array(60).fill(5));
  });

  it('refuses a side file that does not match its record (size, header, a column outside the file)', () => {
    const out = join(dir, 'plane.json');
    const record = JSON.parse(readFileSync(out, 'utf8')).cellsFile as CellsFileRecord;
    const bytes = new Uint8Array(readFileSync(cellsFilePath(out)));
    expect(() => decodeCellsFile(record, bytes.subarray(0, bytes.length - 8))).toThrow(/bytes/);
    const wrong = bytes.slice();
    wrong[0] = 0;
    expect(() => decodeCellsFile(record, wrong)).toThrow(/TSCELLS1/);
    const outside = JSON.parse(JSON.stringify(record));
    outside.tables[0].columns.area.offset = record.bytes;
    expect(() => decodeCellsFile(outside, bytes)).toThrow(/outside/);
  });

  it('large runs use the side file without being asked (above 100,000 cell records)', () => {
    expect(MAX_CELL_RECORDS_IN_JSON).toBe(100_000);
  });

  it('never writes over a file that is not a side file of ours', () => {
    const out = join(dir, 'taken.json');
    writeFileSync(cellsFilePath(out), "someone else's data");
    const run = cli(['run', writeJson('tube2.json', tube), '--out', out, '--cells-file']);
    expect(run.status).toBe(2);
    expect(run.stderr).toMatch(/taken\.cells\.bin/);
    expect(readFileSync(cellsFilePath(out), 'utf8')).toBe("someone else's data");
  });
});

describe('a run whose cells do not fit is refused up front', () => {
  it('16 million cells: one line naming cells, exit 2, before anything is computed', () => {
    const config = validateConfig({
      surface: { kind: 'plane', width: 10000, height: 10000, periodicX: true, periodicY: true },
      resolution: 16384,
      cells: 16_000_000,
      engine: 'exact',
      sheet: { thickness: 5, adjacency: 'exact' },
    });
    const budget = { ...computeBudget(16384, false), maxBytes: 8 * 2 ** 30 };
    let error: unknown;
    try {
      checkRunnable(config, budget);
    } catch (e) {
      error = e;
    }
    expect(exitCodeFor(error)).toBe(2);
    const line = errorLine(error);
    expect(line).toMatch(/^cells: this run needs about [\d.]+ GiB of memory \(16000000 cells on 2 surfaces/);
    expect(line).not.toMatch(/\n/);
    // A million cells fit a 4 GiB budget (measured: 1.5 GB peak with one thread, docs/benchmark.md).
    const million = validateConfig({ ...config, resolution: 4100, cells: 1_000_000 });
    expect(checkRunnable(million, { ...budget, maxBytes: 4 * 2 ** 30 }).bytes).toBeLessThan(2 * 2 ** 30);
  });
});
