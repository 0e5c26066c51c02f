import { spawnSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';

const bin = join(__dirname, '../../bin/tissue-sheet.mjs');
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
  resolution: 256,
  cells: 60,
  seed: 9,
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 1.8, layers: 1 },
};

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
    expect(['blend', 'gather', 'readback']).toContain(result.gpu.centroidPath);
    expect(result.lloyd.iterations).toHaveLength(3);
    expect(result.cells).toHaveLength(60);
    expect(result.surfaces.map((s: { name: string }) => s.name)).toEqual(['layer 1', 'apical']);
    expect(result.analyses.map((a: { method: string }) => a.method)).toEqual(['labels', 'exact']);
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
      const result = JSON.parse(readFileSync(out, 'utf8'));
      delete result.timings;
      for (const record of result.lloyd.iterations) {
        delete record.jumpFloodMs;
        delete record.centroidMs;
      }
      return result;
    });
    expect(outs[1]).toEqual(outs[0]);
  });

  const badInputs: Array<[string, unknown, RegExp]> = [
    ['unknown field', { ...small, cels: 3 }, /^tissue-sheet: cels: unknown field/],
    ['negative size', { ...small, surface: { kind: 'tube', radius: -3, length: 10 } }, /surface\.radius: must be > 0 µm \(got -3\)/],
    ['too many cells', { ...small, cells: 100000 }, /^tissue-sheet: cells: .* lower cells or raise resolution/],
    ['resolution above the largest texture side (16384)', { ...small, surface: { kind: 'tube', radius: 40, length: 400000 }, resolution: 16384 * 2 }, /resolution: must be an integer from 16 to 16384/],
    ['s < 1', { ...small, sheet: { surfaceRatio: 0.5 } }, /sheet\.surfaceRatio: must be >= 1 or null \(got 0\.5\)/],
    ['thickness beyond the radius', { ...small, sheet: { direction: 'inward', thickness: 50 } }, /sheet\.thickness: 50 µm inward reaches the tube's axis/],
    ['negative layers', { ...small, sheet: { layers: -1 } }, /sheet\.layers: must be an integer/],
    ['not JSON', '{"cells": 3,', /not valid JSON/],
  ];
  for (const [name, input, message] of badInputs) {
    it(`bad input (${name}): exit 2, one line naming the problem`, () => {
      const run = cli(['run', writeJson(`bad-${name.replace(/\W/g, '')}.json`, input), '--out', join(dir, 'never.json')]);
      expect(run.status).toBe(2);
      expect(run.stderr.trim().split('\n')).toHaveLength(1);
      expect(run.stderr.trim()).toMatch(message);
      expect(run.stderr).not.toMatch(/\n\s+at /); // no stack trace
    });
  }

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
    const scutoids = header.indexOf('labels.percentScutoids');
    const ratio = header.indexOf('sheet.surfaceRatio');
    for (const row of runs.slice(1)) {
      const cells = row.split(',');
      if (cells[ratio] === '1') expect(Number(cells[scutoids])).toBe(0);
      else expect(Number(cells[scutoids])).toBeGreaterThan(0);
    }
    const aggregate = JSON.parse(readFileSync(join(out, 'aggregate.json'), 'utf8'));
    expect(JSON.stringify(aggregate)).toMatch(/percentScutoids/);

    // Cut the last row off (an interrupted sweep) and rerun: only that run is computed again.
    writeFileSync(join(out, 'runs.csv'), runs.slice(0, 4).join('\r\n') + '\r\n');
    const second = cli(['sweep', spec, '--out', out]);
    expect(second.status).toBe(0);
    expect(second.stderr).toMatch(/1 runs computed, 3 resumed/);
    expect(readFileSync(join(out, 'runs.csv'), 'utf8').trim().split(/\r?\n/)).toEqual(runs);
  });
});

