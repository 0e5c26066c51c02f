import { describe, expect, it } from 'vitest';
import { ConfigError, validateConfig } from '../../src/core/config';
import { checkLimits, estimateRun } from '../../src/core/config/limits';
import { layoutOfKind, maxResolution, surfaceLayout } from '../../src/core/config/surfaceLayout';

const budget = { maxTextureSize: 16384, maxWork: Infinity, maxBytes: Infinity };
const base = { cells: 20, lloyd: { maxIterations: 2 }, sheet: { thickness: 2, layers: 0 } };

const surfaces = {
  plane: { kind: 'plane', width: 200, height: 100 },
  tube: { kind: 'tube', radius: 16, length: 200 },
  sphere: { kind: 'sphere', radius: 50 },
  ellipsoid: { kind: 'ellipsoid', a: 60, b: 40, c: 30 },
} as const;

function layoutOf(surface: object, resolution: number) {
  return surfaceLayout(validateConfig({ ...base, surface, resolution }));
}

describe('surfaceLayout: the one place a surface kind becomes a layout', () => {
  it('lays planes and tubes on a planar grid, closed kinds on a cube map', () => {
    for (const kind of ['plane', 'tube']) {
      const layout = layoutOfKind(kind);
      expect(layout).toMatchObject({ name: 'planar grid', textureName: 'grid', rowsPerResolution: 1, extraBytesPerTexel: 0 });
      expect(layout).toMatchObject({ aspectSetsShortSide: true, flatPicture: true, exactEngine: true, uniformDensityOnly: false });
    }
    for (const kind of ['sphere', 'ellipsoid', 'mesh']) {
      const layout = layoutOfKind(kind);
      expect(layout).toMatchObject({ name: 'cube map', textureName: 'cube map', rowsPerResolution: 6, extraBytesPerTexel: 60 });
      expect(layout).toMatchObject({ aspectSetsShortSide: false, flatPicture: false, exactEngine: false, uniformDensityOnly: true });
    }
    expect(layoutOf(surfaces.sphere, 64).name).toBe('cube map');
    expect(layoutOf(surfaces.plane, 64).name).toBe('planar grid');
  });

  it('gives every surface of the stack its texels: the unrolled grid, or n x 6n per cube map', () => {
    // A plane 200 x 100 µm at resolution 512: 512 x 256 texels, the other surface the same.
    expect(layoutOf(surfaces.plane, 512).grids()).toEqual([
      { width: 512, height: 256 },
      { width: 512, height: 256 },
    ]);
    // A tube of radius 16 µm (circumference 100.5 µm) and length 200 µm: the length gets the
    // resolution; the outer surface (radius 18) is wider by 18/16.
    const tube = layoutOf(surfaces.tube, 512).grids();
    expect(tube[0]).toEqual({ width: 257, height: 512 });
    expect(tube[1]).toEqual({ width: Math.round(257 * (18 / 16)), height: 512 });
    for (const surface of [surfaces.sphere, surfaces.ellipsoid]) {
      expect(layoutOf(surface, 64).grids()).toEqual([
        { width: 64, height: 384 },
        { width: 64, height: 384 },
      ]);
    }
  });

  it('gives the budget its numbers: bytes per texel and the largest resolution a texture limit allows', () => {
    const plane = validateConfig({ ...base, surface: surfaces.plane, resolution: 512, engine: 'gpu' });
    const sphere = validateConfig({ ...base, surface: surfaces.sphere, resolution: 64 });
    // Active texels: 76 bytes on a grid, 76 + 60 on a cube map; kept: 8 per texel of every surface.
    expect(estimateRun(plane).bytes - estimateRun(plane).cellBytes).toBe(76 * 512 * 256 + 8 * 2 * 512 * 256);
    expect(estimateRun(sphere).bytes - estimateRun(sphere).cellBytes).toBe((76 + 60) * 6 * 64 * 64 + 8 * 2 * 6 * 64 * 64);
    expect(maxResolution(layoutOfKind('plane'), 16384)).toBe(16384);
    expect(maxResolution(layoutOfKind('sphere'), 16384)).toBe(2730);
    expect(maxResolution(layoutOfKind('mesh'), 4096)).toBe(682);
    // The refusal names the same largest resolution.
    const tooLarge = (surface: object, resolution: number, maxTextureSize: number) => {
      try {
        checkLimits(validateConfig({ ...base, cells: 2, surface, resolution }), { ...budget, maxTextureSize }, '');
      } catch (error) {
        expect(error).toBeInstanceOf(ConfigError);
        return (error as ConfigError).message;
      }
      return null;
    };
    expect(tooLarge(surfaces.sphere, 683, 4096)).toMatch(/^resolution: the cube map would be 683 x 4098 texels .* lower resolution to at most 682$/);
    expect(tooLarge(surfaces.sphere, 682, 4096)).toBeNull();
    expect(tooLarge(surfaces.plane, 4097, 4096)).toMatch(/^resolution: the grid would be 4097 x 2049 texels .* lower resolution to at most 4096$/);
  });

  it('runs the feasibility check of its layout', () => {
    expect(() => layoutOf({ ...surfaces.plane }, 16).checkFeasible()).toThrow(/^cells: 20 cells need at least 320 texels .* the grid has 128/);
    expect(() => layoutOf(surfaces.sphere, 16).checkFeasible()).not.toThrow();
    expect(() => surfaceLayout(validateConfig({ ...base, cells: 200, surface: surfaces.sphere, resolution: 16 })).checkFeasible()).toThrow(
      /^cells: 200 cells need at least 3200 texels .* the cube map has 1536 \(6 x 16²\)/,
    );
  });
});
