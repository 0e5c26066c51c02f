import { describe, expect, it } from 'vitest';
import {
  defaultResolution,
  checkClosedFeasible,
  ConfigError,
  ellipsoidArea,
  minCurvatureRadius,
  validateConfig,
  type ClosedConfig,
  type ConfigInput,
} from '../../src/core/config';

const closed = (input: ConfigInput) => validateConfig(input) as ClosedConfig;
const feasibility = (input: ConfigInput) => {
  try {
    checkClosedFeasible(closed(input));
    return null;
  } catch (e) {
    return e as ConfigError;
  }
};

describe('closed surface config', () => {
  it('fills defaults and validates the new kinds', () => {
    const mesh = closed({ surface: { kind: 'mesh', src: 'organoid.ply' } });
    expect(mesh.surface).toEqual({ kind: 'mesh', src: 'organoid.ply', scale: 1, geodesic: false });
    expect(() => validateConfig({ surface: { kind: 'ellipsoid', a: 1, b: 1 } })).toThrow('surface.c: required for kind "ellipsoid"; add a number > 0 µm');
    expect(() => validateConfig({ surface: { kind: 'sphere', radius: -1 } })).toThrow('surface.radius: must be > 0 µm (got -1)');
  });
  it('cells <= 6 n² / 16, uniform density, exact on every closed surface, no surface ratio, no exact engine', () => {
    expect(feasibility({ surface: { kind: 'sphere', radius: 50 }, resolution: 32, cells: 384 })).toBeNull();
    expect(feasibility({ surface: { kind: 'sphere', radius: 50 }, resolution: 32, cells: 385 })?.message).toBe(
      'cells: 385 cells need at least 6160 texels (16 per cell) but the cube map has 6144 (6 x 32²); lower cells or raise resolution',
    );
    expect(
      feasibility({ surface: { kind: 'sphere', radius: 50 }, resolution: 32, cells: 10, density: { kind: 'linear', axis: 'x', from: 1, to: 2 } })?.field,
    ).toBe('density.kind');
    // The restricted Voronoi diagram is exact on every closed surface.
    expect(feasibility({ surface: { kind: 'ellipsoid', a: 2, b: 1, c: 1 }, resolution: 32, cells: 10, sheet: { adjacency: 'exact' } })).toBeNull();
    expect(feasibility({ surface: { kind: 'ellipsoid', a: 20, b: 10, c: 10 }, resolution: 32, cells: 10, engine: 'exact' })?.field).toBe('engine');
    expect(feasibility({ surface: { kind: 'sphere', radius: 50 }, resolution: 32, cells: 10, sheet: { surfaceRatio: 2 } })?.field).toBe('sheet.surfaceRatio');
    expect(feasibility({ surface: { kind: 'sphere', radius: 10 }, resolution: 64, cells: 100, minSpacing: 5 })?.field).toBe('minSpacing');
  });
  it('smallest radius of curvature: R, and (min semi-axis)² / (max semi-axis)', () => {
    expect(minCurvatureRadius({ kind: 'sphere', radius: 7 })).toBe(7);
    expect(minCurvatureRadius({ kind: 'ellipsoid', a: 100, b: 50, c: 50 })).toBe(25);
    expect(minCurvatureRadius({ kind: 'ellipsoid', a: 30, b: 60, c: 45 })).toBe(15);
    expect(ellipsoidArea(10, 10, 10) / (4 * Math.PI * 100)).toBeCloseTo(1, 6);
  });
});

describe('directionTexel (allocation-free) and directionToTexel follow the GL cube-map face rule', () => {
  it('on random directions and on cube edges and corners', async () => {
    const { directionTexel } = await import('../../src/core/closed/projector');
    const { directionTexelReference } = await import('../oracles/cubeMap');
    const { createRandom } = await import('../../src/core/random');
    const random = createRandom(9);
    const dirs: number[][] = [
      [1, 1, 1],
      [-1, 1, 0],
      [0, -1, -1],
      [1, 0, 0],
      [0, 0, -1],
      [-1, -1, -1],
    ];
    for (let k = 0; k < 2000; k++) dirs.push([random.next() - 0.5, random.next() - 0.5, random.next() - 0.5]);
    const { directionToTexel, texelIndex } = await import('../../src/core/cubemap/cubemap');
    for (const [x, y, z] of dirs) {
      for (const n of [7, 64]) {
        const expected = directionTexelReference(x, y, z, n);
        expect(directionTexel(x, y, z, n)).toBe(expected);
        const t = directionToTexel([x, y, z], n);
        expect(texelIndex(t.face, t.i, t.j, n)).toBe(expected);
      }
    }
  });
});

describe('one default resolution for closed surfaces', () => {
  it('validation fills it in from the cells and the minimum contact length: a texel edge at most half the shortest counted contact', () => {
    for (const cells of [50, 200, 1000]) {
      for (const surface of [
        { kind: 'sphere', radius: 60 },
        { kind: 'ellipsoid', a: 90, b: 45, c: 45 },
      ] as const) {
        const config = validateConfig({ surface, cells });
        const area = surface.kind === 'sphere' ? 4 * Math.PI * surface.radius ** 2 : ellipsoidArea(surface.a, surface.b, surface.c);
        const contact = (6 / 102.4) * Math.sqrt(area / cells);
        const texel = Math.sqrt(area / (6 * config.resolution ** 2));
        expect(texel).toBeLessThanOrEqual(contact / 2);
        // The smallest such multiple of 8: one step coarser breaks the rule.
        expect(Math.sqrt(area / (6 * (config.resolution - 8) ** 2))).toBeGreaterThan(contact / 2);
        expect(config.resolution).toBe(defaultResolution(config));
      }
    }
    // A given contact length is honoured where the area is known.
    const fine = validateConfig({ surface: { kind: 'sphere', radius: 60 }, cells: 200, sheet: { minContactLength: 0.5 } });
    expect(Math.sqrt((4 * Math.PI * 3600) / (6 * fine.resolution ** 2))).toBeLessThanOrEqual(0.25);
    // Planes and tubes keep 512; an explicit resolution is kept.
    expect(validateConfig({}).resolution).toBe(512);
    expect(validateConfig({ surface: { kind: 'sphere', radius: 60 }, resolution: 48 }).resolution).toBe(48);
  });
});
