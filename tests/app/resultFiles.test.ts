import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, statSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { basename, join } from 'node:path';
import { beforeAll, describe, expect, it } from 'vitest';
import { openFiles, WORKER_JSON_BYTES, type GivenFile, type WholeFileOpener } from '../../src/app/model/resultFiles';

/**
 * The page opens a result written with a cells side file (issue 27): the same configuration is
 * run by the CLI twice, once with its cells in the JSON and once with --cells-file; the page's
 * reading of the pair must equal the JSON result (timings aside), and one file of the pair
 * alone is refused naming the other.
 */
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-result-files-'));
const config = {
  surface: { kind: 'tube', radius: 30, length: 300 },
  resolution: 128,
  cells: 60,
  seed: 4,
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 2, layers: 1 },
};

function given(path: string, name = basename(path)): GivenFile {
  return {
    name,
    size: statSync(path).size,
    text: async () => readFileSync(path, 'utf8'),
    arrayBuffer: async () => {
      const bytes = readFileSync(path);
      return bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
    },
  };
}

const withoutTimings = (value: unknown) => JSON.parse(JSON.stringify(value), (key, v) => (key === 'timings' || key.endsWith('Ms') ? undefined : v));

beforeAll(() => {
  writeFileSync(join(dir, 'cfg.json'), JSON.stringify(config));
  for (const args of [
    ['--out', join(dir, 'plain.json')],
    ['--out', join(dir, 'big.json'), '--cells-file'],
  ]) {
    const run = spawnSync(process.execPath, [join(__dirname, '../cli/fromSource.mjs'), 'run', join(dir, 'cfg.json'), ...args], { encoding: 'utf8' });
    if (run.status !== 0) throw new Error(run.stderr);
  }
}, 120_000);

describe('opening a result with its cells side file', () => {
  it('the pair (in either order) reads back as the JSON result', async () => {
    const plain = JSON.parse(readFileSync(join(dir, 'plain.json'), 'utf8'));
    const side = JSON.parse(readFileSync(join(dir, 'big.json'), 'utf8'));
    expect(side.cells).toBeNull();
    expect(side.cellsFile.path).toBe('big.cells.bin');
    for (const order of [
      [given(join(dir, 'big.json')), given(join(dir, 'big.cells.bin'))],
      [given(join(dir, 'big.cells.bin')), given(join(dir, 'big.json'))],
    ]) {
      const { file, name } = await openFiles(order);
      expect(name).toBe('big.json + big.cells.bin');
      expect(file.kind).toBe('result');
      if (file.kind !== 'result') return;
      expect(withoutTimings(file.output.result)).toEqual(withoutTimings(plain));
      expect(file.output.labelImages).toHaveLength(plain.surfaces.length + 1);
    }
  });

  it('one file of the pair alone, or the wrong side file: refused, naming the missing file', async () => {
    await expect(openFiles([given(join(dir, 'big.json'))])).rejects.toThrow(
      'big.json: its cells are in the side file big.cells.bin (written beside it by tissue-sheet run); choose or drop both files together.',
    );
    await expect(openFiles([given(join(dir, 'big.cells.bin'))])).rejects.toThrow(
      /^big\.cells\.bin is a cells side file: choose it together with its result JSON \(big\.json/,
    );
    await expect(openFiles([given(join(dir, 'big.json')), given(join(dir, 'big.cells.bin'), 'other.cells.bin')])).rejects.toThrow(
      'big.json: its cells are in big.cells.bin, not in other.cells.bin; choose or drop big.json with big.cells.bin.',
    );
    await expect(openFiles([given(join(dir, 'plain.json')), given(join(dir, 'big.cells.bin'))])).rejects.toThrow(/plain\.json has no cellsFile/);
  });

  it('a truncated side file is refused with the sizes', async () => {
    const bytes = readFileSync(join(dir, 'big.cells.bin'));
    writeFileSync(join(dir, 'cut.cells.bin'), bytes.subarray(0, bytes.length - 8));
    await expect(openFiles([given(join(dir, 'big.json')), given(join(dir, 'cut.cells.bin'), 'big.cells.bin')])).rejects.toThrow(
      new RegExp(`big\\.json with big\\.cells\\.bin: big\\.cells\\.bin: ${bytes.length - 8} bytes where the result says ${bytes.length}`),
    );
  });

  it('a result JSON whose cells name no cell of the result, or have no position, is refused naming the cell', async () => {
    const plain = JSON.parse(readFileSync(join(dir, 'plain.json'), 'utf8'));
    const edited = async (name: string, edit: (result: typeof plain) => void) => {
      const copy = JSON.parse(JSON.stringify(plain));
      edit(copy);
      writeFileSync(join(dir, name), JSON.stringify(copy));
      return openFiles([given(join(dir, name))]);
    };
    await expect(edited('far.json', (r) => (r.cells[2].neighbours[0].id = 60))).rejects.toThrow(
      'far.json: cells[2].neighbours[0]: id 60 is not a cell of the 60.',
    );
    await expect(edited('neg.json', (r) => (r.surfaces[0].cells[5].neighbours[1].id = -1))).rejects.toThrow(
      'neg.json: surfaces[0].cells[5].neighbours[1]: id -1 is not a cell of the 60.',
    );
    await expect(edited('nan.json', (r) => (r.surfaces[1].cells[0].surface = [null, 3]))).rejects.toThrow(
      'nan.json: surfaces[1].cells[0].surface: expected [u, v], two finite numbers.',
    );
    await expect(edited('id.json', (r) => (r.surfaces[0].cells[7].id = 8))).rejects.toThrow(
      'id.json: surfaces[0].cells[7]: expected id 7, surface [u, v] and neighbours.',
    );
  });

  it("every surface's grid is sized like the result's, and the analyses are checked, before anything is allocated", async () => {
    const plain = JSON.parse(readFileSync(join(dir, 'plain.json'), 'utf8'));
    const edited = async (name: string, edit: (result: typeof plain) => void) => {
      const copy = JSON.parse(JSON.stringify(plain));
      edit(copy);
      writeFileSync(join(dir, name), JSON.stringify(copy));
      return openFiles([given(join(dir, name))]);
    };
    const huge = (size: number) => (r: typeof plain) => {
      r.surfaces[0].grid.width = size;
      r.surfaces[0].grid.height = size;
    };
    const sizes = /^[a-z0-9]+\.json: surfaces\[0\]\.grid: width and height: positive integers, at most 16777216 texels in all\.$/;
    await expect(edited('huge.json', huge(12000))).rejects.toThrow(sizes);
    await expect(edited('huger.json', huge(100000))).rejects.toThrow(sizes);
    await expect(edited('neg.json', (r) => (r.surfaces[0].grid.width = -5))).rejects.toThrow(sizes);
    await expect(edited('texel.json', (r) => (r.surfaces[1].grid.texelX = 0))).rejects.toThrow(/^texel\.json: surfaces\[1\]\.grid: texelX, texelY/);
    await expect(edited('nosurf.json', (r) => (r.surfaces = []))).rejects.toThrow(/^nosurf\.json: surfaces: expected/);
    await expect(edited('noana.json', (r) => (r.analyses = []))).rejects.toThrow(/^noana\.json: analyses: expected/);
    await expect(edited('nosum.json', (r) => (r.analyses[0].summary = null))).rejects.toThrow(
      'nosum.json: analyses[0].summary: expected the analysis summary (an object).',
    );
    await expect(edited('pct.json', (r) => (r.analyses[0].summary.percentScutoids = 'x'))).rejects.toThrow(
      'pct.json: analyses[0].summary.percentScutoids: expected a number.',
    );
    await expect(edited('short.json', (r) => (r.analyses[0].cells = r.analyses[0].cells.slice(0, 3)))).rejects.toThrow(
      'short.json: analyses[0].cells: expected 60 cell records, one per cell.',
    );
  });

  it('a plain result JSON still opens alone', async () => {
    const { file } = await openFiles([given(join(dir, 'plain.json'))]);
    expect(file.kind).toBe('result');
  });

  it('a JSON over WORKER_JSON_BYTES chosen alone goes whole to the worker; a smaller one, or one with a side file, does not', async () => {
    const asked: string[] = [];
    const whole: WholeFileOpener = async (json, name) => {
      asked.push(name);
      return openFiles([json]).then((opened) => opened.file);
    };
    const plain = given(join(dir, 'plain.json'));
    const large = { ...plain, size: WORKER_JSON_BYTES + 1 };
    expect((await openFiles([large], undefined, whole)).file.kind).toBe('result');
    expect(asked).toEqual(['plain.json']);
    await openFiles([plain], undefined, whole);
    expect(asked).toEqual(['plain.json']);
    const side = given(join(dir, 'big.cells.bin'));
    const pair = await openFiles([{ ...given(join(dir, 'big.json')), size: WORKER_JSON_BYTES + 1 }, side], undefined, whole);
    expect(pair.name).toBe('big.json + big.cells.bin');
    expect(asked).toEqual(['plain.json']);
  });
});
