/**
 * Bad-input corpus: configs, sweep specs, runs files, meshes, images, shard and merge arguments.
 * Every case goes through the code the CLI runs and must end as the CLI ends it: exit code 2
 * (exitCodeFor), one line (errorLine) naming the field or file, no stack trace. In process, so
 * the corpus stays fast; cli.test.ts and shard.test.ts check the same path end to end.
 */
import { mkdirSync, mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { encode } from 'fast-png';
import { describe, expect, it } from 'vitest';
import { parseArgs } from '../../src/cli/args';
import { errorLine, exitCodeFor, InputError } from '../../src/cli/errors';
import { parseMergeArgs } from '../../src/cli/merge';
import { checkRunnable, computeBudget, loadInputs, readJsonFile } from '../../src/cli/prepare';
import { Sources } from '../../src/cli/sources';
import { sweepLayout } from '../../src/run/sweepLayout';
import { validateConfig } from '../../src/core/config';
import { fileHeader, formatCsvRow, parseShard, planResume, ResumeError, validateSweepSpec, type ValidSweepSpec } from '../../src/core/sweep';

const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-corpus-'));
const file = (name: string, data: string | Buffer) => {
  const path = join(dir, name);
  writeFileSync(path, data);
  return path;
};

/** The error `action` throws, as the CLI reports it. */
async function refusal(action: () => unknown): Promise<{ code: number; line: string }> {
  try {
    await action();
  } catch (error) {
    const e = error instanceof ResumeError ? new InputError(error.message) : error;
    return { code: exitCodeFor(e), line: errorLine(e) };
  }
  throw new Error('accepted');
}

async function expectRefused(action: () => unknown, names: RegExp) {
  const { code, line } = await refusal(action);
  expect(code, line).toBe(2);
  expect(line).toMatch(names);
  expect(line).not.toMatch(/\n|\s{2}at \S+ \(|\[object Object\]/);
  expect(line.length).toBeLessThanOrEqual(500);
}

const tube = { surface: { kind: 'tube', radius: 40, length: 300 }, resolution: 128, cells: 24 };
const budget = computeBudget(8192, false);
const config = (c: unknown) => () => checkRunnable(validateConfig(c), budget);

describe('bad input corpus: configs', () => {
  const cases: [string, unknown, RegExp][] = [
    ['a string', 'tube', /config/],
    ['an array', [1], /config/],
    ['an unknown top-level field', { ...tube, colour: 'red' }, /colour/],
    ['an unknown surface kind', { ...tube, surface: { kind: 'torus' } }, /surface/],
    ['a negative radius', { ...tube, surface: { kind: 'tube', radius: -3, length: 300 } }, /surface\.radius/],
    ['a radius as text', { ...tube, surface: { kind: 'tube', radius: '40', length: 300 } }, /surface\.radius/],
    ['zero cells', { ...tube, cells: 0 }, /cells/],
    ['fractional cells', { ...tube, cells: 2.5 }, /cells/],
    ['a seed above uint32', { ...tube, seed: 2 ** 33 }, /seed/],
    ['a seed as text', { ...tube, seed: 'abc' }, /seed/],
    ['an unknown engine', { ...tube, engine: 'quantum' }, /engine/],
    ['negative Lloyd iterations', { ...tube, lloyd: { maxIterations: -1 } }, /lloyd\.maxIterations/],
    ['over-relaxation past 2', { ...tube, lloyd: { overRelaxation: 2.5 } }, /lloyd\.overRelaxation/],
    ['a surface ratio below 1', { ...tube, sheet: { surfaceRatio: 0.5 } }, /sheet\.surfaceRatio/],
    ['an unknown protocol', { ...tube, sheet: { protocol: 'mine' } }, /sheet\.protocol/],
    [
      'the lab protocol on a plane',
      { surface: { kind: 'plane', width: 300, height: 300 }, resolution: 128, cells: 24, sheet: { protocol: 'lab', thickness: 5 } },
      /sheet\.protocol/,
    ],
    ['the exact engine on a sphere', { surface: { kind: 'sphere', radius: 50 }, cells: 24, engine: 'exact' }, /engine/],
    ['layers and a layer step together', { ...tube, sheet: { surfaceRatio: 2, layers: 2, layerStep: 0.25 } }, /sheet\.layer/],
    ['a plane 1e20 µm wide', { surface: { kind: 'plane', width: 1e20, height: 300 }, cells: 24 }, /surface\.width/],
    ['a tube 1e-20 µm around', { surface: { kind: 'tube', radius: 1e-20, length: 300 }, cells: 24 }, /surface\.radius/],
    ['too many cells for the texels', { ...tube, cells: 20000 }, /cells|resolution/],
    ['a resolution above the texture limit', { ...tube, resolution: 100000 }, /resolution/],
    ['a density image without src', { ...tube, density: { kind: 'image' } }, /density/],
  ];
  for (const [name, value, names] of cases) it(`refuses ${name}`, () => expectRefused(config(value), names));
  it('refuses a __proto__ key in a sweep base (a config file: see cli.test.ts)', () =>
    expectRefused(() => validateSweepSpec(JSON.parse('{"base": {"__proto__": {"cells": 5}}}')), /base\.__proto__/));
});

describe('bad input corpus: sweep specs', () => {
  const base = { ...tube, engine: 'exact' };
  const cases: [string, unknown, RegExp][] = [
    ['no base', { vary: {} }, /base/],
    ['a base that is not a config', { base: { cells: 'many' } }, /base\.cells/],
    ['an unknown spec field', { base, repeats: 3 }, /repeats/],
    ['realizations 0', { base, realizations: 0 }, /realizations/],
    ['realizations 1e9', { base, realizations: 1e9 }, /realizations/],
    ['a seed of "abc"', { base, seed: 'abc' }, /seed/],
    ['an unknown seed mode', { base, seedMode: 'sometimes' }, /seedMode/],
    ['a varied path that is no field', { base, vary: { 'sheet.colour': [1] } }, /sheet\.colour/],
    ['varying the seed', { base, vary: { seed: [1, 2] } }, /seed/],
    ['an empty value list', { base, vary: { cells: [] } }, /cells/],
    ['values that are not a list', { base, vary: { cells: 5 } }, /cells/],
    ['a bad value, named by index', { base, vary: { cells: [24, -1] } }, /vary\["cells"\]\[1\]/],
    ['a prototype path', { base, vary: { 'constructor.prototype': [1] } }, /constructor/],
    ['too many runs', { base, vary: { cells: [20, 21, 22] }, realizations: 40000 }, /vary: .*120000 runs/],
  ];
  for (const [name, value, names] of cases) it(`refuses ${name}`, () => expectRefused(() => validateSweepSpec(value), names));

  it('refuses a spec file that is empty, not JSON, or a directory, naming the file', async () => {
    await expectRefused(() => readJsonFile(file('empty.json', ''), 'sweep spec'), /empty\.json: the file is empty/);
    await expectRefused(() => readJsonFile(file('broken.json', '{"base": '), 'sweep spec'), /broken\.json: not valid JSON/);
    await expectRefused(() => readJsonFile(dir, 'sweep spec'), /is a directory/);
    await expectRefused(() => readJsonFile(join(dir, 'absent.json'), 'sweep spec'), /absent\.json: cannot read the sweep spec \(no such file\)/);
  });
});

describe('bad input corpus: runs.csv rows', () => {
  const spec = validateSweepSpec({
    base: { ...tube, engine: 'exact' },
    vary: { 'sheet.layers': [0, 1], 'sheet.surfaceRatio': [1, 2] },
    realizations: 2,
    seed: 1,
  }) as ValidSweepSpec;
  const layout = sweepLayout(spec);
  const good = (run = layout.runs[0]) =>
    layout.header.map((h) => {
      if (h === 'key') return run.key;
      if (h === 'realization') return String(run.realization);
      if (h === 'seed') return String(run.seed);
      if (layout.fields.includes(h)) return String(run.point[h]);
      if (h === 'centroidPath') return 'none (exact engine)';
      // The base columns hold the run's configuration (units.ts geometryValues).
      const base = layout.geometryOf(run);
      if (h in base) return String(base[h]);
      if (!layout.resume.filledColumns(run).has(h) || h.startsWith('labels.')) return '';
      return '1';
    });
  const header = formatCsvRow(fileHeader(layout.header));
  // A good row of run 1, then the corpus row (run 0 with one thing changed).
  const rejected = (cells: string[]) => planResume(header + formatCsvRow(good(layout.runs[1])) + formatCsvRow(cells), layout.resume).rejected;
  const edit = (column: string, value: string) => good().map((c, k) => (layout.header[k] === column ? value : c));

  it('accepts a well-formed row (the corpus rows below differ from it in one place)', () => {
    expect(planResume(header + formatCsvRow(good()) + formatCsvRow(good(layout.runs[1])), layout.resume).rejected).toEqual([]);
  });
  const cases: [string, () => string[], RegExp][] = [
    ['a missing field', () => good().slice(1), /fields where the header has/],
    ['an extra field', () => [...good(), 'x'], /fields where the header has/],
    ['a key of no run', () => edit('key', 'sheet.surfaceRatio=3#r0'), /is not a run of this spec/],
    ['a repeated key', () => good(layout.runs[1]), /duplicate of line 2/],
    ['another realization', () => edit('realization', '1'), /realization "1"/],
    ['another seed', () => edit('seed', '12345'), /seed "12345"/],
    ['another varied value', () => edit('sheet.surfaceRatio', '2'), /sheet\.surfaceRatio is "2"/],
    [
      'another base value (a row of another configuration)',
      () => edit('cells', '7'),
      /cells is "7" but run .* of this spec has \d+ \(a row of another configuration\)/,
    ],
    ['text in a number column', () => edit('exact.percentScutoids', 'lots'), /exact\.percentScutoids: "lots" is not a number/],
    ['a formula in a number column', () => edit('finalEnergy', '=1+1'), /finalEnergy/],
    ['an empty required column', () => edit('iterations', ''), /iterations is empty/],
    ['half a method filled', () => edit('exact.meanTransitions', ''), /exact\.\* columns are partly empty/],
    ['a value where the run fills none', () => edit('exact.layer1.meanSides', '5'), /exact\.layer1\.meanSides should be empty/],
  ];
  for (const [name, cells, reason] of cases) {
    it(`drops a row with ${name}, by line`, () => {
      const bad = rejected(cells());
      expect(bad).toHaveLength(1);
      expect(bad[0].line).toBe(3);
      expect(bad[0].reason).toMatch(reason);
    });
  }
  it('refuses a runs.csv of another spec or version (exit 2, naming the file and the column)', async () => {
    await expectRefused(() => planResume('key,realization,seed\r\n', layout.resume, 'out/runs.csv'), /out\/runs\.csv: written for another spec or version/);
    await expectRefused(() => planResume(header.replace('finalEnergy_um4', 'energy_um4'), layout.resume, 'out/runs.csv'), /column \d+ is "energy_um4"/);
  });
});

describe('bad input corpus: meshes and images', () => {
  const sources = new Sources({ baseDir: dir, allowNetwork: false });
  const mesh = (name: string) => validateConfig({ surface: { kind: 'mesh', src: join(dir, name) }, cells: 24 });
  const image = (name: string) => validateConfig({ ...tube, density: { kind: 'image', src: join(dir, name) } });
  const png = (w: number, h: number) => Buffer.from(encode({ width: w, height: h, data: new Uint8Array(4 * w * h).fill(200), depth: 8, channels: 4 }));
  const meshCases: [string, string, string | Buffer, RegExp][] = [
    ['an empty OBJ', 'empty.obj', '', /empty\.obj/],
    ['an OBJ with a NaN vertex', 'nan.obj', 'v 0 0 0\nv 1 0 0\nv NaN 1 0\nv 0 0 1\nf 1 2 3\nf 1 2 4\nf 1 3 4\nf 2 3 4\n', /nan\.obj/],
    ['an open OBJ (one triangle)', 'open.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n', /open\.obj/],
    ['an OBJ face past its vertices', 'index.obj', 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n', /index\.obj/],
    [
      'a PLY with a wrong vertex count',
      'count.ply',
      'ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\nproperty float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n',
      /count\.ply/,
    ],
    ['text named .stl', 'text.stl', 'hello', /text\.stl/],
    ['an unknown extension', 'shape.dae', '<xml/>', /shape\.dae|surface\.src/],
  ];
  for (const [name, path, data, names] of meshCases) {
    it(`refuses ${name}, naming the file`, async () => {
      file(path, data);
      await expectRefused(() => loadInputs(mesh(path), sources), names);
    });
  }
  it('refuses a missing mesh and a directory given as one', async () => {
    await expectRefused(() => loadInputs(mesh('absent.obj'), sources), /absent\.obj/);
    mkdirSync(join(dir, 'folder.obj'), { recursive: true });
    await expectRefused(() => loadInputs(mesh('folder.obj'), sources), /folder\.obj/);
  });
  const imageCases: [string, string, Buffer, RegExp][] = [
    ['an empty PNG file', 'empty.png', Buffer.alloc(0), /density\.src: .*empty\.png/],
    ['a truncated PNG', 'cut.png', png(16, 16).subarray(0, 40), /density\.src: .*cut\.png/],
    ['a JPEG named .png', 'photo.png', Buffer.from([0xff, 0xd8, 0xff, 0xe0, 0, 16, 0x4a, 0x46, 0x49, 0x46]), /density\.src: .*photo\.png/],
    ['text named .png', 'notes.png', Buffer.from('not an image'), /density\.src: .*notes\.png/],
  ];
  for (const [name, path, data, names] of imageCases) {
    it(`refuses ${name}, naming density.src and the file`, async () => {
      file(path, data);
      await expectRefused(() => loadInputs(image(path), sources), names);
    });
  }
  it('refuses an http(s) density image without --allow-network', async () => {
    await expectRefused(
      () => loadInputs(validateConfig({ ...tube, density: { kind: 'image', src: 'https://example.org/d.png' } }), sources),
      /density\.src|--allow-network/,
    );
  });
});

describe('bad input corpus: command-line arguments, shards and merge', () => {
  const sweep = (args: string[]) => () => parseArgs(args, 'sweep SWEEP.json --out DIR', true);
  const cases: [string, () => unknown, RegExp][] = [
    ['sweep without --out', sweep(['spec.json']), /missing --out/],
    ['sweep without a spec', sweep(['--out', 'x']), /missing input file/],
    ['--out without a value', sweep(['spec.json', '--out']), /--out needs a value/],
    ['an unknown option', sweep(['spec.json', '--out', 'x', '--fast']), /unknown option --fast/],
    ['two specs', sweep(['a.json', 'b.json', '--out', 'x']), /unexpected argument b\.json/],
    ['--max-runs 0', sweep(['s.json', '--out', 'x', '--max-runs', '0']), /--max-runs/],
    ['--max-runs text', sweep(['s.json', '--out', 'x', '--max-runs=many']), /--max-runs: .*"many"/],
    ['--shard without a value', sweep(['s.json', '--out', 'x', '--shard']), /--shard needs a value/],
    // `--force=false` turned the flag on (and overwrote a file); a flag takes no value.
    ['--force=false', sweep(['s.json', '--out', 'x', '--force=false']), /--force takes no value \(got "--force=false"\)/],
    ['--allow-large=0', sweep(['s.json', '--out', 'x', '--allow-large=0']), /--allow-large takes no value/],
    ['--cells-file=no', () => parseArgs(['c.json', '--out', 'x', '--cells-file=no'], 'run CONFIG.json --out RESULT.json'), /--cells-file takes no value/],
    ['--workers in hexadecimal', sweep(['s.json', '--out', 'x', '--workers', '0x2']), /--workers: must be an integer from 1 to 1024 \(got "0x2"\)/],
    ['--max-runs in exponent form', sweep(['s.json', '--out', 'x', '--max-runs', '1e3']), /--max-runs: must be a positive integer/],
    ['--shard 3/2', () => parseShard('3/2'), /--shard: I must be 1 to 2/],
    ['--shard 1/0', () => parseShard('1/0'), /--shard: the number of shards/],
    ['--shard -1/4', () => parseShard('-1/4'), /--shard: "-1\/4" is not I\/N/],
    ['--shard 1.5/4', () => parseShard('1.5/4'), /is not I\/N/],
    [
      '--shard slurm with a stepped array',
      () => parseShard('slurm', { SLURM_ARRAY_TASK_ID: '5', SLURM_ARRAY_TASK_MIN: '1', SLURM_ARRAY_TASK_COUNT: '3' }),
      /not one of 3 consecutive tasks/,
    ],
    ['--shard slurm with no count', () => parseShard('slurm', { SLURM_ARRAY_TASK_ID: '1', SLURM_ARRAY_TASK_MIN: '1' }), /SLURM_ARRAY_TASK_COUNT is not set/],
    ['merge without --out', () => parseMergeArgs(['a', 'b']), /missing --out/],
    ['merge without directories', () => parseMergeArgs(['--out', 'm']), /missing sweep directories/],
    ['merge with an unknown option', () => parseMergeArgs(['a', '--out', 'm', '--shard', '1/2']), /unknown option --shard/],
  ];
  for (const [name, action, names] of cases) it(`refuses ${name}`, () => expectRefused(action, names));
});
