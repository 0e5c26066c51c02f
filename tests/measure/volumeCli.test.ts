/**
 * `tissue-sheet measure --volume` through the command: voxel size from the option, ImageJ or
 * OME-XML metadata; every bad input exits 2 with one line `tissue-sheet: FILE: problem`.
 */
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { afterAll, beforeAll, describe, expect, it, vi } from 'vitest';
import { measureCommand } from '../../src/cli/measure';
import { writeTiff, type TiffPage } from './tiffWriter';
import { labelData, shellVolume, tubeVolume, volumePages, writeBigTiff, type SyntheticVolume } from './volumes';

let dir: string;
let shell: SyntheticVolume;
const f = (name: string) => join(dir, name);

/** A TIFF whose pages declare these sizes, with one 4-byte strip each (never decodable as such). */
function headerOnlyTiff(pages: { width: number; height: number; tile?: number }[]): Uint8Array {
  const ifdSize = 2 + 12 * 8 + 4;
  const bytes = new Uint8Array(16 + pages.length * ifdSize);
  const v = new DataView(bytes.buffer);
  bytes.set([0x49, 0x49]);
  v.setUint16(2, 42, true);
  v.setUint32(4, 16, true);
  pages.forEach((page, k) => {
    const at = 16 + k * ifdSize;
    const entries: [number, number, number][] = page.tile
      ? [
          [256, 4, page.width],
          [257, 4, page.height],
          [258, 3, 16],
          [259, 3, 1],
          [262, 3, 1],
          [322, 4, page.tile],
          [323, 4, page.tile],
          [324, 4, 8],
        ]
      : [
          [256, 4, page.width],
          [257, 4, page.height],
          [258, 3, 16],
          [259, 3, 1],
          [262, 3, 1],
          [273, 4, 8],
          [278, 4, page.height],
          [279, 4, 4],
        ];
    v.setUint16(at, entries.length, true);
    entries.forEach(([tag, type, value], e) => {
      const o = at + 2 + 12 * e;
      v.setUint16(o, tag, true);
      v.setUint16(o + 2, type, true);
      v.setUint32(o + 4, 1, true);
      if (type === 3) v.setUint16(o + 8, value, true);
      else v.setUint32(o + 8, value, true);
    });
    v.setUint32(at + 2 + 12 * entries.length, k + 1 < pages.length ? at + ifdSize : 0, true);
  });
  return bytes;
}

const IMAGEJ = (pages: number, unit = 'micron', spacing = '0.75') =>
  `ImageJ=1.54f\nimages=${pages}\nslices=${pages}\nunit=${unit}\n${spacing ? `spacing=${spacing}\n` : ''}loop=false\n`;
const OME = (pages: number, extra = '') =>
  `<?xml version="1.0" encoding="UTF-8"?><OME xmlns="http://www.openmicroscopy.org/Schemas/OME/2016-06"><Image ID="Image:0"><Pixels ID="Pixels:0" DimensionOrder="XYZCT" Type="uint16" SizeX="1" SizeY="1" SizeZ="${pages}" SizeC="1" SizeT="1" PhysicalSizeX="0.5" PhysicalSizeXUnit="µm" PhysicalSizeY="500" PhysicalSizeYUnit="nm" PhysicalSizeZ="0.75" ${extra}><TiffData/></Pixels></Image></OME>`;

beforeAll(() => {
  dir = mkdtempSync(join(tmpdir(), 'measure-volume-cli-'));
  shell = shellVolume({ voxel: { x: 0.5, y: 0.5, z: 0.75 }, a: 9, b: 8, c: 7, h: 3, sites: 24, seed: 2, margin: 2 });
  const labels = Array.from({ length: shell.sites }, (_, k) => 10 + k);
  const data = labelData(shell, labels, 16);
  const pages = (first: Partial<TiffPage> = {}, bits: 8 | 16 | 32 = 16, d: ArrayLike<number> & { subarray(a: number, b: number): ArrayLike<number> } = data) =>
    volumePages(shell, d, bits, first) as TiffPage[];
  const put = (name: string, bytes: Uint8Array | string) => writeFileSync(f(name), bytes);
  put('plain.tif', writeTiff(pages()));
  put('imagej.tif', writeTiff(pages({ description: IMAGEJ(shell.depth), xResolution: 2, yResolution: 2, resolutionUnit: 1 })));
  put('imagej-nm.tif', writeTiff(pages({ description: IMAGEJ(shell.depth, 'nm', '750'), xResolution: 0.002, yResolution: 0.002, resolutionUnit: 1 })));
  put('imagej-no-spacing.tif', writeTiff(pages({ description: IMAGEJ(shell.depth, 'um', ''), xResolution: 2, yResolution: 4, resolutionUnit: 1 })));
  for (const [name, spacing] of [
    ['zero', '0'],
    ['nan', 'nan'],
    ['negative', '-2'],
  ]) {
    put(
      `imagej-spacing-${name}.tif`,
      writeTiff(pages({ description: IMAGEJ(shell.depth, 'micron', spacing), xResolution: 2, yResolution: 2, resolutionUnit: 1 })),
    );
  }
  put('ome.tif', writeTiff(pages({ description: OME(shell.depth) }), false));
  put('lzw.tif', writeTiff(pages().map((p) => ({ ...p, compression: 5 as const }))));
  put('deflate32.tif', writeTiff(volumePages(shell, labelData(shell, labels, 32), 32).map((p) => ({ ...p, compression: 8 as const })) as TiffPage[], false));
  put('lumen.tif', writeTiff(pages({}, 16, labelData(shell, labels, 16, 999))));
  put('notes.txt', 'not a volume\n');
  put('one-page.tif', writeTiff(pages().slice(0, 1)));
  put('float.tif', writeTiff(pages().map((p) => ({ ...p, bitsPerSample: 32 as const, sampleFormat: 3 as const, data: Float32Array.from(p.data) }))));
  put('signed.tif', writeTiff(pages().map((p) => ({ ...p, sampleFormat: 2 as const }))));
  put('rgb.tif', writeTiff(pages().map((p) => ({ ...p, bitsPerSample: 8 as const, samplesPerPixel: 3, data: new Uint8Array(p.width * p.height * 3) }))));
  put('mixed.tif', writeTiff([...pages().slice(0, 2), { ...pages()[2], width: shell.width - 1, data: new Uint16Array((shell.width - 1) * shell.height) }]));
  put(
    'huge.tif',
    headerOnlyTiff([
      { width: 32768, height: 32768 },
      { width: 32768, height: 32768 },
    ]),
  );
  put(
    'huge-tiles.tif',
    headerOnlyTiff([
      { width: 64, height: 64, tile: 60000 },
      { width: 64, height: 64, tile: 60000 },
    ]),
  );
  put('big.tif', new Uint8Array([0x49, 0x49, 43, 0, 8, 0, 0, 0, 16, 0, 0, 0, 0, 0, 0, 0]));
  const plane = shell.width * shell.height;
  const slices = Array.from({ length: shell.depth }, (_, z) => data.subarray(z * plane, (z + 1) * plane));
  put('bigtiff-ome.tif', writeBigTiff(shell.width, shell.height, slices, OME(shell.depth)));
  const truncated = writeTiff(pages());
  put('truncated.tif', truncated.subarray(0, Math.floor(truncated.length * 0.6)));
  put('channels.tif', writeTiff(pages({ description: 'ImageJ=1.54f\nimages=4\nchannels=2\nslices=2\nunit=micron\nhyperstack=true\n', xResolution: 2 })));
  put('ome-two-images.tif', writeTiff(pages({ description: OME(Math.floor(shell.depth / 2)) + OME(shell.depth - Math.floor(shell.depth / 2)) })));
  put('ome-channels.tif', writeTiff(pages({ description: OME(shell.depth).replace('SizeC="1"', 'SizeC="2"') })));
  // A solid block of cells: the background is all one component (the outside), no lumen.
  const solid = new Uint16Array(shell.site.length);
  shell.site.forEach((s, i) => (solid[i] = s === -2 ? 0 : s === -1 ? 1 : s + 10));
  put('no-lumen.tif', writeTiff(pages({}, 16, solid)));
  const tube = tubeVolume({ width: 60, height: 60, depth: 40, voxel: { x: 0.5, y: 0.5, z: 1 }, inner: 7, outer: 13, sites: 24, seed: 8 });
  put(
    'tube.tif',
    writeTiff(
      volumePages(
        tube,
        labelData(
          tube,
          Array.from({ length: tube.sites }, (_, k) => k + 1),
          16,
        ),
        16,
      ) as TiffPage[],
    ),
  );
  mkdirSync(f('folder'));
}, 60_000);
afterAll(() => rmSync(dir, { recursive: true, force: true }));

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

const read = (name: string) => JSON.parse(readFileSync(f(name), 'utf8'));

describe('tissue-sheet measure --volume', () => {
  it('measures a volume with --voxel-size and writes the result (exit 0)', async () => {
    const { code, errors, log } = await run(['--volume', f('plain.tif'), '--out', f('plain.json'), '--voxel-size', '0.5,0.5,0.75']);
    expect(errors).toEqual([]);
    expect(code).toBe(0);
    expect(log.at(-1)).toMatch(/^done: 24 cells, 24 valid, [\d.]+ % scutoids, min contact [\d.]+ µm basal, [\d.]+ µm apical/);
    const r = read('plain.json');
    expect(r.software.name).toBe('tissue-sheet');
    expect(r.inputs.voxelSize).toEqual({ x: 0.5, y: 0.5, z: 0.75, source: 'option' });
    expect(r.inputs.voxelSizeDetail).toBe('--voxel-size');
    expect(r.inputs.layers.map((l: { name: string }) => l.name)).toEqual(['basal', 'apical']);
    expect(r.cells[0]).toMatchObject({ label: 10, valid: true, exclusion: null });
    expect(r.cells[0].neighbours).toHaveLength(2);
    expect(r.cells[0].areas).toHaveLength(2);
    expect(r.cells[0].volume).toBeGreaterThan(0);
  });

  it('reads the voxel size from ImageJ metadata (µm and nm) and from OME-XML (big-endian)', async () => {
    const reference = read('plain.json');
    for (const [file, source] of [
      ['imagej.tif', 'imagej'],
      ['imagej-nm.tif', 'imagej'],
      ['ome.tif', 'ome'],
    ]) {
      const { code, errors } = await run(['--volume', f(file), '--out', f(`${file}.json`)]);
      expect(errors).toEqual([]);
      expect(code).toBe(0);
      const r = read(`${file}.json`);
      expect(r.inputs.voxelSize.source).toBe(source);
      expect(r.inputs.voxelSize.x).toBeCloseTo(0.5, 9);
      expect(r.inputs.voxelSize.y).toBeCloseTo(0.5, 9);
      expect(r.inputs.voxelSize.z).toBeCloseTo(0.75, 9);
      expect(r.cells.map((c: { neighbours: number[][] }) => c.neighbours)).toEqual(reference.cells.map((c: { neighbours: number[][] }) => c.neighbours));
    }
  });

  it('reads a BigTIFF OME-TIFF (64-bit offsets)', async () => {
    const { code, errors } = await run(['--volume', f('bigtiff-ome.tif'), '--out', f('bigtiff.json')]);
    expect(errors).toEqual([]);
    expect(code).toBe(0);
    const r = read('bigtiff.json');
    expect(r.inputs.voxelSize.source).toBe('ome');
    expect(r.cells).toEqual(read('plain.json').cells);
  });

  it('takes ImageJ without spacing= as 1 unit between slices, and X and Y resolutions apart', async () => {
    const { code } = await run(['--volume', f('imagej-no-spacing.tif'), '--out', f('no-spacing.json')]);
    expect(code).toBe(0);
    const r = read('no-spacing.json');
    expect(r.inputs.voxelSize).toEqual({ x: 0.5, y: 0.25, z: 1, source: 'imagej' });
    expect(r.inputs.voxelSizeDetail).toMatch(/no spacing \(1 unit\)/);
  });

  it('lets --voxel-size override the metadata, with a warning', async () => {
    const { code, log } = await run(['--volume', f('imagej.tif'), '--out', f('override.json'), '--voxel-size', '1,1,1.5']);
    expect(code).toBe(0);
    const r = read('override.json');
    expect(r.inputs.voxelSize).toMatchObject({ x: 1, y: 1, z: 1.5, source: 'option' });
    expect(r.warnings[0]).toMatch(/--voxel-size 1,1,1.5 overrides the file's 0.5,0.5,0.75 µm/);
    expect(log.some((l) => l.startsWith('warning: --voxel-size'))).toBe(true);
    // Twice the voxel size: volumes x 8, areas x 4, the same neighbours.
    const reference = read('plain.json');
    expect(r.cells[3].volume).toBeCloseTo(8 * reference.cells[3].volume, 6);
    expect(r.cells[3].areas[0]).toBeCloseTo(4 * reference.cells[3].areas[0], 6);
    expect(r.cells.map((c: { neighbours: number[][] }) => c.neighbours)).toEqual(reference.cells.map((c: { neighbours: number[][] }) => c.neighbours));
  });

  it('decodes LZW and Deflate 32-bit volumes alike', async () => {
    const reference = read('plain.json');
    for (const file of ['lzw.tif', 'deflate32.tif']) {
      const { code, errors } = await run(['--volume', f(file), '--out', f(`${file}.json`), '--voxel-size', '0.5,0.5,0.75']);
      expect(errors).toEqual([]);
      expect(code).toBe(0);
      expect(read(`${file}.json`).cells).toEqual(reference.cells);
    }
  });

  it('takes a labelled lumen with --lumen-label, and --apical outside, --quartet-filter, --min-contact', async () => {
    const { code } = await run([
      '--volume',
      f('lumen.tif'),
      '--out',
      f('lumen.json'),
      '--voxel-size',
      '0.5,0.5,0.75',
      '--lumen-label',
      '999',
      '--apical',
      'outside',
      '--quartet-filter',
      '--min-contact',
      '0.8',
    ]);
    expect(code).toBe(0);
    const r = read('lumen.json');
    expect(r.inputs.options).toEqual({ apical: 'outside', lumenLabel: 999, minContact: 0.8, minContactSource: 'option', quartetFilter: true });
    expect(r.inputs.layers.map((l: { faces: string }) => l.faces)).toEqual(['lumen', 'outside']);
    expect(r.quartetFilter).not.toBeNull();
    expect(r.cells.map((c: { label: number }) => c.label)).not.toContain(999);
    expect(
      (await run(['--volume', f('lumen.tif'), '--out', f('lumen2.json'), '--voxel-size', '0.5,0.5,0.75', '--lumen-label', '999', '--quartets'])).code,
    ).toBe(0);
    expect(read('lumen2.json').inputs.options.quartetFilter).toBe(true);
  });

  it('--compare on an open tube: the model of the fitted tube beside the measurement', async () => {
    const { code, errors, log } = await run([
      '--volume',
      f('tube.tif'),
      '--out',
      f('tube.json'),
      '--voxel-size',
      '0.5,0.5,1',
      '--compare',
      '--realizations',
      '3',
      '--seed',
      '5',
    ]);
    expect(errors).toEqual([]);
    expect(code).toBe(0);
    const r = read('tube.json');
    expect(r.comparison).toMatchObject({ method: 'exact', realizations: 3, seed: 5, geometry: { kind: 'tube', seededLayer: 'apical' } });
    expect(r.comparison.geometry.innerRadius).toBeCloseTo(7, 0);
    expect(r.comparison.model.percentScutoids.ci95).toHaveLength(2);
    expect(log.some((l) => /^model: tube of radius [\d.]+ to [\d.]+ µm, [\d.]+ µm long; Voronoi \d+ matches best/.test(l))).toBe(true);
  });

  it('--compare on a closed shell: the model on its own surface meshes', async () => {
    const { code, errors, log } = await run([
      '--volume',
      f('plain.tif'),
      '--out',
      f('compare.json'),
      '--voxel-size',
      '0.5,0.5,0.75',
      '--compare',
      '--realizations',
      '2',
    ]);
    expect(errors).toEqual([]);
    expect(code).toBe(0);
    const r = read('compare.json');
    expect(r.comparison).toMatchObject({ method: 'exact', realizations: 2, seed: 1, geometry: { kind: 'mesh', seededLayer: 'apical' } });
    expect(r.comparison.geometry.projection.alongNormal + r.comparison.geometry.projection.parallel).toBe(2 * 24);
    expect(log.some((l) => /^model: the shell's own surfaces \(\d+ and \d+ triangles\); Voronoi \d+ matches best/.test(l))).toBe(true);
  });

  const bad: [string, string[], RegExp][] = [
    ['a file that is not a TIFF', ['notes.txt'], /notes\.txt: not a TIFF file/],
    ['a TIFF with one page', ['one-page.tif'], /one-page\.tif: has one page; a label volume needs at least two pages/],
    ['floating-point samples', ['float.tif'], /float\.tif: page 1 of \d+: 32-bit floating point samples; labels must be 8-, 16- or 32-bit unsigned integers/],
    ['signed samples', ['signed.tif'], /signed\.tif: page 1 of \d+: 16-bit signed samples/],
    ['RGB pages', ['rgb.tif'], /rgb\.tif: page 1 of \d+: 3 samples per pixel/],
    ['pages of different sizes', ['mixed.tif'], /mixed\.tif: page 3 of 3: \d+ x \d+ pixels, page 1 has \d+ x \d+; every slice must have the same size/],
    [
      'a header declaring more than 2^30 voxels',
      ['huge.tif'],
      /huge\.tif: the header declares 32768 x 32768 pixels per page and at least 2 pages, over the limit of 1073741824 voxels/,
    ],
    ['tiles declared far larger than the page', ['huge-tiles.tif'], /huge-tiles\.tif: page 1 of 2: tiles of 60000 x 60000 pixels, larger than the page/],
    ['a BigTIFF cut short', ['big.tif'], /big\.tif: corrupt TIFF \(page 1 starts outside the file\)/],
    ['a truncated file', ['truncated.tif'], /truncated\.tif: .*corrupt TIFF/],
    ['an ImageJ hyperstack with two channels', ['channels.tif'], /channels\.tif: an ImageJ hyperstack with 2 channels; save the label channel alone/],
    ['an OME-TIFF with two channels', ['ome-channels.tif'], /ome-channels\.tif: an OME-TIFF with 2 channels/],
    ['an OME-TIFF of two images', ['ome-two-images.tif'], /ome-two-images\.tif: its OME-XML says SizeZ=\d+ but it has \d+ pages \(2 images\); save one image/],
    ['a volume without a lumen', ['no-lumen.tif'], /no-lumen\.tif: no lumen: .*--lumen-label/],
    ['a lumen label no voxel carries', ['plain.tif', '--lumen-label', '4321'], /plain\.tif: no voxel carries --lumen-label 4321/],
    ['a missing file', ['nowhere.tif'], /nowhere\.tif: no such file$/],
    ['a directory', ['folder'], /folder: is a directory/],
  ];
  for (const [what, [file, ...more], message] of bad) {
    it(`refuses ${what}: exit 2, one line naming the file`, async () => {
      const { code, errors } = await run(['--volume', f(file), '--out', f('bad.json'), '--voxel-size', '0.5,0.5,0.75', ...more]);
      expect(code).toBe(2);
      expect(errors).toHaveLength(1);
      expect(errors[0]).toMatch(/^tissue-sheet: /);
      expect(errors[0]).not.toContain('\n');
      expect(errors[0]).toMatch(message);
    });
  }

  it('refuses a volume without a voxel size, and bad or misplaced options (exit 2)', async () => {
    const cases: [string[], RegExp][] = [
      [['--volume', f('plain.tif'), '--out', f('x.json')], /plain\.tif: no voxel size in the file .*give --voxel-size X,Y,Z/],
      // A spacing the file gives that is no distance is refused, not read as 1 unit (it scales every volume).
      [
        ['--volume', f('imagej-spacing-zero.tif'), '--out', f('x.json')],
        /imagej-spacing-zero\.tif: ImageJ spacing=0 is not a distance > 0 .*give --voxel-size/,
      ],
      [['--volume', f('imagej-spacing-nan.tif'), '--out', f('x.json')], /imagej-spacing-nan\.tif: ImageJ spacing=nan is not a distance > 0/],
      [['--volume', f('imagej-spacing-negative.tif'), '--out', f('x.json')], /imagej-spacing-negative\.tif: ImageJ spacing=-2 is not a distance > 0/],
      [['--volume', f('plain.tif'), '--out', f('x.json'), '--voxel-size', '0.5,0.5'], /^tissue-sheet: --voxel-size: needs three numbers > 0/],
      [['--volume', f('plain.tif'), '--out', f('x.json'), '--voxel-size', '0.5,0,1'], /--voxel-size: needs three numbers > 0/],
      [['--volume', f('plain.tif'), '--out', f('x.json'), '--voxel-size', '1,1,1', '--apical', 'top'], /--apical: needs lumen or outside/],
      [['--volume', f('plain.tif'), '--out', f('x.json'), '--voxel-size', '1,1,1', '--pixel-size', '1'], /--pixel-size: is for layer images, not --volume/],
      [['--volume', f('plain.tif'), f('imagej.tif'), '--out', f('x.json')], /imagej\.tif: with --volume, give no layer files/],
      [[f('plain.tif'), '--out', f('x.json'), '--voxel-size', '1,1,1'], /--voxel-size: is for --volume VOLUME\.tif only/],
      [['--volume', f('plain.tif'), '--out', f('plain.tif'), '--voxel-size', '1,1,1'], /plain\.tif: is also --out/],
      [['--volume', f('plain.tif'), '--voxel-size', '1,1,1'], /--out: missing/],
      [['--volume', f('plain.tif'), '--volume', f('imagej.tif'), '--out', f('x.json')], /--volume: given twice/],
    ];
    for (const [args, message] of cases) {
      const { code, errors } = await run(args);
      expect(code).toBe(2);
      expect(errors).toHaveLength(1);
      expect(errors[0]).toMatch(message);
    }
  });

  it('runs as a process: exit 2 with one last stderr line, the only one starting tissue-sheet:', () => {
    const script = join(dir, 'cli.mjs');
    writeFileSync(
      script,
      `import { main } from ${JSON.stringify(join(process.cwd(), 'src/cli/main.ts'))};\nprocess.exitCode = await main(process.argv.slice(2));\n`,
    );
    const bad = spawnSync(process.execPath, ['--import', 'tsx', script, 'measure', '--volume', f('huge.tif'), '--out', f('p.json'), '--voxel-size', '1,1,1'], {
      encoding: 'utf8',
      cwd: process.cwd(),
    });
    expect(bad.status).toBe(2);
    const lines = bad.stderr.trim().split('\n');
    expect(lines.at(-1)).toMatch(/^tissue-sheet: .*huge\.tif: the header declares/);
    expect(lines.filter((l) => l.startsWith('tissue-sheet:'))).toHaveLength(1);
    const good = spawnSync(process.execPath, ['--import', 'tsx', script, 'measure', '--volume', f('imagej.tif'), '--out', f('p.json')], {
      encoding: 'utf8',
      cwd: process.cwd(),
    });
    expect(good.status).toBe(0);
    expect(JSON.parse(readFileSync(f('p.json'), 'utf8')).inputs.voxelSize.source).toBe('imagej');
  }, 60_000);
});
