import { describe, expect, it, vi } from 'vitest';
import { Random } from '../../src/core/random';
import { anchoredB, fitFlintstones, flintstonesLaw, type FlintstonesPoint } from '../../src/core/analysis/flintstones';

const RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10];

function gaussian(random: Random): number {
  const u = Math.max(random.next(), 1e-12);
  return Math.sqrt(-2 * Math.log(u)) * Math.cos(2 * Math.PI * random.next());
}

function synthetic(truth: { nMax: number; c: number; d: number }, noise: number, seed: number, repeats = 3): FlintstonesPoint[] {
  const p = { ...truth, b: anchoredB(truth.nMax, truth.c, truth.d, 6) };
  const random = new Random(seed);
  const points: FlintstonesPoint[] = [];
  for (const s of RATIOS) for (let r = 0; r < repeats; r++) points.push({ s, n: flintstonesLaw(s, p) + noise * gaussian(random) });
  return points;
}

describe('Flintstones law fit', () => {
  const truth = { nMax: 8, c: 2.5, d: -1.2 };

  it('never calls Math.exp (engines differ in its last bit): the same fit in Node and in every browser', () => {
    const points = synthetic(truth, 0.05, 7);
    const expected = fitFlintstones(points);
    const spy = vi.spyOn(Math, 'exp').mockImplementation(() => {
      throw new Error('Math.exp called');
    });
    try {
      expect(fitFlintstones(points)).toEqual(expected);
      expect(flintstonesLaw(2, { ...truth, b: anchoredB(truth.nMax, truth.c, truth.d, 6) })).toBeGreaterThan(6);
    } finally {
      spy.mockRestore();
    }
  });

  it('the anchored law passes through n3D(1) = 6 and saturates at nMax', () => {
    const p = { ...truth, b: anchoredB(truth.nMax, truth.c, truth.d, 6) };
    expect(flintstonesLaw(1, p)).toBeCloseTo(6, 12);
    expect(flintstonesLaw(200, p)).toBeCloseTo(8, 6);
  });

  it('recovers known parameters within 3 standard errors', () => {
    const fit = fitFlintstones(synthetic(truth, 0.05, 7));
    expect(fit.converged).toBe(true);
    for (const key of ['nMax', 'c', 'd'] as const) {
      expect(fit.standardErrors[key]).toBeGreaterThan(0);
      expect(Math.abs(fit.parameters[key] - truth[key])).toBeLessThan(3 * fit.standardErrors[key]);
    }
    expect(fit.rSquared).toBeGreaterThan(0.95);
  });

  it('standard errors are calibrated: about 68 % of 120 fits land within 1 SE of the truth', () => {
    const within = { nMax: 0, c: 0, d: 0 };
    const trials = 120;
    for (let seed = 1; seed <= trials; seed++) {
      const fit = fitFlintstones(synthetic(truth, 0.05, 1000 + seed));
      for (const key of ['nMax', 'c', 'd'] as const) if (Math.abs(fit.parameters[key] - truth[key]) <= fit.standardErrors[key]) within[key]++;
    }
    for (const key of ['nMax', 'c', 'd'] as const) {
      expect(within[key] / trials).toBeGreaterThan(0.55);
      expect(within[key] / trials).toBeLessThan(0.82);
    }
  });

  it('exact data give a near-zero residual; bad input names the problem', () => {
    const fit = fitFlintstones(synthetic(truth, 0, 1, 1));
    expect(fit.parameters.nMax).toBeCloseTo(8, 4);
    expect(fit.parameters.c).toBeCloseTo(2.5, 3);
    expect(() =>
      fitFlintstones([
        { s: 1, n: 6 },
        { s: 2, n: 6.5 },
      ]),
    ).toThrow(/points/);
    expect(() => fitFlintstones([...synthetic(truth, 0, 1, 1), { s: Number.NaN, n: 6 }])).toThrow(/finite/);
  });

  it('chi² is the sum over every point, weighted by 1/sigma², though the fit iterates per ratio', () => {
    const random = new Random(7);
    const points = synthetic(truth, 0.3, 3, 5).map((q) => ({ ...q, sigma: 0.2 + random.next() }));
    for (const data of [points, points.map(({ s, n }): FlintstonesPoint => ({ s, n }))]) {
      const fit = fitFlintstones(data);
      let direct = 0;
      for (const q of data) direct += ((q.n - flintstonesLaw(q.s, fit.parameters)) / (q.sigma ?? 1)) ** 2;
      expect(fit.chiSquared).toBeCloseTo(direct, 9);
      expect(fit.degreesOfFreedom).toBe(data.length - 3);
    }
  });

  it('each point given twice: the same fit, twice the chi², standard errors of twice the points', () => {
    const points = synthetic(truth, 0.05, 11, 4);
    const once = fitFlintstones(points);
    const twice = fitFlintstones([...points, ...points]);
    for (const key of ['nMax', 'c', 'd'] as const) expect(twice.parameters[key]).toBeCloseTo(once.parameters[key], 4);
    expect(twice.chiSquared).toBeCloseTo(2 * once.chiSquared, 6);
    // s² = chi²/(m - p) doubles its chi² over 2m - p, JᵀJ doubles: SE ratio sqrt((m - p) / (2m - p)).
    const m = points.length;
    const scale = Math.sqrt((m - 3) / (2 * m - 3));
    expect(twice.standardErrors.nMax).toBeCloseTo(once.standardErrors.nMax * scale, 4);
  });
});
