import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { encode } from 'fast-png';
import { measureCommand } from '../../src/cli/measure';
import { hexLattice, png16, rasterizeVoronoi } from './images';
import { writeTiff } from './tiffWriter';

let dir: string;
const hex = hexLattice(6, 5, 20);
const image = rasterizeVoronoi(
  hex.width,
  hex.height,
  hex.sites,
  hex.sites.map((_, i) => i + 1),
  true,
);
const page = { width: image.width, height: image.height, bitsPerSample: 16 as const, data: image.data };

beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'measure-cli-'));
  const put = (name: string, bytes: Uint8Array | string) => writeFileSync(join(dir, name), bytes);
  put('basal.png', png16(image));
  put('apical.png', png16(image));
  put('short.png', png16({ width: image.width, height: image.height - 1, data: image.data.subarray(0, image.width * (image.height - 1)) }));
  put('zeros.png', png16({ width: 8, height: image.height, data: new Uint16Array(8 * image.height) }));
  // Two cells side by side, each touching the open top and bottom borders: none is valid.
  const halves = new Uint16Array(16 * 16).map((_, k) => (k % 16 < 8 ? 1 : 2));
  put('halves.png', png16({ width: 16, height: 16, data: halves }));
  put('notes.txt', 'these are not pixels\n');
  put('float.tif', writeTiff([{ ...page, bitsPerSample: 32, sampleFormat: 3, data: Float32Array.from(image.data) }]));
  put('rgb.png', encode({ width: 4, height: image.height, data: new Uint8Array(4 * image.height * 3), depth: 8, channels: 3 }));
  put('rgb.tif', writeTiff([{ ...page, bitsPerSample: 8, samplesPerPixel: 3, data: new Uint8Array(image.width * image.height * 3) }]));
  put('one-page.tif', writeTiff([page]));
  put('stack.tif', writeTiff([page, page], false));
  put('mixed-bits.tif', writeTiff([page, { ...page, bitsPerSample: 8, data: Uint8Array.from(image.data, (v) => v & 255) }]));
  mkdirSync(join(dir, 'folder'));
});
afterAll(() => rmSync(dir, { recursive: true, force: true }));

/** Runs the command in-process; returns the exit code and what went to stderr. */
async function run(args: string[]): Promise<{ code: number; errors: string[]; log: string[] }> {
  const errors: string[] = [];
  const spy = vi.spyOn(console, 'error').mockImplementation((...parts: unknown[]) => void errors.push(parts.join(' ')));
  const log: string[] = [];
  try {
    const code = await measureCommand(args, (line) => log.push(line));
    return { code, errors, log };
  } finally {
    spy.mockRestore();
  }
}

const f = (name: string) => join(dir, name);

describe('tissue-sheet measure', () => {
  it('with no valid cell: exit 0, a warning, and "no % scutoids", never "NaN %"', async () => {
    const { code, log } = await run([f('halves.png'), f('halves.png'), '--out', f('none-valid.json'), '--pixel-size', '1']);
    expect(code).toBe(0);
    expect(log.join('\n')).toContain('warning: no valid cell');
    expect(log.at(-1)).toMatch(/^done: 2 cells, 0 valid, no % scutoids \(no valid cell\) over 2 layers/);
    expect(log.join('\n')).not.toMatch(/NaN/);
  });

  it('measures two PNG layers and writes the result JSON (exit 0)', async () => {
    const out = f('result.json');
    const { code, errors, log } = await run([f('basal.png'), f('apical.png'), '--out', out, '--pixel-size', '0.5', '--periodic-x']);
    expect(errors).toEqual([]);
    expect(code).toBe(0);
    expect(log.at(-1)).toMatch(/^done: 30 cells, 18 valid, 0\.0 % scutoids over 2 layers/);
    const result = JSON.parse(readFileSync(out, 'utf8'));
    expect(result.kind).toBe('measured');
    expect(result.software.name).toBe('tissue-sheet');
    expect(result.inputs.files.map((x: { name: string }) => x.name)).toEqual([f('basal.png'), f('apical.png')]);
    expect(result.inputs.options).toEqual({ periodicX: true, minContact: null, minContactSource: 'default' });
  });

  it('replaces a previous result of its own, and anything else only with --force', async () => {
    const out = f('again.json');
    for (let k = 0; k < 2; k++) expect((await run([f('basal.png'), f('apical.png'), '--out', out, '--pixel-size', '1'])).code).toBe(0);
    writeFileSync(out, 'precious notes');
    expect((await run([f('basal.png'), f('apical.png'), '--out', out, '--pixel-size', '1'])).code).toBe(2);
    expect(readFileSync(out, 'utf8')).toBe('precious notes');
    expect((await run([f('basal.png'), f('apical.png'), '--out', out, '--pixel-size', '1', '--force'])).code).toBe(0);
    expect(JSON.parse(readFileSync(out, 'utf8')).kind).toBe('measured');
  });

  it('measures a two-page 3D TIFF (big-endian)', async () => {
    const { code, errors } = await run([f('stack.tif'), '--out', f('stack.json'), '--pixel-size=1']);
    expect(errors).toEqual([]);
    expect(code).toBe(0);
    expect(JSON.parse(readFileSync(f('stack.json'), 'utf8')).inputs.layers).toHaveLength(2);
  });

  const bad: [string, string[], RegExp][] = [
    [
      'layers of different heights',
      ['basal.png', 'short.png'],
      new RegExp(`short\\.png: height ${image.height - 1} differs from the first layer's ${image.height} .*same height`),
    ],
    ['an image without labels', ['basal.png', 'zeros.png'], /zeros\.png: no labels \(every pixel is 0\)$/],
    ['a file that is not an image', ['notes.txt', 'basal.png'], /notes\.txt: not a PNG or TIFF image/],
    ['a float TIFF', ['basal.png', 'float.tif'], /float\.tif: unsupported pixel type: 32-bit floating point/],
    ['an RGB PNG', ['rgb.png', 'basal.png'], /rgb\.png: unsupported pixel type: 8-bit RGB colour/],
    ['an RGB TIFF', ['basal.png', 'rgb.tif'], /rgb\.tif: unsupported pixel type: 3 samples per pixel/],
    ['a 3D stack with one page', ['one-page.tif'], /one-page\.tif: a 3D stack with one page/],
    ['a 3D stack of 16- and 8-bit pages', ['mixed-bits.tif'], /mixed-bits\.tif: page 2: 8-bit, page 1 is 16-bit; every page must have the same type/],
    ['a single 2D image', ['basal.png'], /basal\.png: one 2D image; give a 3D TIFF/],
    ['a missing file', ['basal.png', 'nowhere.png'], /nowhere\.png: no such file$/],
    ['a directory', ['basal.png', 'folder'], /folder: is a directory/],
    ['a 3D stack among 2D files', ['basal.png', 'stack.tif'], /stack\.tif: a 3D stack of 2 pages among several files/],
  ];
  for (const [what, files, message] of bad) {
    it(`refuses ${what}: exit 2, one line naming the file`, async () => {
      const { code, errors } = await run([...files.map(f), '--out', f('bad.json'), '--pixel-size', '1']);
      expect(code).toBe(2);
      expect(errors).toHaveLength(1);
      expect(errors[0]).toMatch(/^tissue-sheet: /);
      expect(errors[0]).not.toContain('\n');
      expect(errors[0]).toMatch(message);
    });
  }

  it('refuses a missing pixel size, bad options and --out equal to an input (exit 2)', async () => {
    const cases: [string[], RegExp][] = [
      [[f('basal.png'), f('apical.png'), '--out', f('x.json')], /basal\.png: no pixel size in the metadata; give --pixel-size/],
      [[f('basal.png'), f('apical.png'), '--out', f('x.json'), '--pixel-size', '-1'], /^tissue-sheet: --pixel-size: needs a number > 0/],
      [[f('basal.png'), f('apical.png'), '--pixel-size', '1'], /^tissue-sheet: --out: missing/],
      [[f('basal.png'), f('apical.png'), '--out', f('x.json'), '--bogus'], /--bogus: unknown option/],
      // Options that would be taken silently the wrong way.
      [[f('basal.png'), f('apical.png'), '--out', f('x.json'), '--pixel-size', '0x10'], /--pixel-size: needs a number > 0 \(got "0x10"\)/],
      [[f('basal.png'), f('apical.png'), '--out', f('x.json'), '--pixel-size', '1', '--compare=false'], /--compare: takes no value/],
      [[f('basal.png'), f('apical.png'), '--out', f('x.json'), '--pixel-size', '1', '--realizations', '3'], /--realizations: is for --compare/],
      [[f('basal.png'), f('apical.png'), '--out', f('apical.png'), '--pixel-size', '1'], /apical\.png: is also --out/],
      [
        [f('basal.png'), f('apical.png'), '--out', f('notes.txt'), '--pixel-size', '1'],
        /--out .*notes\.txt: exists and is not a tissue-sheet result; pass --force/,
      ],
      // Checked before the layers are read: a measurement is never thrown away for want of a directory.
      [
        [f('basal.png'), f('apical.png'), '--out', join(dir, 'no-such-dir', 'x.json'), '--pixel-size', '1'],
        /--out .*x\.json: the directory .*no-such-dir does not exist; create it or give another path$/,
      ],
    ];
    for (const [args, message] of cases) {
      const { code, errors } = await run(args);
      expect(code).toBe(2);
      expect(errors).toHaveLength(1);
      expect(errors[0]).toMatch(message);
    }
  });

  it('runs as a process through the CLI entry point (exit code and one stderr line)', () => {
    const script = join(dir, 'cli.mjs');
    writeFileSync(
      script,
      `import { main } from ${JSON.stringify(join(process.cwd(), 'src/cli/main.ts'))};\nprocess.exitCode = await main(process.argv.slice(2));\n`,
    );
    const bad = spawnSync(process.execPath, ['--import', 'tsx', script, 'measure', f('basal.png'), f('short.png'), '--out', f('p.json'), '--pixel-size', '1'], {
      encoding: 'utf8',
      cwd: process.cwd(),
    });
    expect(bad.status).toBe(2);
    expect(bad.stderr.trim().split('\n')).toEqual([expect.stringMatching(/^tissue-sheet: .*short\.png: height \d+ differs/)]);
    const good = spawnSync(
      process.execPath,
      ['--import', 'tsx', script, 'measure', f('basal.png'), f('apical.png'), '--out', f('p.json'), '--pixel-size', '1'],
      {
        encoding: 'utf8',
        cwd: process.cwd(),
      },
    );
    expect(good.status).toBe(0);
    expect(JSON.parse(readFileSync(f('p.json'), 'utf8')).analyses[0].summary.cells).toBe(30);
  }, 60_000);
});
