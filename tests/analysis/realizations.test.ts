import { describe, expect, it } from 'vitest';
import { describeHeadline, type Headline } from '../../src/core/analysis/headline';
import {
  checkRealizations,
  combineHeadlines,
  DEFAULT_REALIZATIONS,
  headlineOverRealizations,
  meanInterval,
  realizationSeeds,
  tQuantile975,
} from '../../src/core/analysis/realizations';

const one = (percent: number | null, seed: number): Headline => ({
  method: 'exact',
  protocol: 'default',
  percentScutoids: percent,
  scutoids: percent === null ? 0 : Math.round(percent),
  validCells: percent === null ? 0 : 100,
  cells: 200,
  meanTransitions: percent === null ? null : percent / 50,
  meanNeighbours3D: percent === null ? null : 6 + percent / 100,
  voronoiK: 51,
  realizations: 1,
  ci95: null,
  sd: null,
  realizationSeeds: [seed],
  realizationValues: [percent],
  byConstruction: null,
  noValidCells: percent === null ? 'No cell was counted.' : null,
  omittedMethods: [],
});

describe('headline over realizations', () => {
  it('a default n from 5 to 10 and seeds seed, seed + 1, ... (wrapping at 2^32)', () => {
    expect(DEFAULT_REALIZATIONS).toBeGreaterThanOrEqual(5);
    expect(DEFAULT_REALIZATIONS).toBeLessThanOrEqual(10);
    expect(realizationSeeds(1, 3)).toEqual([1, 2, 3]);
    expect(realizationSeeds(4294967295, 2)).toEqual([4294967295, 0]);
  });

  it("Student's t quantiles and the interval of the issue's example (seeds 1-3: 97.8, 88.1, 94.1)", () => {
    expect(tQuantile975(1)).toBeCloseTo(12.706, 3);
    expect(tQuantile975(9)).toBeCloseTo(2.262, 3);
    expect(tQuantile975(100)).toBeCloseTo(1.984, 3);
    const m = meanInterval([97.8, 88.1, 94.1]);
    expect(m.mean).toBeCloseTo(93.333, 3);
    expect(m.sd).toBeCloseTo(4.8952, 3);
    // 93.333 ± 4.303 · 4.8952 / √3, clamped to 100
    expect(m.ci95![0]).toBeCloseTo(93.333 - 12.161, 2);
    expect(m.ci95![1]).toBe(100);
    expect(meanInterval([42]).ci95).toBeNull();
  });

  it('combines realizations: mean, SD, CI, every seed and value, the drawn one first', () => {
    const h = combineHeadlines([one(97.8, 1), one(88.1, 2), one(94.1, 3)], [1, 2, 3]);
    expect(h.realizations).toBe(3);
    expect(h.percentScutoids).toBeCloseTo(93.333, 3);
    expect(h.realizationSeeds).toEqual([1, 2, 3]);
    expect(h.realizationValues).toEqual([97.8, 88.1, 94.1]);
    expect(h.scutoids).toBe(98); // realization 1's counts
    expect(h.meanTransitions).toBeCloseTo(280 / 3 / 50, 9);
    expect(h.sd).toBeCloseTo(4.8952, 3);
    const line = describeHeadline(h);
    expect(line).toContain('93.3 % scutoids');
    expect(line).toContain('mean of 3 realizations (seeds 1–3), 95 % CI 81.2–100.0 %; realization 1 (seed 1, drawn): 97.8 %');
    expect(describeHeadline(one(97.8, 1))).toContain('one realization (seed 1)');
  });

  it('a realization with no valid cell has no %: the mean is over the others; none at all keeps why', () => {
    const h = combineHeadlines([one(50, 1), one(null, 2), one(70, 3)], [1, 2, 3]);
    expect(h.percentScutoids).toBe(60);
    expect(h.realizationValues).toEqual([50, null, 70]);
    const none = combineHeadlines([one(null, 1), one(null, 2)], [1, 2]);
    expect(none.percentScutoids).toBeNull();
    expect(none.ci95).toBeNull();
    expect(none.noValidCells).toBe('No cell was counted.');
  });

  it('refuses realizations of different methods, and bad counts in words', () => {
    expect(() => combineHeadlines([one(1, 1), { ...one(2, 2), method: 'labels' }], [1, 2])).toThrow(/different methods/);
    expect(checkRealizations('7')).toBe(7);
    for (const bad of [0, 2.5, 101, 'five', '']) expect(() => checkRealizations(bad)).toThrow(/whole number of realizations from 1 to 100/);
  });

  it('runs the other seeds in order and reports progress', async () => {
    const asked: number[] = [];
    const progress: number[] = [];
    const h = await headlineOverRealizations(
      10,
      4,
      one(40, 10),
      async (seed) => (asked.push(seed), one(seed * 4, seed)),
      (done) => progress.push(done),
    );
    expect(asked).toEqual([11, 12, 13]);
    expect(progress).toEqual([1, 2, 3, 4]);
    expect(h!.realizationValues).toEqual([40, 44, 48, 52]);
    expect(await headlineOverRealizations(10, 1, one(40, 10), async () => null)).toEqual(one(40, 10));
  });
});

describe('omitted methods', () => {
  it('"both" on the exact engine names the labels method left out and why', async () => {
    const { omittedMethods, describeOmitted } = await import('../../src/core/analysis/headline');
    const { validateConfig } = await import('../../src/core/config');
    const auto = validateConfig({ sheet: { surfaceRatio: 2 } });
    expect(omittedMethods(auto, ['exact'])).toEqual([{ method: 'labels', reason: expect.stringContaining('engine "auto" took the exact engine') }]);
    expect(omittedMethods(auto, ['labels', 'exact'])).toEqual([]);
    const exact = validateConfig({ engine: 'exact', sheet: { surfaceRatio: 2, adjacency: 'labels' } });
    expect(describeOmitted({ omittedMethods: omittedMethods(exact, ['exact']) })).toMatch(/^labels method left out: engine "exact" ran Lloyd/);
  });
});
