/**
 * The symmetry every adjacency must have (a test invariant, not used by the product): j is in
 * i's list exactly when i is in j's, with the same shared length.
 */
import type { SurfaceAdjacency } from '../../src/core/analysis/adjacency';

/** True when j is in i's list exactly when i is in j's list (with equal lengths, within tol). */
export function isSymmetric(adj: Pick<SurfaceAdjacency, 'offsets' | 'neighbours' | 'lengths'>, tol = 1e-9): boolean {
  const count = adj.offsets.length - 1;
  for (let i = 0; i < count; i++) {
    for (let k = adj.offsets[i]; k < adj.offsets[i + 1]; k++) {
      const j = adj.neighbours[k];
      let found = -1;
      for (let q = adj.offsets[j]; q < adj.offsets[j + 1]; q++) if (adj.neighbours[q] === i) found = q;
      if (found < 0) return false;
      if (Math.abs(adj.lengths[found] - adj.lengths[k]) > tol * Math.max(1, adj.lengths[k])) return false;
    }
  }
  return true;
}
