/**
 * flatValues (a thread's fast flattening of run summaries) against flattenSummary, the
 * definition: where flatKeys equals flattenSummary's key list, the values are flattenSummary's
 * values in that order; summaries of one shape share their key list; awkward inputs (coinciding
 * keys, empty keys, integer-like keys, empty containers, typed arrays) are detected as such.
 */
import { describe, expect, it } from 'vitest';
import { flattenSummary } from '../../src/core/sweep/csv';
import { flatKeys, flatValues } from '../../src/core/sweep/flatValues';
import { Random } from '../../src/core/random';

function randomValue(random: Random, depth: number): unknown {
  const r = random.next();
  if (depth > 3 || r < 0.35) return r < 0.1 ? 'text' : r < 0.15 ? null : r < 0.2 ? NaN : Math.round(r * 1000) / 7;
  if (r < 0.5) return Array.from({ length: Math.floor(random.next() * 4) }, () => randomValue(random, depth + 1));
  if (r < 0.55) return Float64Array.from({ length: Math.floor(random.next() * 3) }, () => random.next());
  const names = ['a', 'b', 'meanSides', 'polygons', '3', '10+', 'a.b', '', '7', 'exact'];
  const out: Record<string, unknown> = {};
  const count = Math.floor(random.next() * 5);
  for (let k = 0; k < count; k++) out[names[Math.floor(random.next() * names.length)]] = randomValue(random, depth + 1);
  return out;
}

describe('flatValues', () => {
  it("gives flattenSummary's values in its key order wherever flatKeys is its key list, on random nested values", () => {
    const random = new Random(11);
    let aligned = 0;
    let refused = 0;
    for (let trial = 0; trial < 3000; trial++) {
      const value = randomValue(random, 0);
      const flat = flattenSummary(value);
      const keys = Object.keys(flat);
      const own = flatKeys(value);
      if (own.length === keys.length && own.every((k, n) => k === keys[n])) {
        aligned++;
        expect(flatValues(value).values).toEqual(Object.values(flat));
      } else refused++;
    }
    // Both cases occur (the random names include coinciding, empty and integer-like keys).
    expect(aligned).toBeGreaterThan(1000);
    expect(refused).toBeGreaterThan(10);
  });

  it('gives one shape to values with the same keys and different shapes to different key lists', () => {
    const summary = (n: number, method: string) => ({ iterations: n, finalEnergy: n / 3, exact: { [method]: { meanSides: n, polygons: { 3: 0, 4: n } } } });
    expect(flatValues(summary(1, 'basal')).shape).toBe(flatValues(summary(2, 'basal')).shape);
    expect(flatValues(summary(1, 'basal')).shape).not.toBe(flatValues(summary(1, 'apical')).shape);
    // Keys that would read as structure stay apart.
    expect(flatValues({ a: { b: 1 } }).shape).not.toBe(flatValues({ 'a{1:b': 1 }).shape);
    expect(flatValues([1, 2]).shape).not.toBe(flatValues([[1, 2]]).shape);
    expect(flatValues({ a: [] }).values).toEqual(['']);
    expect(flatValues({ '': 5, a: 1 }).values).toEqual([1]);
  });
});
