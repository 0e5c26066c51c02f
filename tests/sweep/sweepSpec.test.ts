import { describe, expect, it } from 'vitest';
import { analysisMethods, engineNameFor, validateConfig } from '../../src/core/config';
import { expandSweep, setPath, summaryColumns, sweepColumns, SweepSpecError, validateSweepSpec } from '../../src/core/sweep';

const base = { surface: { kind: 'tube', radius: 16, length: 200 }, resolution: 64, cells: 20, lloyd: { maxIterations: 1 } };

function specError(input: unknown, maxRuns?: number): SweepSpecError {
  try {
    validateSweepSpec(input, { maxRuns, raiseHint: 'pass --max-runs N' });
  } catch (error) {
    expect(error).toBeInstanceOf(SweepSpecError);
    expect((error as Error).message).not.toMatch(/\n/);
    return error as SweepSpecError;
  }
  throw new Error('accepted');
}

describe('sweep spec validation', () => {
  const cases: Array<[string, unknown, string, RegExp]> = [
    ['seed "abc"', { base, seed: 'abc' }, 'seed', /^seed: must be an integer/],
    ['fractional seed', { base, seed: 1.5 }, 'seed', /integer/],
    ['unknown seed mode', { base, seedMode: 'weird' }, 'seedMode', /^seedMode: must be one of "per-realization", "per-run"/],
    ['realizations 1e9', { base, realizations: 1e9 }, 'realizations', /^realizations: must be an integer from 1 to/],
    ['realizations 0', { base, realizations: 0 }, 'realizations', /from 1/],
    ['unknown top-level field', { base, realisations: 3 }, 'realisations', /unknown field of a sweep spec; allowed: base, vary/],
    ['no base', { vary: {} }, 'base', /^base: required/],
    ['unknown field in base', { base: { ...base, cels: 3 } }, 'base.cels', /^base\.cels: unknown field/],
    ['bad value in base', { base: { ...base, cells: -1 } }, 'base.cells', /^base\.cells: must be an integer >= 1/],
    [
      'varied path that does not exist',
      { base, vary: { 'sheet.layer': [1] } },
      'vary["sheet.layer"]',
      /"layer" is not a field of "sheet"; fields there: .*layers/,
    ],
    ['varied path under a leaf', { base, vary: { 'cells.x': [1] } }, 'vary["cells.x"]', /"cells" has no fields inside/],
    ['varied seed', { base, vary: { seed: [1, 2] } }, 'vary["seed"]', /derived per run/],
    [
      'varied value of the wrong type',
      { base, vary: { 'sheet.layers': [1, 'two'] } },
      'vary["sheet.layers"][1]',
      /must be an integer from 0 to 64 \(got "two"\)/,
    ],
    ['varied value out of range', { base, vary: { resolution: [64, 99999] } }, 'vary["resolution"][1]', /from 16 to 16384/],
    ['empty value list', { base, vary: { cells: [] } }, 'vary["cells"]', /at least one value/],
    [
      'a value given twice',
      { base, vary: { cells: [5, 6, 5] } },
      'vary["cells"][2]',
      /^vary\["cells"\]\[2\]: 5 repeats vary\["cells"\]\[0\]; give each value once/,
    ],
    [
      'an object value given twice',
      { base, vary: { density: [{ kind: 'uniform' }, { kind: 'uniform' }] } },
      'vary["density"][1]',
      /repeats vary\["density"\]\[0\]/,
    ],
    ['value list not an array', { base, vary: { cells: 5 } }, 'vary["cells"]', /array/],
    ['__proto__ in a varied path', { base, vary: { '__proto__.polluted': [1] } }, 'vary["__proto__.polluted"]', /"__proto__" is not allowed/],
    ['constructor.prototype in a varied path', { base, vary: { 'constructor.prototype.x': [1] } }, 'vary["constructor.prototype.x"]', /not allowed/],
    ['__proto__ inside base', JSON.parse(`{"base": {"cells": 20, "sheet": {"__proto__": {"layers": 3}}}}`), 'base.sheet.__proto__', /not allowed/],
  ];
  for (const [name, input, field, message] of cases) {
    it(`refuses ${name}, naming ${field}`, () => {
      const error = specError(input);
      expect(error.field).toBe(field);
      expect(error.message).toMatch(message);
    });
  }

  it('refuses a cap that is no number >= 1 (NaN let every spec through)', () => {
    for (const maxRuns of [NaN, 0, -1]) expect(() => validateSweepSpec({ base }, { maxRuns })).toThrow(/maxRuns must be a number >= 1/);
    expect(validateSweepSpec({ base }, { maxRuns: Infinity }).realizations).toBe(1);
  });

  it('caps the number of runs before expanding anything, saying how to raise it', () => {
    const huge = {
      base,
      vary: { cells: Array.from({ length: 300 }, (_, k) => k + 1), 'lloyd.maxIterations': Array.from({ length: 300 }, (_, k) => k) },
      realizations: 60,
    };
    const start = performance.now();
    const error = specError(huge);
    expect(performance.now() - start).toBeLessThan(500);
    expect(error.message).toMatch(/5400000 runs \(300 cells x 300 lloyd\.maxIterations x 60 realizations\), above the limit of 100000; .*--max-runs N/);
    expect(() => validateSweepSpec({ base, realizations: 200 }, { maxRuns: 100 })).toThrow(/200 runs/);
    expect(validateSweepSpec({ base, realizations: 100 }, { maxRuns: 100 }).realizations).toBe(100);
  });

  it('accepts a varied path through either branch of a union, and fills defaults', () => {
    const spec = validateSweepSpec({ base, vary: { 'surface.radius': [8, 16], density: [{ kind: 'uniform' }, { kind: 'image', src: 'a.png' }] } });
    expect(spec.seedMode).toBe('per-realization');
    expect(spec.realizations).toBe(1);
  });
});

describe('setPath never reaches a prototype', () => {
  it('refuses __proto__, constructor and prototype and leaves Object.prototype alone', () => {
    for (const path of ['__proto__.polluted', 'constructor.prototype.polluted', 'a.__proto__.polluted', 'prototype']) {
      expect(() => setPath({}, path, 1)).toThrow(/not a config field/);
    }
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });
  it('does not follow inherited properties or setters', () => {
    const target = Object.create({ inherited: { deep: 1 } }) as Record<string, unknown>;
    setPath(target, 'inherited.deep', 2);
    expect(Object.getPrototypeOf(target).inherited.deep).toBe(1);
    expect((target.inherited as { deep: number }).deep).toBe(2);
  });
});

describe('seeds', () => {
  it('derives 200,000 distinct realization seeds in seconds (quadratic de-duplication would take minutes)', () => {
    const start = performance.now();
    const runs = expandSweep({ base: { seed: 1 }, realizations: 200_000, seedMode: 'per-realization' });
    expect(performance.now() - start).toBeLessThan(4000);
    expect(new Set(runs.map((r) => r.seed)).size).toBe(200_000);
  });
});

describe('runs.csv columns', () => {
  it('are the union over the grid, fixed before any run, whatever the first grid point produces', () => {
    const spec = validateSweepSpec({
      base: { ...base, sheet: { surfaceRatio: 1.5 } },
      vary: { 'sheet.adjacency': ['labels', 'exact', 'both'], 'sheet.layers': [0, 2] },
    });
    const configs = expandSweep(spec).map((r) => validateConfig(r.config));
    const columns = sweepColumns(configs);
    const first = summaryColumns(configs[0]); // labels only, no layers
    expect(first.some((c) => c.startsWith('exact.'))).toBe(false);
    expect(columns).toContain('exact.percentScutoids');
    expect(columns).toContain('labels.layer2.meanSides');
    expect(columns).toContain('exact.layer1.polygons.10+');
    for (const config of configs) for (const c of summaryColumns(config)) expect(columns).toContain(c);
    expect(new Set(columns).size).toBe(columns.length);
    // the order does not depend on the order of the grid
    expect(sweepColumns([...configs].reverse()).filter((c) => !c.includes('layer'))).toEqual(columns.filter((c) => !c.includes('layer')));
  });
  it('give every closed surface the exact columns (the restricted Voronoi diagram) wherever the method is asked for', () => {
    const surfaces = [
      { kind: 'sphere', radius: 12 },
      { kind: 'ellipsoid', a: 10, b: 12, c: 14 },
      { kind: 'mesh', src: 'organoid.ply', scale: 20 },
    ];
    for (const surface of surfaces) {
      for (const adjacency of ['labels', 'exact', 'both'] as const) {
        const config = validateConfig({ ...base, surface, sheet: { adjacency, thickness: 2 } });
        const columns = summaryColumns(config);
        expect(
          columns.some((c) => c.startsWith('exact.')),
          `${surface.kind} ${adjacency}`,
        ).toBe(adjacency !== 'labels');
        expect(
          columns.some((c) => c.startsWith('labels.')),
          `${surface.kind} ${adjacency}`,
        ).toBe(adjacency !== 'exact');
        // the columns' methods are those the pipeline computes (core/config/analysisMethods.ts) on
        // either engine the policy may pick for it (a GPU, or a software renderer)
        const methods = new Set(columns.flatMap((c) => (c.includes('.') ? [c.split('.')[0]] : [])));
        const engines = [false, true].map((softwareRenderer) => engineNameFor(config, { softwareRenderer }));
        const computed = new Set(engines.flatMap((engine) => analysisMethods(config, engine)));
        expect([...methods].sort()).toEqual([...computed].sort());
      }
    }
  });
});
