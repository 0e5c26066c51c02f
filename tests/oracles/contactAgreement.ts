/**
 * How well a label adjacency's contact lengths and neighbour sets match an exact adjacency of
 * the same sites (test oracle for src/core/labels.ts labelAdjacency and
 * src/core/closed/geometry.ts cubeLabelAdjacency).
 *
 * - Length ratio: over the contacts present in both, with an exact length of at least
 *   `minTexels` texel edges (shorter ones are dominated by where the staircase ends), the
 *   mean of label / exact per contact, and Σ label / Σ exact.
 * - Neighbour sets: the minimum contact length applied to both (contacts of at least that
 *   length count), the fraction of cells whose sets are equal.
 */
import type { SurfaceAdjacency } from '../../src/core/analysis/adjacency';

export interface ContactAgreement {
  /** Contacts compared for length. */
  readonly contacts: number;
  /** Mean of label / exact per contact. */
  readonly meanRatio: number;
  /** Σ label / Σ exact over the compared contacts. */
  readonly totalRatio: number;
  /** Fraction of cells whose thresholded neighbour sets are equal. */
  readonly cellAgreement: number;
}

type Lengths = Pick<SurfaceAdjacency, 'offsets' | 'neighbours' | 'lengths'>;

/** Length of contact (i, j) in a CSR adjacency, 0 if absent. */
export function contactLength(adj: Lengths, i: number, j: number): number {
  for (let q = adj.offsets[i]; q < adj.offsets[i + 1]; q++) if (adj.neighbours[q] === j) return adj.lengths[q];
  return 0;
}

/** Cell i's neighbours with a contact of at least minLength, ascending. */
export function neighbourSet(adj: Lengths, i: number, minLength: number): number[] {
  const out: number[] = [];
  for (let q = adj.offsets[i]; q < adj.offsets[i + 1]; q++) if (adj.lengths[q] >= minLength) out.push(adj.neighbours[q]);
  return out.sort((a, b) => a - b);
}

export function contactAgreement(labels: Lengths, exact: Lengths, count: number, texelEdge: number, minLength: number, minTexels = 3): ContactAgreement {
  let contacts = 0,
    ratioSum = 0,
    labelSum = 0,
    exactSum = 0,
    same = 0;
  for (let i = 0; i < count; i++) {
    for (let q = exact.offsets[i]; q < exact.offsets[i + 1]; q++) {
      const j = exact.neighbours[q];
      if (j <= i || exact.lengths[q] < minTexels * texelEdge) continue;
      const l = contactLength(labels, i, j);
      if (l === 0) continue;
      contacts++;
      ratioSum += l / exact.lengths[q];
      labelSum += l;
      exactSum += exact.lengths[q];
    }
    if (neighbourSet(labels, i, minLength).join() === neighbourSet(exact, i, minLength).join()) same++;
  }
  return { contacts, meanRatio: ratioSum / contacts, totalRatio: labelSum / exactSum, cellAgreement: same / count };
}
