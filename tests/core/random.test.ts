import { describe, expect, it } from 'vitest';
import { Random, createRandom } from '../../src/core/random';

describe('Random (sfc32 seeded by splitmix32)', () => {
  it('gives the same sequence for the same seed', () => {
    const a = createRandom(12345);
    const b = createRandom(12345);
    for (let i = 0; i < 1000; i++) expect(a.nextUint32()).toBe(b.nextUint32());
  });

  it('gives unrelated sequences for neighbouring seeds', () => {
    const a = new Random(1);
    const b = new Random(2);
    let equal = 0;
    for (let i = 0; i < 1000; i++) if (a.nextUint32() === b.nextUint32()) equal++;
    expect(equal).toBe(0);
  });

  it('returns 32-bit unsigned integers and floats in [0, 1)', () => {
    const r = new Random(7);
    for (let i = 0; i < 10000; i++) {
      const u = r.nextUint32();
      expect(Number.isInteger(u) && u >= 0 && u < 2 ** 32).toBe(true);
      const f = r.next();
      expect(f >= 0 && f < 1).toBe(true);
    }
  });

  it('is roughly uniform (chi-square over 32 bins) with mean 1/2', () => {
    const r = new Random(99);
    const bins = new Array<number>(32).fill(0);
    const n = 64000;
    let sum = 0;
    for (let i = 0; i < n; i++) {
      const f = r.next();
      sum += f;
      bins[Math.floor(f * 32)]++;
    }
    const expected = n / 32;
    const chi2 = bins.reduce((acc, count) => acc + (count - expected) ** 2 / expected, 0);
    // 31 degrees of freedom: the 99.99th percentile is about 67.
    expect(chi2).toBeLessThan(67);
    expect(Math.abs(sum / n - 0.5)).toBeLessThan(0.01);
  });

  it('spreads the high and low bits alike', () => {
    const r = new Random(3);
    const n = 20000;
    let low = 0;
    let high = 0;
    for (let i = 0; i < n; i++) {
      const u = r.nextUint32();
      low += u & 1;
      high += u >>> 31;
    }
    // Binomial(n, 1/2): standard deviation ~71; allow 5 sigma.
    expect(Math.abs(low - n / 2)).toBeLessThan(355);
    expect(Math.abs(high - n / 2)).toBeLessThan(355);
  });

  it('draws integers in [0, n) without bias and rejects bad n', () => {
    const r = new Random(5);
    const counts = [0, 0, 0];
    for (let i = 0; i < 30000; i++) counts[r.nextInt(3)]++;
    for (const c of counts) expect(Math.abs(c - 10000)).toBeLessThan(500);
    expect(() => r.nextInt(0)).toThrow(RangeError);
    expect(() => r.nextInt(2.5)).toThrow(RangeError);
  });

  it('uses the seed modulo 2^32', () => {
    const a = new Random(2 ** 32 + 17);
    const b = new Random(17);
    expect(a.nextUint32()).toBe(b.nextUint32());
  });
});
