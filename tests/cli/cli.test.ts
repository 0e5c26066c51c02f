import { spawn, spawnSync } from 'node:child_process';
import { createHash } from 'node:crypto';
import { existsSync, mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { hostname, tmpdir } from 'node:os';
import { join } from 'node:path';
import { encode } from 'fast-png';
import { describe, expect, it } from 'vitest';
import { validateConfig } from '../../src/core/config';
import { geometryValues, readCsvTable, readRunsCsv, summaryColumns } from '../../src/core/sweep';

// The CLI from its sources (same main() as bin/tissue-sheet.mjs, which runs the compiled build).
const bin = join(__dirname, 'fromSource.mjs');
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-cli-'));

function cli(args: string[]) {
  return spawnSync(process.execPath, [bin, ...args], { encoding: 'utf8', env: process.env });
}

function writeJson(name: string, value: unknown): string {
  const path = join(dir, name);
  writeFileSync(path, typeof value === 'string' ? value : JSON.stringify(value));
  return path;
}

const small = {
  surface: { kind: 'tube', radius: 40, length: 400 },
  resolution: 128,
  cells: 40,
  seed: 9,
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 1.8, layers: 1 },
};

/** A result file without what depends on the clock. */
function withoutTimings(path: string): unknown {
  const result = JSON.parse(readFileSync(path, 'utf8'));
  delete result.timings;
  for (const record of result.lloyd.iterations) {
    delete record.diagramMs;
    delete record.centroidMs;
  }
  return result;
}

describe('tissue-sheet run', () => {
  it('writes the documented result, with progress on stderr', () => {
    const out = join(dir, 'result.json');
    const run = cli(['run', writeJson('small.json', small), '--out', out]);
    expect(run.status).toBe(0);
    expect(run.stderr).toMatch(/iteration 3\/3/);
    const result = JSON.parse(readFileSync(out, 'utf8'));
    expect(result.software.name).toBe('tissue-sheet');
    expect(result.config.lloyd.overRelaxation).toBe(1); // defaults filled in
    expect(result.seed).toBe(9);
    // the engine policy may pick the exact CPU engine on a software renderer (result.gpu null)
    if (result.engine.name === 'gpu') expect(['blend', 'gather', 'readback']).toContain(result.gpu.centroidPath);
    else expect(result.gpu).toBeNull();
    expect(result.lloyd.iterations).toHaveLength(3);
    expect(result.cells).toHaveLength(40);
    expect(result.surfaces.map((s: { name: string }) => s.name)).toEqual(['layer 1', 'apical']);
    expect(result.analyses.map((a: { method: string }) => a.method)).toEqual(result.engine.name === 'exact' ? ['exact'] : ['labels', 'exact']);
    const cell = result.cells[0];
    expect(cell.position).toHaveLength(3);
    expect(cell.surface).toHaveLength(2);
    expect(cell.area).toBeGreaterThan(0);
    expect(cell.neighbours[0]).toHaveProperty('length');
    expect(typeof cell.touchesBorder).toBe('boolean');
  });

  it('gives the same output for the same input, except timings', () => {
    const outs = [1, 2].map((k) => {
      const out = join(dir, `again${k}.json`);
      expect(cli(['run', join(dir, 'small.json'), '--out', out]).status).toBe(0);
      return withoutTimings(out);
    });
    expect(outs[1]).toEqual(outs[0]);
  });

  const badInputs: Array<[string, unknown, RegExp]> = [
    ['unknown field', { ...small, cels: 3 }, /^tissue-sheet: cels: unknown field/],
    ['negative size', { ...small, surface: { kind: 'tube', radius: -3, length: 10 } }, /surface\.radius: must be > 0 µm \(got -3\)/],
    ['too many cells', { ...small, cells: 100000 }, /^tissue-sheet: cells: .* lower cells or raise resolution/],
    [
      'resolution above the largest texture side (16384)',
      { ...small, surface: { kind: 'tube', radius: 40, length: 400000 }, resolution: 16384 * 2 },
      /resolution: must be an integer from 16 to 16384/,
    ],
    ['s < 1', { ...small, sheet: { surfaceRatio: 0.5 } }, /sheet\.surfaceRatio: must be >= 1 or null \(got 0\.5\)/],
    ['thickness beyond the radius', { ...small, sheet: { direction: 'inward', thickness: 50 } }, /sheet\.thickness: 50 µm inward reaches the tube's axis/],
    ['negative layers', { ...small, sheet: { layers: -1 } }, /sheet\.layers: must be an integer/],
    ['not JSON', '{"cells": 3,', /not valid JSON/],
    [
      'a plane 1e20 µm wide',
      { ...small, surface: { kind: 'plane', width: 1e20, height: 1e20 }, sheet: {} },
      /^tissue-sheet: surface\.width: 100000000000000000000 µm is outside/,
    ],
    [
      'a plane 1e-20 µm wide',
      { ...small, surface: { kind: 'plane', width: 1e-20, height: 1e-20 }, sheet: {} },
      /^tissue-sheet: surface\.width: 1e-20 µm is outside/,
    ],
    [
      'one texel around a tube',
      { ...small, surface: { kind: 'tube', radius: 0.1, length: 4000 }, resolution: 1024, sheet: {} },
      /^tissue-sheet: resolution: the grid is 1 x 1024 texels/,
    ],
    ['a huge surface ratio', { ...small, sheet: { surfaceRatio: 1e6 } }, /^tissue-sheet: sheet\.surfaceRatio: .* lower sheet\.surfaceRatio/],
    [
      'a ratio beyond the texture limit',
      { ...small, resolution: 64, sheet: { surfaceRatio: 600 } },
      /^tissue-sheet: sheet\.surfaceRatio: the other surface would be \d+ x \d+ texels .* this GPU allows/,
    ],
    [
      'a mesh with a NaN vertex',
      { ...small, surface: { kind: 'mesh', src: 'nan.ply' }, sheet: {} },
      /^tissue-sheet: surface\.src: .*nan\.ply: .*vertex 3 .*NaN/,
    ],
    [
      // issue 26: was refused as a minSpacing problem with exit 1
      'a mesh scaled to 1e30',
      { ...small, surface: { kind: 'mesh', src: 'unit.ply', scale: 1e30 }, sheet: {} },
      /^tissue-sheet: surface\.src: .*unit\.ply: the mesh is 1\.00e\+30 µm across after surface\.scale 1e\+30; .*set surface\.scale to about 100 for a 100 µm sheet$/,
    ],
    [
      'a PLY with a wrong vertex count',
      { ...small, surface: { kind: 'mesh', src: 'count.ply' }, sheet: {} },
      /^tissue-sheet: surface\.src: .*count\.ply: the PLY header declares 5 vertex \+ 4 face = 9 lines but the body has 8/,
    ],
    [
      'an http mesh',
      { ...small, surface: { kind: 'mesh', src: 'http://127.0.0.1:9/a.ply' }, sheet: {} },
      /^tissue-sheet: surface\.src: "http:\/\/127\.0\.0\.1:9\/a\.ply" is a network address; .*--allow-network/,
    ],
    [
      'an empty density image',
      { ...small, density: { kind: 'image', src: 'empty.png' } },
      /^tissue-sheet: density\.src: density image .*empty\.png: the file is empty/,
    ],
    ['a __proto__ key', '{"cells": 20, "sheet": {"__proto__": {"layers": 3}}}', /^tissue-sheet: .*sheet\.__proto__: not allowed as a key/],
    [
      'a directory as density image',
      { ...small, density: { kind: 'image', src: 'folder.png' } },
      /^tissue-sheet: density\.src: density image .*folder\.png: is a directory/,
    ],
  ];
  const tetra = (vertices: number, last: string) =>
    `ply\nformat ascii 1.0\nelement vertex ${vertices}\nproperty float x\nproperty float y\nproperty float z\nelement face 4\nproperty list uchar int vertex_indices\nend_header\n` +
    `0 0 0\n1 0 0\n0 1 0\n${last}\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n`;
  writeFileSync(join(dir, 'nan.ply'), tetra(4, '0 0 NaN'));
  writeFileSync(join(dir, 'count.ply'), tetra(5, '0 0 1'));
  writeFileSync(join(dir, 'unit.ply'), tetra(4, '0 0 1'));
  writeFileSync(join(dir, 'empty.png'), '');
  mkdirSync(join(dir, 'folder.png'), { recursive: true });
  for (const [name, input, message] of badInputs) {
    it(`bad input (${name}): exit 2, one line naming the problem`, () => {
      const run = cli(['run', writeJson(`bad-${name.replace(/\W/g, '')}.json`, input), '--out', join(dir, 'never.json')]);
      expect(run.status).toBe(2);
      expect(run.stderr.trim().split('\n')).toHaveLength(1);
      expect(run.stderr.trim()).toMatch(message);
      expect(run.stderr).not.toMatch(/\n\s+at /); // no stack trace
    });
  }

  it('accepts a UTF-8 byte-order mark', () => {
    const path = join(dir, 'bom.json');
    writeFileSync(path, '\ufeff' + JSON.stringify({ ...small, lloyd: { maxIterations: 1 } }));
    expect(cli(['run', path, '--out', join(dir, 'bom-result.json')]).status).toBe(0);
  });

  it('never writes over its input, through a link, or over a foreign file without --force', () => {
    const input = join(dir, 'small.json');
    const before = readFileSync(input, 'utf8');
    const same = cli(['run', input, '--out', input]);
    expect(same.status).toBe(2);
    expect(same.stderr).toMatch(/--out .*small\.json: that is the input file/);
    writeFileSync(join(dir, 'notes.txt'), 'mine');
    const foreign = cli(['run', input, '--out', join(dir, 'notes.txt')]);
    expect(foreign.status).toBe(2);
    expect(foreign.stderr).toMatch(/exists and is not a tissue-sheet result; pass --force/);
    expect(readFileSync(input, 'utf8')).toBe(before);
    expect(readFileSync(join(dir, 'notes.txt'), 'utf8')).toBe('mine');
  });

  it('documents its exit codes in --help', () => {
    const help = cli(['--help']);
    expect(help.status).toBe(0);
    for (const code of ['0 ', '1 ', '2 ', '3 ', '130 ']) expect(help.stdout).toContain(`\n  ${code}`);
  });

  it('missing --out is a usage error', () => {
    const run = cli(['run', join(dir, 'small.json')]);
    expect(run.status).toBe(2);
    expect(run.stderr).toMatch(/missing --out/);
  });
});

describe('tissue-sheet sweep', () => {
  it('writes tidy and aggregated CSV, and resumes without recomputing finished runs', () => {
    const spec = writeJson('sweep.json', {
      base: { ...small, lloyd: { maxIterations: 2 }, sheet: {} },
      vary: { 'sheet.surfaceRatio': [1, 2] },
      realizations: 2,
      seed: 3,
    });
    const out = join(dir, 'sweep');
    const first = cli(['sweep', spec, '--out', out]);
    expect(first.status).toBe(0);
    const runs = readFileSync(join(out, 'runs.csv'), 'utf8').trim().split(/\r?\n/);
    expect(runs).toHaveLength(1 + 4);
    const header = runs[0].split(',');
    const scutoids = header.indexOf('exact.percentScutoids_pct');
    const ratio = header.indexOf('sheet.surfaceRatio');
    for (const row of runs.slice(1)) {
      const cells = row.split(',');
      if (cells[ratio] === '1') expect(Number(cells[scutoids])).toBe(0);
      else expect(Number(cells[scutoids])).toBeGreaterThan(0);
    }
    const aggregate = JSON.parse(readFileSync(join(out, 'aggregate.json'), 'utf8'));
    expect(aggregate.points[0].stats['exact.percentScutoids']).toMatchObject({ n: 2, missing: 0 });
    const record = JSON.parse(readFileSync(join(out, 'sweep.json'), 'utf8'));
    expect(record).toMatchObject({ software: { name: 'tissue-sheet' }, runs: 4, computed: 4 });
    expect(typeof record.renderer).toBe('string');
    expect(Date.parse(record.ended)).toBeGreaterThanOrEqual(Date.parse(record.started));

    // Cut the last row in half (an interrupted write) and duplicate another: only the cut run
    // is computed again, and the file ends with one row per run.
    writeFileSync(join(out, 'runs.csv'), [...runs.slice(0, 4), runs[1]].join('\r\n') + '\r\n' + runs[4].slice(0, 30));
    const second = cli(['sweep', spec, '--out', out]);
    expect(second.status).toBe(0);
    expect(second.stderr).toMatch(/runs\.csv:5: duplicate of line 2/);
    expect(second.stderr).toMatch(/runs\.csv:6: incomplete last line/);
    expect(second.stderr).toMatch(/1 runs computed, 3 resumed/);
    expect(readFileSync(join(out, 'runs.csv'), 'utf8').trim().split(/\r?\n/)).toEqual(runs);
  });

  it('fixes the header from the spec: every method and surface of the grid, each row filling its own', () => {
    const spec = writeJson('union.json', {
      base: { ...small, lloyd: { maxIterations: 1 }, sheet: { surfaceRatio: 1.5 } },
      vary: { 'sheet.adjacency': ['labels', 'both'], 'sheet.layers': [0, 1] },
      seed: 4,
    });
    const out = join(dir, 'union');
    const run = cli(['sweep', spec, '--out', out]);
    expect(run.status).toBe(0);
    const table = readRunsCsv(readFileSync(join(out, 'runs.csv'), 'utf8'));
    expect(table.header).toContain('exact.percentScutoids');
    expect(table.header).toContain('labels.layer1.meanSides');
    for (const row of table.rows) {
      const config = validateConfig({ ...small, sheet: { surfaceRatio: 1.5, adjacency: row['sheet.adjacency'], layers: Number(row['sheet.layers']) } });
      // the real summary fills only columns predicted for its config, each method all or none
      const possible = new Set(summaryColumns(config));
      const geometry = new Set(Object.keys(geometryValues(config, ['sheet.adjacency', 'sheet.layers'])));
      for (const column of table.header.slice(5)) if (!possible.has(column) && !geometry.has(column)) expect(row[column], `${row.key} ${column}`).toBe('');
      for (const column of ['iterations', 'finalEnergy', 'centroidPath']) expect(row[column]).not.toBe('');
      const methods = ['labels', 'exact'].filter((m) => row[`${m}.percentScutoids`] !== '');
      expect(methods.length).toBeGreaterThan(0);
      for (const m of methods)
        for (const column of [...possible].filter((c) => c.startsWith(`${m}.`))) expect(row[column], `${row.key} ${column}`).not.toBe('');
    }
    const aggregate = readCsvTable(readFileSync(join(out, 'aggregate.csv'), 'utf8'));
    const labelsOnly = aggregate.rows.find((r) => r['sheet.adjacency'] === 'labels')!;
    expect(labelsOnly['exact.percentScutoids.n']).toBe('0');
    expect(labelsOnly['exact.percentScutoids.mean_pct']).toBe('');
  });

  it('runs a sweep over a density image', () => {
    const data = new Uint8Array(4 * 32);
    for (let k = 0; k < 32; k++) data.fill(k % 8 < 4 ? 0 : 255, 4 * k, 4 * k + 3).fill(255, 4 * k + 3, 4 * k + 4);
    writeFileSync(join(dir, 'half.png'), encode({ width: 8, height: 4, data, depth: 8, channels: 4 }));
    const spec = writeJson('density.json', {
      base: { ...small, lloyd: { maxIterations: 1 }, sheet: {} },
      vary: { density: [{ kind: 'uniform' }, { kind: 'image', src: 'half.png', high: 4 }] },
    });
    const run = cli(['sweep', spec, '--out', join(dir, 'density')]);
    expect(run.stderr).toMatch(/2 runs computed/);
    expect(run.status).toBe(0);
    // The spec names the image by path; the record holds what was read: its size and SHA-256.
    const bytes = readFileSync(join(dir, 'half.png'));
    const digest = createHash('sha256').update(bytes).digest('hex');
    const record = JSON.parse(readFileSync(join(dir, 'density', 'sweep.json'), 'utf8'));
    expect(record.inputFiles).toEqual([{ field: 'density.src', src: 'half.png', bytes: bytes.length, sha256: digest }]);
    // The same file: resumed. Another image under the same name: refused, its rows kept.
    expect(cli(['sweep', spec, '--out', join(dir, 'density')]).stderr).toMatch(/0 runs computed, 2 resumed/);
    const rows = readFileSync(join(dir, 'density', 'runs.csv'), 'utf8');
    writeFileSync(join(dir, 'half.png'), encode({ width: 8, height: 4, data: data.map((v, k) => (k % 4 === 3 ? v : 255 - v)), depth: 8, channels: 4 }));
    const changed = cli(['sweep', spec, '--out', join(dir, 'density')]);
    expect(changed.status).toBe(2);
    expect(changed.stderr).toMatch(
      /density\.src "half\.png" has changed since \(\d+ bytes, SHA-256 [0-9a-f]{12}… then; \d+ bytes, [0-9a-f]{12}… now\); its 2 rows would be mixed/,
    );
    expect(readFileSync(join(dir, 'density', 'runs.csv'), 'utf8')).toBe(rows);
    // A run records the file it read too.
    const config = writeJson('density-run.json', { ...small, lloyd: { maxIterations: 1 }, sheet: {}, density: { kind: 'image', src: 'half.png', high: 4 } });
    expect(cli(['run', config, '--out', join(dir, 'density-run.out.json'), '--realizations', '1']).status).toBe(0);
    const result = JSON.parse(readFileSync(join(dir, 'density-run.out.json'), 'utf8'));
    const now = readFileSync(join(dir, 'half.png'));
    expect(result.inputFiles).toEqual([{ field: 'density.src', src: 'half.png', bytes: now.length, sha256: createHash('sha256').update(now).digest('hex') }]);
  });

  const badSpecs: Array<[string, unknown, RegExp]> = [
    ['seed "abc"', { base: small, seed: 'abc' }, /^tissue-sheet: seed: must be an integer$/],
    ['unknown seed mode', { base: small, seedMode: 'sometimes' }, /^tissue-sheet: seedMode: must be one of/],
    ['realizations 1e9', { base: small, realizations: 1e9 }, /^tissue-sheet: realizations: must be an integer from 1 to/],
    ['unknown field in base', { base: { ...small, cels: 3 } }, /^tissue-sheet: base\.cels: unknown field/],
    ['a prototype path', { base: small, vary: { '__proto__.polluted': [1] } }, /^tissue-sheet: vary\["__proto__\.polluted"\]: "__proto__" is not allowed/],
    [
      '5.4 million runs',
      {
        base: small,
        vary: { cells: Array.from({ length: 300 }, (_, k) => k + 1), seed: undefined, 'lloyd.maxIterations': Array.from({ length: 300 }, (_, k) => k) },
        realizations: 60,
      },
      /5400000 runs .* --max-runs/,
    ],
    [
      'a grid point beyond the texture limit',
      { base: { ...small, resolution: 64, sheet: {} }, vary: { 'sheet.surfaceRatio': [1, 800] } },
      /^tissue-sheet: grid point sheet\.surfaceRatio=800: sheet\.surfaceRatio: .*this GPU allows/,
    ],
    [
      'a grid point with a broken mesh',
      {
        base: { ...small, sheet: {} },
        vary: {
          surface: [
            { kind: 'sphere', radius: 30 },
            { kind: 'mesh', src: 'nan.ply' },
          ],
        },
      },
      /^tissue-sheet: grid point surface=.*nan\.ply.*NaN/,
    ],
  ];
  for (const [name, spec, message] of badSpecs) {
    it(`bad sweep spec (${name}): exit 2 in seconds, one line, nothing written`, () => {
      const out = join(dir, `never-${name.replace(/\W/g, '')}`);
      const start = Date.now();
      const run = cli(['sweep', writeJson(`spec-${name.replace(/\W/g, '')}.json`, spec), '--out', out]);
      expect(Date.now() - start).toBeLessThan(15_000);
      expect(run.status).toBe(2);
      expect(run.stderr.trim().split('\n')).toHaveLength(1);
      expect(run.stderr.trim()).toMatch(message);
      expect(existsSync(out)).toBe(false);
    });
  }

  it('refuses a second sweep on a locked directory (exit 3), naming the holder', () => {
    const out = join(dir, 'locked');
    mkdirSync(out);
    writeFileSync(join(out, '.tissue-sheet.lock'), JSON.stringify({ pid: process.pid, host: hostname(), started: 'earlier' }));
    const run = cli(['sweep', writeJson('lock.json', { base: { ...small, lloyd: { maxIterations: 1 } } }), '--out', out]);
    expect(run.status).toBe(3);
    expect(run.stderr).toMatch(new RegExp(`another sweep is writing here \\(process ${process.pid} on ${hostname()}`));
    expect(existsSync(join(out, 'runs.csv'))).toBe(false);
  });

  it('stops on Ctrl-C with exit 130, keeping finished rows, and resumes', async () => {
    // Many short runs on one worker thread: the interrupt lands while most are still to come
    // (with reuse and threads, 12 runs could all finish before the signal arrived).
    const RUNS = 200;
    const spec = writeJson('interrupt.json', { base: { ...small, lloyd: { maxIterations: 2 }, sheet: {} }, realizations: RUNS });
    const out = join(dir, 'interrupted');
    const child = spawn(process.execPath, [bin, 'sweep', spec, '--out', out, '--workers', '1'], { env: process.env });
    let stderr = '';
    const code = await new Promise<number | null>((resolve) => {
      child.stderr.on('data', (chunk) => {
        stderr += chunk;
        if (/done 2\/200/.test(stderr) && !child.killed) child.kill('SIGINT');
      });
      child.on('exit', (status) => resolve(status));
    });
    expect(code).toBe(130);
    expect(stderr).toMatch(/interrupt/);
    const kept = readCsvTable(readFileSync(join(out, 'runs.csv'), 'utf8'));
    expect(kept.truncated).toBe(false);
    expect(kept.rows.length).toBeGreaterThanOrEqual(2);
    expect(kept.rows.length).toBeLessThan(RUNS);
    expect(existsSync(join(out, '.tissue-sheet.lock'))).toBe(false);
    const again = cli(['sweep', spec, '--out', out]);
    expect(again.status).toBe(0);
    expect(again.stderr).toMatch(new RegExp(`${RUNS - kept.rows.length} runs computed, ${kept.rows.length} resumed`));
  });
});

describe('closed surfaces through the CLI (issue 24)', () => {
  // Small closed sheets: the default adjacency ("both"), so labels and the exact restricted
  // Voronoi diagram; a few Lloyd iterations keep the GPU engine quick under headless-gl.
  const ellipsoid = { surface: { kind: 'ellipsoid', a: 44, b: 27, c: 23 }, cells: 40, seed: 3, lloyd: { maxIterations: 2 }, sheet: { thickness: 6 } };
  const mesh = { surface: { kind: 'mesh', src: 'organoid.ply', scale: 40 }, cells: 40, seed: 3, lloyd: { maxIterations: 2 }, sheet: { thickness: 2 } };

  for (const [name, base, vary] of [
    ['an ellipsoid', ellipsoid, { 'sheet.thickness': [4, 8] }],
    ['a mesh', mesh, { 'lloyd.maxIterations': [1, 2] }],
  ] as const) {
    it(`sweeps ${name} with the default adjacency: every run written, exact columns filled`, () => {
      const out = join(dir, `closed-${name.replace(/\W/g, '')}`);
      const run = cli(['sweep', writeJson(`closed-${name.replace(/\W/g, '')}.json`, { base, vary, realizations: 1, seed: 5 }), '--out', out]);
      expect(run.status, run.stderr).toBe(0);
      const table = readRunsCsv(readFileSync(join(out, 'runs.csv'), 'utf8'));
      expect(table.rows).toHaveLength(2);
      for (const method of ['labels', 'exact']) {
        expect(table.header).toContain(`${method}.percentScutoids`);
        for (const row of table.rows) {
          expect(Number(row[`${method}.percentScutoids`]), `${method} ${row.key}`).toBeGreaterThanOrEqual(0);
          expect(Number(row[`${method}.validCells`])).toBe(40);
        }
      }
      // the header is exactly what the config's description predicts
      const predicted = summaryColumns(validateConfig(base));
      for (const column of predicted) expect(table.header).toContain(column);
      const aggregate = readCsvTable(readFileSync(join(out, 'aggregate.csv'), 'utf8'));
      for (const row of aggregate.rows) expect(row['exact.percentScutoids.n']).toBe('1');
    });
  }

  it('run writes the headline (exact method on a closed surface) and prints it with the Voronoi k', () => {
    const out = join(dir, 'ellipsoid-result.json');
    const run = cli(['run', writeJson('ellipsoid.json', ellipsoid), '--out', out, '--realizations', '1']);
    expect(run.status, run.stderr).toBe(0);
    const result = JSON.parse(readFileSync(out, 'utf8'));
    const exact = result.analyses.find((a: { method: string }) => a.method === 'exact');
    expect(result.headline.method).toBe('exact');
    expect(result.headline.percentScutoids).toBe(exact.summary.percentScutoids);
    expect(result.headline.voronoiK).toBe(3);
    expect(result.headline.realizations).toBe(1);
    expect(result.headline.ci95).toBeNull();
    expect(result.headline.realizationSeeds).toEqual([3]);
    expect(result.headline.byConstruction).toBeNull();
    expect(result.byConstruction).toBeNull();
    const last = run.stderr.trim().split('\n').pop()!;
    expect(last).toContain(`headline: ${exact.summary.percentScutoids.toFixed(1)} % scutoids (exact method`);
    expect(last).toContain('one realization');
    expect(last).toContain('Voronoi 3');
  });

  it('run --realizations 3: the headline is the mean of seeds s, s + 1, s + 2 with its t interval; the file is realization 1', () => {
    const out = join(dir, 'realizations-result.json');
    const config = { ...ellipsoid, seed: 7 };
    const run = cli(['run', writeJson('realizations.json', config), '--out', out, '--realizations', '3']);
    expect(run.status, run.stderr).toBe(0);
    const result = JSON.parse(readFileSync(out, 'utf8'));
    const exact = result.analyses.find((a: { method: string }) => a.method === 'exact');
    const h = result.headline;
    expect(h.realizations).toBe(3);
    expect(h.realizationSeeds).toEqual([7, 8, 9]);
    expect(result.config.seed).toBe(7);
    // realization 1 is the file's own run
    expect(h.realizationValues[0]).toBe(exact.summary.percentScutoids);
    const values = h.realizationValues as number[];
    const mean = values.reduce((a, b) => a + b, 0) / 3;
    expect(h.percentScutoids).toBeCloseTo(mean, 10);
    const sd = Math.sqrt(values.reduce((a, v) => a + (v - mean) ** 2, 0) / 2);
    expect(h.sd).toBeCloseTo(sd, 10);
    const half = 4.303 * (sd / Math.sqrt(3));
    expect(h.ci95[0]).toBeCloseTo(Math.max(0, mean - half), 10);
    expect(h.ci95[1]).toBeCloseTo(Math.min(100, mean + half), 10);
    const last = run.stderr.trim().split('\n').pop()!;
    expect(last).toContain(`headline: ${mean.toFixed(1)} % scutoids (exact method`);
    expect(last).toContain('mean of 3 realizations (seeds 7–9), 95 % CI');
    expect(last).toContain(`realization 1 (seed 7, drawn): ${values[0].toFixed(1)} %`);
  });

  it('run --realizations refuses what is not a whole number from 1 to 100', () => {
    for (const bad of ['0', '2.5', '101', 'five']) {
      const run = cli(['run', writeJson('bad-n.json', ellipsoid), '--out', join(dir, 'bad-n.out.json'), '--realizations', bad]);
      expect(run.status).toBe(2);
      expect(run.stderr).toMatch(/--realizations: must be a whole number from 1 to 100/);
    }
  });

  it('says why a sphere gives 0 % by construction, in the result and on stderr', () => {
    const out = join(dir, 'sphere-result.json');
    const run = cli(['run', writeJson('sphere.json', { ...ellipsoid, surface: { kind: 'sphere', radius: 30 } }), '--out', out, '--realizations', '2']);
    expect(run.status, run.stderr).toBe(0);
    const result = JSON.parse(readFileSync(out, 'utf8'));
    expect(result.headline.percentScutoids).toBe(0);
    expect(result.headline.realizations).toBe(2);
    expect(result.headline.ci95).toEqual([0, 0]);
    expect(result.headline.byConstruction.reason).toBe('concentric-spheres');
    expect(result.byConstruction.reason).toBe('concentric-spheres');
    expect(run.stderr.trim().split('\n').pop()).toMatch(/headline: 0\.0 % scutoids .*Concentric spheres/);
  });
});

// `tissue-sheet run`'s other realizations on worker threads (src/cli/realizationThreads.ts): the
// result file does not depend on the number of threads, and Ctrl-C stops the threads and writes
// nothing.
/** A small tube on the exact CPU engine (the only engine whose realizations go to threads). */
const exactTube = {
  surface: { kind: 'tube', radius: 40, length: 400 },
  resolution: 128,
  cells: 60,
  seed: 11,
  engine: 'exact',
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 1.8, layers: 1 },
};

describe('tissue-sheet run --workers N (realizations on threads)', () => {
  it('gives the same result file with 1 thread (all on the main thread) and 2', () => {
    // Realizations long enough (about 0.25 s each, 20 of them) that the thread, which takes about a
    // second to start from the sources (several on a loaded machine), computes some of them before
    // the main thread has done them all.
    const config = writeJson('exact-tube.json', { ...exactTube, cells: 3000, resolution: 512, lloyd: { maxIterations: 10 } });
    const seeds = Array.from({ length: 20 }, (_, k) => 11 + k);
    const results = ['1', '2'].map((workers) => {
      const out = join(dir, `exact-tube-${workers}.json`);
      const run = cli(['run', config, '--out', out, '--realizations', '20', '--workers', workers]);
      expect(run.status, run.stderr).toBe(0);
      // Every realization is reported once, whichever thread computed it.
      for (const seed of seeds.slice(1)) expect(run.stderr.match(new RegExp(`realization \\d+ of 20 \\(seed ${seed}\\b`, 'g'))).toHaveLength(1);
      // Threads only where asked: --workers 1 keeps every realization on the main thread.
      if (workers === '1') expect(run.stderr).not.toMatch(/thread/);
      else {
        expect(run.stderr).toMatch(/realizations 2–20 on 1 worker thread/);
        expect(run.stderr).toMatch(/\(seed \d+, on a thread\)/);
      }
      return withoutTimings(out);
    });
    const headline = (results[0] as { headline: { realizations: number; realizationSeeds: number[]; realizationValues: unknown[] } }).headline;
    expect(headline.realizations).toBe(20);
    expect(headline.realizationSeeds).toEqual(seeds);
    expect(headline.realizationValues.every((v) => typeof v === 'number')).toBe(true);
    expect(results[1]).toEqual(results[0]);
  });

  it('refuses --workers that is not a whole number from 1', () => {
    const run = spawnSync(process.execPath, [bin, 'run', writeJson('bad-workers.json', exactTube), '--out', join(dir, 'bad.out.json'), '--workers', '0'], {
      encoding: 'utf8',
    });
    expect(run.status).toBe(2);
    expect(run.stderr).toMatch(/--workers: must be an integer from 1 to 1024/);
  });

  it('stops on Ctrl-C while threads compute realizations: exit 130, threads stopped, nothing written', async () => {
    // Many realizations, so that most are still to come when the signal lands.
    const config = writeJson('many.json', { ...exactTube, cells: 400, lloyd: { maxIterations: 5 } });
    const out = join(dir, 'interrupted.json');
    const child = spawn(process.execPath, [bin, 'run', config, '--out', out, '--realizations', '60', '--workers', '3'], { env: process.env });
    let stderr = '';
    const code = await new Promise<number | null>((resolve) => {
      child.stderr.on('data', (chunk) => {
        stderr += chunk;
        if (/realization \d+ of 60/.test(stderr) && !child.killed) child.kill('SIGINT');
      });
      // The process exits only once its threads are stopped (a live thread keeps it running).
      child.on('exit', (status) => resolve(status));
    });
    expect(code, stderr).toBe(130);
    expect(stderr).toMatch(/interrupt/);
    expect(stderr).not.toMatch(/realization 60 of 60/);
    expect(existsSync(out)).toBe(false);
  });
});
