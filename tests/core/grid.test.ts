import { describe, expect, it } from 'vitest';
import { distanceSquared, wrapCoordinate, wrapDelta } from '../../src/core/grid';

describe('grid', () => {
  it('takes the minimum image across a periodic seam', () => {
    expect(wrapDelta(9, 10, true)).toBe(-1);
    expect(wrapDelta(-9, 10, true)).toBe(1);
    expect(wrapDelta(9, 10, false)).toBe(9);
  });
  it('measures physical distance with anisotropic texels', () => {
    const grid = { width: 10, height: 10, texelX: 2, texelY: 1, periodicX: true, periodicY: false };
    expect(distanceSquared(grid, 0.5, 0.5, 9.5, 3.5)).toBeCloseTo(4 + 9);
  });
  it('wraps and clamps coordinates', () => {
    expect(wrapCoordinate(-0.5, 10, true)).toBeCloseTo(9.5);
    expect(wrapCoordinate(10.5, 10, true)).toBeCloseTo(0.5);
    expect(wrapCoordinate(11, 10, false)).toBe(10);
  });
});
