/**
 * exp (src/core/exp.ts), e^x in plain double arithmetic: special values, its accuracy against
 * Math.exp over the whole range (both within 1 ulp of e^x, so within 2 of each other; the most
 * seen is reported), and exact powers of two. The Flintstones fit and Gaussian densities use it
 * instead of Math.exp (tests/analysis: the fit does not call Math.exp at all).
 */
import { describe, expect, it } from 'vitest';
import { exp } from '../../src/core/exp';
import { Random } from '../../src/core/random';

/** Distance in units in the last place between two positive finite doubles. */
function ulps(a: number, b: number): number {
  const view = new DataView(new ArrayBuffer(16));
  view.setFloat64(0, a);
  view.setFloat64(8, b);
  return Number(view.getBigInt64(0) - view.getBigInt64(8));
}

describe('exp', () => {
  it('special values', () => {
    expect(exp(0)).toBe(1);
    expect(exp(-0)).toBe(1);
    expect(exp(Number.NaN)).toBeNaN();
    expect(exp(Infinity)).toBe(Infinity);
    expect(exp(-Infinity)).toBe(0);
    expect(exp(710)).toBe(Infinity);
    expect(exp(-746)).toBe(0);
    expect(exp(1e-300)).toBe(1);
    expect(exp(Math.LN2 * 10)).toBeCloseTo(1024, 10);
  });

  it('agrees with Math.exp within 2 ulp everywhere, subnormal results included', () => {
    const random = new Random(7);
    let worst = 0;
    for (const [low, high] of [
      [-1, 1],
      [-40, 40],
      [-745, 709.78],
      [-745, -708],
    ]) {
      for (let k = 0; k < 100_000; k++) {
        const x = low + (high - low) * random.next();
        const expected = Math.exp(x);
        const got = exp(x);
        if (expected === 0) expect(got).toBe(0);
        else worst = Math.max(worst, Math.abs(ulps(got, expected)));
      }
    }
    console.log(`exp vs Math.exp: at most ${worst} ulp apart over 400,000 arguments`);
    expect(worst).toBeLessThanOrEqual(2);
  });

  it('near the thresholds and the reduction boundaries', () => {
    for (const x of [
      709.78,
      709.782712893383,
      -708.3964185322641,
      -744.4,
      0.5 * Math.LN2,
      1.5 * Math.LN2,
      -0.5 * Math.LN2,
      -1.5 * Math.LN2,
      2 ** -28,
      -(2 ** -27),
    ]) {
      const expected = Math.exp(x);
      expect(Math.abs(ulps(exp(x), expected))).toBeLessThanOrEqual(2);
    }
  });
});
