/**
 * runs.csv and aggregate.csv as a pandas user reads them (docs/sweep.md, "Reading the files"):
 * units in the header names, the base geometry and the scutoid, won and lost counts in every
 * row, only meaningful statistics in the aggregate; an older file refused on resume; a runs.csv
 * that is a directory refused by name.
 */
import { spawnSync } from 'node:child_process';
import { mkdirSync, mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { describe, expect, it } from 'vitest';
import { validateConfig } from '../../src/core/config';
import { schemaField } from '../../src/core/config/schemaFields';
import { fileColumn, plainColumn, readCsvTable, readRunsCsv } from '../../src/core/sweep';

const bin = join(__dirname, 'fromSource.mjs');
const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-pandas-'));
const cli = (args: string[]) => spawnSync(process.execPath, [bin, ...args], { encoding: 'utf8', env: process.env });

const base = {
  surface: { kind: 'tube', radius: 40, length: 400 },
  resolution: 128,
  cells: 40,
  minSpacing: 2,
  engine: 'exact',
  lloyd: { maxIterations: 2 },
  sheet: { surfaceRatio: 1.8, adjacency: 'exact' },
};
const spec = { base, vary: { 'sheet.surfaceRatio': [1.5, 2.5] }, realizations: 3, seed: 7 };
const specPath = join(dir, 'spec.json');
writeFileSync(specPath, JSON.stringify(spec));
const out = join(dir, 'out');
const run = cli(['sweep', specPath, '--out', out, '--workers', '1']);

describe('runs.csv for pandas', () => {
  const text = readFileSync(join(out, 'runs.csv'), 'utf8');
  const file = readCsvTable(text);
  const rows = readRunsCsv(text).rows;

  it('names every column with its unit: config units from the schema, % and fractions from the definitions', () => {
    expect(run.status, run.stderr).toBe(0);
    for (const name of file.header) {
      const plain = plainColumn(name);
      expect(fileColumn(plain), name).toBe(name);
      let schemaUnit: string | null = null;
      try {
        schemaUnit = schemaField(plain).unit;
      } catch {
        schemaUnit = null;
      }
      const unit = name.includes('_') ? name.slice(name.indexOf('_') + 1) : null;
      if (schemaUnit === 'µm') expect(unit, name).toBe('um');
      else if (plain.endsWith('.percentScutoids')) expect(unit, name).toBe('pct');
      else if (/\.polygons\./.test(plain)) expect(unit, name).toBe('frac');
      else if (plain === 'finalEnergy') expect(unit, name).toBe('um4');
      else expect(unit, name).toBeNull();
    }
    expect(file.header).toContain('surface.radius_um');
    expect(file.header).toContain('exact.basal.polygons.6_frac');
  });

  it('carries the base geometry of each run: the validated config, not the varied field twice', () => {
    const config = validateConfig(base) as unknown as Record<string, Record<string, unknown>>;
    for (const row of rows) {
      expect(row['surface.kind']).toBe('tube');
      expect(Number(row['surface.radius'])).toBe(40);
      expect(Number(row['surface.length'])).toBe(400);
      expect(Number(row.cells)).toBe(40);
      expect(Number(row.minSpacing)).toBe(2);
      expect(Number(row['lloyd.maxIterations'])).toBe(2);
      expect(row['sheet.seeded']).toBe(String(config.sheet.seeded));
      expect(row['sheet.protocol']).toBe(String(config.sheet.protocol));
      expect(row.engine).toBe('exact');
    }
    expect(file.header.filter((h) => plainColumn(h) === 'sheet.surfaceRatio')).toHaveLength(1);
  });

  it('has scutoid, valid-cell, won and lost counts that agree with the percentages and transitions', () => {
    for (const row of rows) {
      const valid = Number(row['exact.validCells']);
      expect(valid + Number(row['exact.excludedCells'])).toBe(40);
      expect(Number(row['exact.scutoids'])).toBe(Math.round((Number(row['exact.percentScutoids']) * valid) / 100));
      // Two surfaces, no layers: transitions = won + lost for every cell (scutoids.ts).
      expect(Number(row['exact.meanWon']) + Number(row['exact.meanLost'])).toBeCloseTo(Number(row['exact.meanTransitions']), 12);
      expect(Number(row['exact.meanWon'])).toBeGreaterThan(0);
    }
  });
});

describe('aggregate.csv for pandas', () => {
  it('keeps only meaningful statistics, each equal to its definition over runs.csv', () => {
    const agg = readCsvTable(readFileSync(join(out, 'aggregate.csv'), 'utf8'));
    const rows = readRunsCsv(readFileSync(join(out, 'runs.csv'), 'utf8')).rows;
    for (const name of agg.header) {
      expect(name, name).not.toMatch(/^(iterations|finalEnergy|centroidPath)\.|excludedCells|\.se(_|$)/);
    }
    const metrics = ['percentScutoids', 'scutoids', 'validCells', 'meanTransitions', 'meanWon', 'meanLost', 'meanNeighbours3D'];
    const expected = [
      'sheet.surfaceRatio',
      'runs',
      ...metrics.flatMap((m) => ['mean', 'sd', 'ci95low', 'ci95high', 'n'].map((s) => `exact.${m}.${s}${s !== 'n' && m === 'percentScutoids' ? '_pct' : ''}`)),
    ];
    expect(agg.header.slice(0, expected.length)).toEqual(expected);
    expect(agg.header.filter((h) => /\.polygons\./.test(h)).every((h) => /\.polygons\.[^.]+\.mean_frac$/.test(h))).toBe(true);
    expect(agg.header.filter((h) => /meanSides/.test(h)).every((h) => /meanSides\.(mean|sd)$/.test(h))).toBe(true);
    for (const point of agg.rows) {
      const values = rows.filter((r) => r['sheet.surfaceRatio'] === point['sheet.surfaceRatio']).map((r) => Number(r['exact.percentScutoids']));
      const n = values.length;
      const mean = values.reduce((a, b) => a + b, 0) / n;
      const sd = Math.sqrt(values.reduce((a, b) => a + (b - mean) ** 2, 0) / (n - 1));
      expect(Number(point['exact.percentScutoids.n'])).toBe(3);
      expect(Number(point['exact.percentScutoids.mean_pct'])).toBeCloseTo(mean, 10);
      expect(Number(point['exact.percentScutoids.sd_pct'])).toBeCloseTo(sd, 10);
      // t(0.975, 2) = 4.3027 (tables)
      expect(Number(point['exact.percentScutoids.ci95low_pct'])).toBeCloseTo(mean - (4.3027 * sd) / Math.sqrt(3), 2);
      expect(Number(point['exact.percentScutoids.ci95high_pct'])).toBeCloseTo(mean + (4.3027 * sd) / Math.sqrt(3), 2);
    }
  });
});

describe('runs.csv that cannot be resumed', () => {
  it('refuses a runs.csv written before units (the plain header), saying why, exit 2', () => {
    const old = join(dir, 'old');
    mkdirSync(old);
    writeFileSync(join(old, 'sweep.json'), readFileSync(join(out, 'sweep.json')));
    const text = readFileSync(join(out, 'runs.csv'), 'utf8');
    const [head, ...rest] = text.split('\r\n');
    writeFileSync(join(old, 'runs.csv'), [head.split(',').map(plainColumn).join(','), ...rest].join('\r\n'));
    const r = cli(['sweep', specPath, '--out', old]);
    expect(r.status).toBe(2);
    expect(r.stderr).toMatch(/^tissue-sheet: .*old\/runs\.csv: written by an older tissue-sheet \(its header has no units/m);
    expect(readFileSync(join(old, 'runs.csv'), 'utf8')).not.toBe(text);
  });

  it('refuses a runs.csv that is a directory, naming it, exit 2 (sweep and merge)', () => {
    const odd = join(dir, 'odd');
    mkdirSync(join(odd, 'runs.csv'), { recursive: true });
    writeFileSync(join(odd, 'sweep.json'), readFileSync(join(out, 'sweep.json')));
    const r = cli(['sweep', specPath, '--out', odd]);
    expect(r.status).toBe(2);
    expect(r.stderr.trim()).toMatch(/^tissue-sheet: .*odd\/runs\.csv: is a directory, not a runs file; move it away/);
    expect(r.stderr).not.toMatch(/EISDIR/);
    const m = cli(['merge', out, odd, '--out', join(dir, 'merged')]);
    expect(m.status).toBe(2);
    expect(m.stderr).toMatch(/odd\/runs\.csv: is a directory/);
  });
});
