import { describe, expect, it } from 'vitest';
import { timings } from '../../src/app/panels/results';

/**
 * The timings line (issue 14: "timings report a total smaller than the Lloyd time"): the parts
 * of a run add up to its total, and a reused seeded surface's times are named as an earlier run's,
 * never shown as parts of a smaller total.
 */
const numbers = (text: string) => [...text.matchAll(/(\d+) ms/g)].map((m) => Number(m[1]));

describe('timings in words', () => {
  it('a full run: total, then its parts, which add up to it (the rest as "other")', () => {
    const text = timings({ setupMs: 120.4, lloydMs: 850.2, adjacencyMs: 300.1, totalMs: 1300.6 });
    const [total, setup, lloyd, adjacency, other] = numbers(text);
    expect(total).toBe(1301);
    expect([setup, lloyd, adjacency]).toEqual([120, 850, 300]);
    expect(Math.abs(setup + lloyd + adjacency + other - total)).toBeLessThanOrEqual(2);
    expect(text).not.toMatch(/reused/);
  });

  it('a reused seeded surface: its setup and Lloyd times are said to be from an earlier run', () => {
    const text = timings({ setupMs: 120, lloydMs: 850, adjacencyMs: 300, totalMs: 310 });
    expect(text).toMatch(/^310 ms in all \(adjacency and analysis 300 ms; the seeded surface was reused from an earlier run/);
    expect(text).toMatch(/setup took 120 ms and Lloyd 850 ms/);
  });
});
