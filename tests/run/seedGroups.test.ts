import { describe, expect, it } from 'vitest';
import { validateConfig } from '../../src/core/config';
import { expandSweep, validateSweepSpec } from '../../src/core/sweep';
import { chainKey, seededKey } from '../../src/run/runSheet';
import { seedGroups, type Run } from '../../src/run/sweepLayout';

/**
 * seedGroups: runs share a key exactly when the key function gives their configs the same text
 * (seededKey: the seeded surface; chainKey: the Lloyd run), the text made once per grid point.
 * Checked pair by pair against the texts of every run's own config.
 */
describe('seedGroups', () => {
  const spec = validateSweepSpec({
    base: { surface: { kind: 'tube', radius: 40, length: 300 }, resolution: 128, cells: 24, engine: 'exact' },
    vary: { 'lloyd.maxIterations': [0, 2], 'sheet.surfaceRatio': [1, 2], cells: [24, 30] },
    realizations: 3,
    seed: 5,
  });
  const runs = expandSweep(spec) as Run[];
  const configs = new Map(runs.map((run) => [run.pointKey, validateConfig(run.config)]));

  for (const [name, keyOf] of [
    ['seededKey', seededKey],
    ['chainKey', chainKey],
  ] as const) {
    it(`groups runs as ${name} of their own configs does`, () => {
      const group = seedGroups((run) => configs.get(run.pointKey)!, keyOf);
      const keys = runs.map(group);
      const texts = runs.map((run) => keyOf(validateConfig(run.config)));
      for (let a = 0; a < runs.length; a++) {
        for (let b = 0; b < runs.length; b++) expect(keys[a] === keys[b], `${runs[a].key} ~ ${runs[b].key}`).toBe(texts[a] === texts[b]);
      }
      // Both kinds of pairs occur: the check is not vacuous.
      expect(new Set(keys).size).toBeGreaterThan(1);
      expect(new Set(keys).size).toBeLessThan(runs.length);
    });
  }
});
