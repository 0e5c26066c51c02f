import { describe, expect, it } from 'vitest';
import { describeIntervals, referenceInterval, type ReferenceCurve } from '../../src/core/reference';

const point = (percent: number, sd: number | null, n: number | null) => ({ x: 1, percent, sd, n, source: 'test' });

describe('reference error bars', () => {
  it('are the 95 % CI of the mean from SD and n (Student t), clamped to 0..100', () => {
    // t(0.975, 19) = 2.0930 (tables): 40 ± 2.093·5/√20
    const ci = referenceInterval(point(40, 5, 20))!;
    expect(ci.low).toBeCloseTo(40 - (2.093 * 5) / Math.sqrt(20), 2);
    expect(ci.high).toBeCloseTo(40 + (2.093 * 5) / Math.sqrt(20), 2);
    expect(ci.high - 40).toBeCloseTo(40 - ci.low, 12);
    expect(referenceInterval(point(1, 10, 4))!.low).toBe(0);
    expect(referenceInterval(point(99, 10, 4))!.high).toBe(100);
  });

  it('are absent without both an SD and n ≥ 2, and the note says so', () => {
    expect(referenceInterval(point(40, null, 20))).toBeNull();
    expect(referenceInterval(point(40, 5, null))).toBeNull();
    expect(referenceInterval(point(40, 5, 1))).toBeNull();
    const curve = (points: ReturnType<typeof point>[]): ReferenceCurve => ({ id: 'c', label: 'C', kind: 'data', quantity: 'surfaceRatio', fixed: {}, points });
    expect(describeIntervals(curve([point(1, null, null)]))).toMatch(/C: no error bars \(its file gives no SD and n/);
    expect(describeIntervals(curve([point(1, 2, 5)]))).toMatch(/C: error bars are the 95 % CI of the mean/);
    expect(describeIntervals(curve([point(1, 2, 5), { ...point(2, null, null), x: 2 }]))).toMatch(/on 1 of 2 points/);
  });
});
