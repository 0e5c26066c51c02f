import { describe, expect, it } from 'vitest';
import { labelAdjacency } from '../../src/core/labels';
import {
  BORDER_X_END as BORDER_RIGHT,
  BORDER_X_START as BORDER_LEFT,
  BORDER_Y_END as BORDER_BOTTOM,
  BORDER_Y_START as BORDER_TOP,
} from '../../src/core/border';
import { countContacts, pairKey, type LayerContacts } from '../../src/core/measure';
import { randomSites, rasterizeVoronoi } from './images';

/** Edge count between raw labels a and b (0 when they do not touch). */
const edgesBetween = (contacts: LayerContacts, a: number, b: number): number => (a === b ? 0 : (contacts.edges.get(pairKey(a, b)) ?? 0));

/**
 * The hand-checkable case of docs/measure.md's edge-count definition:
 *
 *   1 1 2 2
 *   1 3 3 2
 *   4 4 4 2
 *
 * Horizontal pairs (x, x+1): row 0: 1|2; row 1: 1|3, 3|2; row 2: 4|2.
 * Vertical pairs (y, y+1): column 0: 1|4; column 1: 1|3, 3|4; column 2: 2|3, 3|4.
 * So e(1,2) = 1, e(1,3) = 2, e(2,3) = 2, e(2,4) = 1, e(1,4) = 1, e(3,4) = 2.
 * With --periodic-x the pairs (3, y)-(0, y) add 2|1 (rows 0 and 1) and 2|4 (row 2):
 * e(1,2) = 3, e(2,4) = 2, the rest unchanged.
 */
const small = { width: 4, height: 3, bitsPerSample: 8 as const, data: Uint8Array.from([1, 1, 2, 2, 1, 3, 3, 2, 4, 4, 4, 2]) };

describe('countContacts', () => {
  it('counts 4-connected pixel edges between labels (hand-checked case)', () => {
    const c = countContacts(small, false);
    const expected: [number, number, number][] = [
      [1, 2, 1],
      [1, 3, 2],
      [2, 3, 2],
      [2, 4, 1],
      [1, 4, 1],
      [3, 4, 2],
    ];
    for (const [a, b, n] of expected) {
      expect(edgesBetween(c, a, b), `e(${a},${b})`).toBe(n);
      expect(edgesBetween(c, b, a)).toBe(n);
    }
    expect(c.edges.size).toBe(expected.length);
    expect([...c.pixels.subarray(0, 5)]).toEqual([0, 3, 4, 2, 3]);
    expect(c.labels).toBe(4);
    expect(c.border[1]).toBe(BORDER_TOP | BORDER_LEFT);
    expect(c.border[2]).toBe(BORDER_TOP | BORDER_RIGHT | BORDER_BOTTOM);
    expect(c.border[3]).toBe(0);
    expect(c.border[4]).toBe(BORDER_LEFT | BORDER_BOTTOM);
  });

  it('wraps horizontal edges from the last column to the first with periodicX, never rows', () => {
    const c = countContacts(small, true);
    expect(edgesBetween(c, 1, 2)).toBe(3);
    expect(edgesBetween(c, 2, 4)).toBe(2);
    expect(edgesBetween(c, 1, 3)).toBe(2);
    expect(edgesBetween(c, 1, 4)).toBe(1);
    // Left/right are no border any more; top/bottom still are (rows do not wrap).
    expect(c.border[1]).toBe(BORDER_TOP);
    expect(c.border[2]).toBe(BORDER_TOP | BORDER_BOTTOM);
    expect(c.border[4]).toBe(BORDER_BOTTOM);
  });

  it('ignores background (0) and counts nothing between a label and itself', () => {
    const image = { width: 3, height: 2, bitsPerSample: 8 as const, data: Uint8Array.from([5, 0, 6, 5, 5, 6]) };
    const c = countContacts(image, true);
    expect(edgesBetween(c, 5, 6)).toBe(3); // (1,1)-(2,1), and the wraps (2,0)-(0,0), (2,1)-(0,1)
    expect(c.edges.size).toBe(1);
    expect(c.pixels[0]).toBe(0);
  });

  for (const periodicX of [false, true]) {
    it(`agrees with labelAdjacency (src/core/labels.ts) on a random Voronoi image, periodicX ${periodicX}`, () => {
      const width = 97;
      const height = 61;
      const sites = randomSites(40, width, height, 7);
      const labels = sites.map((_, i) => 1000 + 37 * i); // sparse, non-consecutive labels
      const image = rasterizeVoronoi(width, height, sites, labels, periodicX);
      const c = countContacts({ width, height, bitsPerSample: 16, data: image.data }, periodicX);
      const dense = Int32Array.from(image.data, (v) => (v - 1000) / 37);
      // Edge counts: labelAdjacency's staircase lengths (its true lengths remove the staircase bias).
      const ref = labelAdjacency({ width, height, texelX: 1, texelY: 1, periodicX, periodicY: false }, dense, sites.length, 'staircase');
      let pairs = 0;
      for (let i = 0; i < sites.length; i++) {
        expect(c.pixels[labels[i]]).toBe(ref.areas[i]);
        expect(c.border[labels[i]]).toBe(ref.border[i]);
        for (let k = ref.offsets[i]; k < ref.offsets[i + 1]; k++) {
          const j = ref.neighbours[k];
          expect(edgesBetween(c, labels[i], labels[j])).toBe(ref.lengths[k]);
          if (j > i) pairs++;
        }
      }
      expect(c.edges.size).toBe(pairs);
    });
  }
});
