/**
 * sweepSummaryValues (a thread's flat summary without the nested one) against its definition,
 * flatValues(sweepSummary(result)) with flattenSummary's keys: the same values in the same
 * order wherever it gives any, one shape per key list, and null for the names an object would
 * reorder or merge (repeated, metric-named, integer-like).
 */
import { describe, expect, it } from 'vitest';
import { flattenSummary } from '../../src/core/sweep/csv';
import { flatKeys, flatValues } from '../../src/core/sweep/flatValues';
import { Random } from '../../src/core/random';
import { sweepSummary, sweepSummaryValues } from '../../src/run/sweepSummary';
import type { SheetResult } from '../../src/run/result';

function resultOf(random: Random, analyses: { method: string; labels: (string | undefined)[] }[]): SheetResult {
  const number = () => (random.next() < 0.1 ? NaN : Math.round(random.next() * 1e6) / 997);
  return {
    lloyd: { iterations: Array.from({ length: Math.floor(random.next() * 4) }), finalEnergy: number() },
    engine: random.next() < 0.5 ? { centroidPath: 'exact' } : {},
    analyses: analyses.map(({ method, labels }) => ({
      method,
      summary: {
        percentScutoids: number(),
        scutoids: number(),
        validCells: number(),
        excludedCells: number(),
        meanTransitions: number(),
        meanWon: number(),
        meanLost: number(),
        meanNeighbours3D: number(),
        perSurface: labels.map((label) => ({ label, meanSides: number(), polygonDistribution: Array.from({ length: 8 }, number) })),
      },
    })),
  } as unknown as SheetResult;
}

describe('sweepSummaryValues', () => {
  it('gives flatValues(sweepSummary) in flattenSummary key order, one shape per key list', () => {
    const random = new Random(5);
    const stacks: { method: string; labels: (string | undefined)[] }[][] = [
      [{ method: 'exact', labels: ['apical', 'basal'] }],
      [{ method: 'exact', labels: ['apical', 'layer 1', 'layer 2', 'basal'] }],
      [
        { method: 'labels', labels: ['apical', 'layer 1', 'basal'] },
        { method: 'exact', labels: ['apical', 'layer 1', 'basal'] },
      ],
      [{ method: 'exact', labels: [undefined, 'a b', 'meanSides', 'polygons', ''] }],
      [{ method: 'exact', labels: [] }],
      [],
    ];
    const shapes = new Map<string, string>();
    for (let trial = 0; trial < 60; trial++) {
      const analyses = stacks[trial % stacks.length];
      const result = resultOf(random, analyses);
      const direct = sweepSummaryValues(result);
      expect(direct, JSON.stringify(analyses)).not.toBeNull();
      const summary = sweepSummary(result);
      const keys = Object.keys(flattenSummary(summary));
      expect(flatKeys(summary)).toEqual(keys);
      const values = flatValues(summary).values;
      expect(direct!.values.length).toBe(values.length);
      direct!.values.forEach((value, n) => expect(Object.is(value, values[n]), keys[n]).toBe(true));
      const known = shapes.get(direct!.shape);
      if (known !== undefined) expect(known).toBe(JSON.stringify(keys));
      shapes.set(direct!.shape, JSON.stringify(keys));
    }
    // Different key lists, different shapes.
    expect(new Set(shapes.values()).size).toBe(shapes.size);
  });

  it('is null for names an object would reorder or merge', () => {
    const random = new Random(6);
    for (const analyses of [
      [{ method: 'exact', labels: ['apical', 'apical'] }],
      [{ method: 'exact', labels: ['layer1', 'layer 1'] }],
      [{ method: 'exact', labels: ['apical', 'scutoids'] }],
      [{ method: 'exact', labels: ['apical', '12'] }],
      [{ method: 'exact', labels: ['0'] }],
      [
        { method: 'exact', labels: ['a'] },
        { method: 'exact', labels: ['b'] },
      ],
      [{ method: 'iterations', labels: ['a'] }],
      [{ method: '7', labels: ['a'] }],
    ]) {
      expect(sweepSummaryValues(resultOf(random, analyses)), JSON.stringify(analyses)).toBeNull();
    }
  });
});
