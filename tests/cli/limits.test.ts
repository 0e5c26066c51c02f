import { describe, expect, it } from 'vitest';
import { ConfigError, validateConfig } from '../../src/core/config';
import { checkBudget, checkExtents, checkLimits, estimateRun, MAX_EXTENT_UM, MIN_EXTENT_UM, threadsWithinBudget } from '../../src/core/config/limits';
import { surfaceLayout } from '../../src/core/config/surfaceLayout';

const budget = { maxTextureSize: 16384, maxWork: 2 ** 34, maxBytes: 8 * 2 ** 30 };
const tube = { surface: { kind: 'tube', radius: 16, length: 200 }, resolution: 64, cells: 20, lloyd: { maxIterations: 2 } };

function refusal(input: unknown, limits = budget): ConfigError {
  try {
    checkLimits(validateConfig(input), limits, 'pass --allow-large');
  } catch (error) {
    expect(error).toBeInstanceOf(ConfigError);
    return error as ConfigError;
  }
  throw new Error('not refused');
}

describe('scale guards', () => {
  it('refuses absurd extents (1e20 and 1e-20 µm) naming the field, accepts the range ends', () => {
    expect(refusal({ ...tube, surface: { kind: 'plane', width: 1e20, height: 1e20 } }).field).toBe('surface.width');
    expect(refusal({ ...tube, surface: { kind: 'plane', width: 100, height: 1e-20 } }).message).toMatch(/^surface\.height: 1e-20 µm is outside/);
    expect(refusal({ ...tube, surface: { kind: 'sphere', radius: 1e9 } }).field).toBe('surface.radius');
    for (const side of [MIN_EXTENT_UM, MAX_EXTENT_UM]) {
      expect(() => checkLimits(validateConfig({ ...tube, surface: { kind: 'plane', width: side, height: side } }), budget, '')).not.toThrow();
    }
  });

  it('refuses a surface ratio that puts the other surface beyond the extent range, naming it (no NaN, no Infinity)', () => {
    for (const surfaceRatio of [1e308, 1e300, 1e15]) {
      const e = refusal({ ...tube, sheet: { surfaceRatio } });
      expect(e.field).toBe('sheet.surfaceRatio');
      expect(e.message).toMatch(
        /^sheet\.surfaceRatio: .* x the radius \(16 µm\) puts the other surface more than 10000000 µm outside the tube; lower sheet\.surfaceRatio to at most 625000$/,
      );
      expect(e.message).not.toMatch(/NaN|Infinity/);
    }
    // At the bound the extent check passes (the texture and budget checks then speak); inward
    // ratios only shrink the other surface (checked by texels per side).
    expect(() => checkExtents(validateConfig({ ...tube, sheet: { surfaceRatio: 1 + MAX_EXTENT_UM / 16 } }))).not.toThrow();
    expect(() => checkExtents(validateConfig({ ...tube, sheet: { surfaceRatio: 1e308, direction: 'inward' } }))).not.toThrow();
    expect(refusal({ ...tube, sheet: { surfaceRatio: 1e308, direction: 'inward' } }).message).not.toMatch(/NaN|Infinity/);
  });

  it('refuses a tube with one texel around, saying why and what to change', () => {
    const e = refusal({ ...tube, surface: { kind: 'tube', radius: 0.1, length: 4000 }, resolution: 1024 });
    expect(e.field).toBe('resolution');
    expect(e.message).toMatch(/1 x 1024 texels.*at least 8.*too elongated/);
    const fixable = refusal({ ...tube, surface: { kind: 'tube', radius: 3, length: 4000 }, resolution: 1024 });
    // 2π·3 µm around, 4000 µm long: 8 texels around need resolution 8 x 4000 / 18.85 = 1698
    expect(fixable.message).toMatch(/5 x 1024 texels.*raise resolution to at least 1698/);
    const fixed = validateConfig({ ...tube, surface: { kind: 'tube', radius: 3, length: 4000 }, resolution: 1698 });
    expect(surfaceLayout(fixed).grids()[0].width).toBeGreaterThanOrEqual(8);
    expect(() => checkLimits(fixed, budget, '')).not.toThrow();
  });

  it('names sheet.surfaceRatio, not resolution, when the other surface is what is too large', () => {
    const texture = refusal({ ...tube, sheet: { surfaceRatio: 600 } });
    expect(texture.field).toBe('sheet.surfaceRatio');
    expect(texture.message).toMatch(/19200 x 64 texels .* at most 16384 per side; lower sheet\.surfaceRatio to at most about/);
    const memory = refusal({ ...tube, sheet: { surfaceRatio: 1e6 } });
    expect(memory.field).toBe('sheet.surfaceRatio');
    expect(memory.message).not.toMatch(/lower resolution/);
    expect(refusal({ ...tube, resolution: 16384, surface: { kind: 'plane', width: 10, height: 10 } }, { ...budget, maxTextureSize: 8192 }).message).toMatch(
      /^resolution: the grid would be 16384 x 16384 texels but this GPU allows at most 8192 per side; lower resolution to at most 8192/,
    );
  });

  it('estimates work as seeded texels x iterations + every surface once, and refuses beyond the budget', () => {
    const config = validateConfig({ ...tube, sheet: { surfaceRatio: 2, layers: 1 } });
    const grids = surfaceLayout(config).grids();
    expect(grids.map((g) => g.width)).toEqual([32, 48, 64]); // circumference scales 1, 1.5, 2
    const e = estimateRun(config);
    expect(e.work).toBe(32 * 64 * 2 + (32 + 48 + 64) * 64);
    expect(() => checkBudget(config, { ...budget, maxWork: e.work - 1 }, 'raise it')).toThrow(/texel-floods .* above the limit of .*raise it/);
    expect(() => checkBudget(config, { ...budget, maxBytes: e.bytes - 1 }, 'raise it')).toThrow(/memory/);
    expect(checkBudget(config, { ...budget, maxWork: e.work, maxBytes: e.bytes }, '')).toEqual(e);
  });

  it('starts no more realization threads than the memory budget holds beside the run (each holds a whole run)', () => {
    const million = validateConfig({
      surface: { kind: 'plane', width: 10000, height: 10000, periodicX: true, periodicY: true },
      resolution: 4100,
      cells: 1_000_000,
      engine: 'exact',
      sheet: { thickness: 5, adjacency: 'exact' },
    });
    const e = estimateRun(million);
    const within = (maxBytes: number, wanted = 7) => threadsWithinBudget(million, e, { ...budget, maxBytes }, wanted);
    expect(within(Infinity)).toBe(7);
    expect(within(Infinity, 0)).toBe(0);
    expect(within(e.bytes)).toBe(0);
    expect(within(e.bytes - 1)).toBe(0);
    // A thread costs at least the cells' share of the run, at most the whole run again plus the thread.
    const one = (() => {
      let lo = e.bytes;
      let hi = 4 * e.bytes;
      while (hi - lo > 1) {
        const mid = Math.floor((lo + hi) / 2);
        if (within(mid) >= 1) hi = mid;
        else lo = mid;
      }
      return hi - e.bytes;
    })();
    expect(one).toBeGreaterThan(e.cellBytes / 2);
    expect(one).toBeLessThan(e.bytes + 2 ** 28);
    expect(within(e.bytes + 3 * one)).toBe(3);
    // More memory never means fewer threads.
    let last = 0;
    for (let gib = 1; gib <= 16; gib++) {
      const n = within(gib * 2 ** 30);
      expect(n).toBeGreaterThanOrEqual(last);
      last = n;
    }
  });
});
