import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import {
  ConfigError,
  DEFAULT_TUBE_RADIUS,
  checkFeasible,
  configSchema,
  makeGrid,
  unrolledDomain,
  validateConfig,
  type ClosedConfig,
  type PlanarConfig,
} from '../../src/core/config';
import { checkClosedFeasible } from '../../src/core/config/feasibility';
import { validatePlanarConfig } from '../planarConfig';

/** Runs validatePlanarConfig and returns the ConfigError it throws (fails the test if none). */
function errorOf(input: unknown): ConfigError {
  try {
    validatePlanarConfig(input);
  } catch (error) {
    expect(error).toBeInstanceOf(ConfigError);
    const e = error as ConfigError;
    // One line, starting with the field it names.
    expect(e.message).not.toContain('\n');
    expect(e.message.startsWith(`${e.field === '' ? 'config' : e.field}: `)).toBe(true);
    return e;
  }
  throw new Error(`expected a ConfigError for ${JSON.stringify(input)}`);
}

function feasibilityError(input: unknown): ConfigError | null {
  const config = validatePlanarConfig(input);
  try {
    checkFeasible(config, makeGrid(config));
    return null;
  } catch (error) {
    expect(error).toBeInstanceOf(ConfigError);
    return error as ConfigError;
  }
}

describe('validatePlanarConfig: defaults', () => {
  it('fills every default from an empty object', () => {
    const config = validatePlanarConfig({});
    expect(config.surface).toEqual({ kind: 'tube', radius: DEFAULT_TUBE_RADIUS, length: 4096 });
    expect(2 * Math.PI * (config.surface as { radius: number }).radius).toBeCloseTo(512, 9);
    expect(config.resolution).toBe(512);
    expect(config.cells).toBe(200);
    expect(config.seed).toBe(1);
    expect(config.minSpacing).toBe(0);
    expect(config.density).toEqual({ kind: 'uniform' });
    expect(config.lloyd).toEqual({ maxIterations: 50, tolerance: 0, overRelaxation: 1, warmStart: true });
    expect(config.jumpFlood).toEqual({ variant: 'jfa+2' });
    expect(config.centroidPath).toBe('auto');
  });

  it('fills defaults inside the chosen union branch and partial objects', () => {
    const config = validatePlanarConfig({
      surface: { kind: 'plane', width: 100, height: 50 },
      density: { kind: 'image', src: 'a.png' },
      lloyd: { maxIterations: 3 },
    });
    expect(config.surface).toEqual({ kind: 'plane', width: 100, height: 50, periodicX: false, periodicY: false });
    expect(config.density).toEqual({ kind: 'image', src: 'a.png', low: 1, high: 16, invert: false });
    expect(config.lloyd).toEqual({ maxIterations: 3, tolerance: 0, overRelaxation: 1, warmStart: true });
  });

  it('does not modify its input and returns a fresh object each time', () => {
    const input = { lloyd: { maxIterations: 3 } };
    const frozen = JSON.stringify(input);
    const a = validatePlanarConfig(input);
    expect(JSON.stringify(input)).toBe(frozen);
    const b = validatePlanarConfig(input);
    a.lloyd.tolerance = 5;
    (a.surface as { length: number }).length = 1;
    expect(b.lloyd.tolerance).toBe(0);
    expect(validatePlanarConfig({}).surface).toEqual({ kind: 'tube', radius: DEFAULT_TUBE_RADIUS, length: 4096 });
  });

  it('keeps a valid complete config unchanged', () => {
    const full: PlanarConfig = {
      surface: { kind: 'plane', width: 300, height: 200, periodicX: true, periodicY: true },
      resolution: 256,
      cells: 100,
      seed: 4294967295,
      minSpacing: 2.5,
      density: { kind: 'gaussian', center: [150, 100], sigma: 30, peak: 4 },
      lloyd: { maxIterations: 10, tolerance: 0.01, overRelaxation: 1.5, warmStart: false },
      jumpFlood: { variant: '1+jfa' },
      centroidPath: 'gather',
      engine: 'gpu',
      sheet: {
        seeded: 'apical',
        direction: 'inward',
        thickness: 4,
        surfaceRatio: null,
        offset: 'normal',
        layers: 2,
        adjacency: 'labels',
        protocol: 'default',
        layerStep: null,
        validityMaxRatio: 10,
        minContactPixels: 3,
        minContactLength: 1.5,
      },
    };
    expect(validatePlanarConfig(full)).toEqual(full);
  });
});

describe('validatePlanarConfig: errors name the exact field', () => {
  it('bounds, with unit and value', () => {
    const e = errorOf({ surface: { kind: 'tube', radius: -3, length: 10 } });
    expect(e.field).toBe('surface.radius');
    expect(e.message).toBe('surface.radius: must be > 0 µm (got -3)');
    expect(errorOf({ resolution: 8 }).message).toBe('resolution: must be an integer from 16 to 16384 or null (got 8)');
    expect(errorOf({ resolution: 20000 }).field).toBe('resolution');
    expect(errorOf({ cells: 0 }).message).toBe('cells: must be an integer >= 1 (got 0)');
    expect(errorOf({ seed: 2 ** 32 }).field).toBe('seed');
    expect(errorOf({ seed: -1 }).field).toBe('seed');
    expect(errorOf({ minSpacing: -1 }).message).toBe('minSpacing: must be >= 0 µm (got -1)');
    expect(errorOf({ lloyd: { overRelaxation: 2 } }).message).toBe('lloyd.overRelaxation: must be from 1 to 1.95 (got 2)');
    expect(errorOf({ lloyd: { maxIterations: 100001 } }).field).toBe('lloyd.maxIterations');
    expect(errorOf({ lloyd: { tolerance: -0.1 } }).field).toBe('lloyd.tolerance');
  });

  it('unknown fields list the allowed ones', () => {
    const e = errorOf({ lloyd: { maxIter: 3 } });
    expect(e.field).toBe('lloyd.maxIter');
    expect(e.message).toBe('lloyd.maxIter: unknown field; allowed: maxIterations, tolerance, overRelaxation, warmStart');
    expect(errorOf({ cellCount: 3 }).field).toBe('cellCount');
    // A field of the other branch of a union is unknown in this one.
    const branch = errorOf({ surface: { kind: 'tube', radius: 1, length: 2, width: 3 } });
    expect(branch.field).toBe('surface.width');
    expect(branch.message).toBe('surface.width: unknown field; allowed: kind, radius, length');
    expect(errorOf({ jumpFlood: { steps: 3 } }).field).toBe('jumpFlood.steps');
  });

  it('missing required fields name the branch', () => {
    const e = errorOf({ surface: { kind: 'plane', width: 3 } });
    expect(e.field).toBe('surface.height');
    expect(e.message).toContain('required for kind "plane"');
    expect(errorOf({ density: { kind: 'gaussian', center: [0, 0], sigma: 1 } }).field).toBe('density.peak');
    const kind = errorOf({ surface: { radius: 3, length: 3 } });
    expect(kind.field).toBe('surface.kind');
    expect(kind.message).toContain('"plane", "tube"');
  });

  it('unknown union kinds list the kinds', () => {
    const e = errorOf({ surface: { kind: 'cone' } });
    expect(e.field).toBe('surface.kind');
    expect(e.message).toBe('surface.kind: must be one of "plane", "tube", "sphere", "ellipsoid", "mesh" (got "cone")');
    const d = errorOf({ density: { kind: 'noise' } });
    expect(d.field).toBe('density.kind');
    expect(d.message).toContain('"uniform", "linear", "gaussian", "stripes", "image"');
  });

  it('wrong types, enums, strings and arrays', () => {
    expect(errorOf({ cells: '200' }).message).toBe('cells: must be an integer >= 1 (got "200")');
    expect(errorOf({ cells: 2.5 }).field).toBe('cells');
    expect(errorOf({ surface: { kind: 'plane', width: 1, height: 1, periodicX: 'yes' } }).message).toBe('surface.periodicX: must be true or false (got "yes")');
    expect(errorOf({ jumpFlood: { variant: 'jfa+1' } }).message).toBe('jumpFlood.variant: must be one of "jfa+2", "1+jfa", "jfa" (got "jfa+1")');
    expect(errorOf({ centroidPath: 'fast' }).field).toBe('centroidPath');
    expect(errorOf({ density: { kind: 'linear', axis: 'z', from: 1, to: 2 } }).field).toBe('density.axis');
    expect(errorOf({ density: { kind: 'image', src: '' } }).field).toBe('density.src');
    expect(errorOf({ density: { kind: 'gaussian', center: [1], sigma: 1, peak: 2 } }).field).toBe('density.center');
    expect(errorOf({ density: { kind: 'gaussian', center: [1, 2, 3], sigma: 1, peak: 2 } }).field).toBe('density.center');
    expect(errorOf({ density: { kind: 'gaussian', center: [1, 'a'], sigma: 1, peak: 2 } }).field).toBe('density.center[1]');
    expect(errorOf({ density: { kind: 'stripes', axis: 'x', period: 0, low: 1, high: 2 } }).field).toBe('density.period');
    expect(errorOf({ lloyd: 3 }).message).toBe('lloyd: must be an object (got 3)');
    expect(errorOf(null).field).toBe('');
    expect(errorOf([]).message).toContain('config: must be an object');
  });

  it('rejects NaN, Infinity and non-JSON values explicitly', () => {
    const nan = errorOf({ surface: { kind: 'tube', radius: NaN, length: 3 } });
    expect(nan.field).toBe('surface.radius');
    expect(nan.message).toContain('got NaN');
    expect(errorOf({ minSpacing: Infinity }).field).toBe('minSpacing');
    expect(errorOf({ density: { kind: 'gaussian', center: [0, -Infinity], sigma: 1, peak: 2 } }).field).toBe('density.center[1]');
    expect(errorOf({ seed: () => 1 }).field).toBe('seed');
    expect(errorOf({ cells: new Date(0) }).field).toBe('cells');
  });

  it('treats an undefined field as absent', () => {
    expect(validatePlanarConfig({ cells: undefined }).cells).toBe(200);
  });
});

describe('configSchema', () => {
  it('documents every property and forbids unknown fields in every object', () => {
    const visit = (node: Record<string, unknown>, path: string): void => {
      if (node.type === 'object' && node.properties) expect(node.additionalProperties, path).toBe(false);
      for (const branch of (node.oneOf as Record<string, unknown>[] | undefined) ?? []) visit(branch, path);
      const properties = (node.properties ?? {}) as Record<string, Record<string, unknown>>;
      for (const [name, child] of Object.entries(properties)) {
        expect(typeof child.description, `${path}.${name}`).toBe('string');
        expect((child.description as string).length).toBeGreaterThan(10);
        visit(child, `${path}.${name}`);
      }
    };
    visit(configSchema as unknown as Record<string, unknown>, '');
  });
});

describe('makeGrid', () => {
  it('gives the default tube 64 x 512 square texels of 8 µm, periodic around', () => {
    const grid = makeGrid(validatePlanarConfig({}));
    expect(grid).toEqual({ width: 64, height: 512, texelX: 8, texelY: 8, periodicX: true, periodicY: false });
    const fine = makeGrid(validatePlanarConfig({ resolution: 4096 }));
    expect([fine.width, fine.height]).toEqual([512, 4096]);
    expect(fine.texelX).toBeCloseTo(1, 12);
  });

  it('keeps lengths exact and texels nearly square for odd aspect ratios', () => {
    for (const [w, h, res] of [
      [300, 200, 256],
      [123.4, 987.6, 100],
      [1000, 1, 64],
    ] as const) {
      const config = validatePlanarConfig({ surface: { kind: 'plane', width: w, height: h }, resolution: res });
      const grid = makeGrid(config);
      expect(Math.max(grid.width, grid.height)).toBe(res);
      expect(grid.width * grid.texelX).toBeCloseTo(w, 9);
      expect(grid.height * grid.texelY).toBeCloseTo(h, 9);
      expect(Math.min(grid.width, grid.height)).toBeGreaterThanOrEqual(1);
      const domain = unrolledDomain(config.surface);
      const texel = Math.max(w, h) / res;
      // The short side is within half a texel of its exact length.
      const shortTexels = w >= h ? grid.height : grid.width;
      const shortLength = w >= h ? domain.lengthY : domain.lengthX;
      if (shortLength / texel >= 1) expect(Math.abs(shortTexels - shortLength / texel)).toBeLessThanOrEqual(0.5);
    }
  });
});

describe('checkFeasible', () => {
  it('accepts the defaults', () => {
    expect(feasibilityError({})).toBeNull();
  });

  it('needs 16 texels per cell', () => {
    const e = feasibilityError({ surface: { kind: 'plane', width: 100, height: 100 }, resolution: 256, cells: 5000 });
    expect(e?.field).toBe('cells');
    expect(e?.message).toBe('cells: 5000 cells need at least 80000 texels (16 per cell) but the grid has 65536; lower cells or raise resolution');
    expect(feasibilityError({ surface: { kind: 'plane', width: 100, height: 100 }, resolution: 256, cells: 4096 })).toBeNull();
  });

  it('bounds the minimum spacing by hexagonal packing', () => {
    // 100 x 100 µm torus: 100 points fit at spacing d only if 100·(√3/2)·d² <= 10000, d <= 10.75 µm.
    const base = { surface: { kind: 'plane', width: 100, height: 100, periodicX: true, periodicY: true }, cells: 100 };
    const e = feasibilityError({ ...base, minSpacing: 10.8 });
    expect(e?.field).toBe('minSpacing');
    expect(e?.message).toMatch(/\(hexagonal packing\).*lower minSpacing to at most 10\.7457 µm/);
  });

  it('bounds it by the jamming of random placement, which comes well before the lattice', () => {
    // Random sequential addition jams when the disks cover 0.547 of the area: 100 points on the
    // 100 x 100 µm torus at d <= sqrt(4·0.547·10000/(π·100)) = 8.35 µm; a closed surface alike.
    const torus = { surface: { kind: 'plane', width: 100, height: 100, periodicX: true, periodicY: true }, cells: 100 };
    expect(feasibilityError({ ...torus, minSpacing: 8.3 })).toBeNull();
    for (const minSpacing of [8.4, 10.7]) {
      const e = feasibilityError({ ...torus, minSpacing });
      expect(e?.field).toBe('minSpacing');
      expect(e?.message).toMatch(/random placement jams near 54\.7 %; lower minSpacing to well below 8\.34543 µm or lower cells/);
    }
    // A density field places by rejection too, but its jam is not predicted: found as it happens.
    expect(feasibilityError({ ...torus, minSpacing: 8.4, density: { kind: 'linear', axis: 'x', from: 1, to: 2 } })).toBeNull();
    // A sphere of radius 20 µm: 100 points up to sqrt(4·0.547·5026.5/(π·100)) = 5.917 µm apart.
    const sphere = (minSpacing: number) =>
      checkClosedFeasible(
        validateConfig({ surface: { kind: 'sphere', radius: 20 }, cells: 100, resolution: 64, minSpacing, sheet: { thickness: 2 } }) as ClosedConfig,
      );
    expect(() => sphere(5.9)).not.toThrow();
    expect(() => sphere(6)).toThrow(/minSpacing: .*random placement jams near 54\.7 %; lower minSpacing to well below 5\.9167\d* µm/);
  });

  it('keeps densities within what the density texture holds, and stripes at least two texels wide', () => {
    // The default tube: 64 x 512 texels of 8 µm.
    const extreme = feasibilityError({ density: { kind: 'linear', axis: 'x', from: 1e-300, to: 1e300 } });
    expect(extreme?.field).toBe('density.from');
    expect(extreme?.message).toMatch(/^density\.from: 1e-300 is outside 1e-30 to 1e\+30/);
    expect(feasibilityError({ density: { kind: 'stripes', axis: 'y', period: 1e10, low: 1, high: 1e31 } })?.field).toBe('density.high');
    expect(feasibilityError({ density: { kind: 'linear', axis: 'x', from: 1e-6, to: 1e6 } })).toBeNull();
    // A period of 1e-6 µm never finished on the exact engine (every cell cut at each stripe).
    const fine = feasibilityError({ density: { kind: 'stripes', axis: 'x', period: 1e-6, low: 1, high: 2 } });
    expect(fine?.field).toBe('density.period');
    expect(fine?.message).toMatch(/^density\.period: 0\.000001 µm is finer than two texels of this grid \(2 x 8 µm along x\).*at least 16 µm/);
    expect(feasibilityError({ density: { kind: 'stripes', axis: 'x', period: 16, low: 1, high: 2 } })).toBeNull();
  });

  it('keeps a gaussian centre inside the domain', () => {
    const inside = { kind: 'gaussian', center: [512, 4096], sigma: 10, peak: 3 };
    expect(feasibilityError({ density: inside })).toBeNull();
    const e = feasibilityError({ density: { ...inside, center: [513, 10] } });
    expect(e?.field).toBe('density.center');
    expect(e?.message).toContain('outside the domain');
    expect(feasibilityError({ density: { ...inside, center: [10, -1] } })?.field).toBe('density.center');
  });
});

describe('docs/config.md', () => {
  const text = readFileSync(fileURLToPath(new URL('../../docs/config.md', import.meta.url)), 'utf8');

  it('has examples that validate and are feasible', () => {
    const blocks = [...text.matchAll(/```json\n([\s\S]*?)```/g)].map((m) => JSON.parse(m[1]) as unknown);
    expect(blocks.length).toBeGreaterThanOrEqual(2);
    for (const block of blocks) {
      const config = validatePlanarConfig(block);
      expect(() => checkFeasible(config, makeGrid(config))).not.toThrow();
    }
    // The first example spells out every top-level field.
    expect(Object.keys(blocks[0] as object).sort()).toEqual(Object.keys(configSchema.properties).sort());
  });

  it('mentions every field of the schema', () => {
    const names = new Set<string>();
    const visit = (node: Record<string, unknown>) => {
      for (const branch of (node.oneOf as Record<string, unknown>[] | undefined) ?? []) visit(branch);
      for (const [name, child] of Object.entries((node.properties ?? {}) as Record<string, Record<string, unknown>>)) {
        names.add(name);
        visit(child);
      }
    };
    visit(configSchema as unknown as Record<string, unknown>);
    for (const name of names) expect(text, name).toContain(`\`${name}\``);
  });
});
