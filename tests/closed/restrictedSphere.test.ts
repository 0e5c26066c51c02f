import { describe, expect, it } from 'vitest';
import { isSymmetric } from '../oracles/adjacency';
import { randomSequentialSites } from './randomSequentialSites';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import { sphereSurface } from '../../src/core/closed/restrictedSurface';
import { sphericalVoronoi } from '../oracles/sphericalDelaunay';
import { createRandom } from '../../src/core/random';
import { compareNeighbourSets } from './restrictedReference';

/** Exact on the sphere: the restricted Voronoi diagram of the analytic sphere equals the convex hull's. */
function compareWithHull(R: number, positions: Float64Array, count: number) {
  const hull = sphericalVoronoi(positions, count, R);
  const rvd = restrictedVoronoi(sphereSurface(R), positions, count);
  const lists = Array.from({ length: count }, (_, i) =>
    Array.from(hull.adjacency.neighbours.subarray(hull.adjacency.offsets[i], hull.adjacency.offsets[i + 1])).sort((x, y) => x - y),
  );
  const cmp = compareNeighbourSets(rvd.adjacency, lists);
  let maxLength = 0,
    maxArea = 0,
    sum = 0;
  for (let i = 0; i < count; i++) {
    for (let k = hull.adjacency.offsets[i]; k < hull.adjacency.offsets[i + 1]; k++) {
      const j = hull.adjacency.neighbours[k];
      for (let q = rvd.adjacency.offsets[i]; q < rvd.adjacency.offsets[i + 1]; q++) {
        if (rvd.adjacency.neighbours[q] === j) maxLength = Math.max(maxLength, Math.abs(rvd.adjacency.lengths[q] - hull.adjacency.lengths[k]));
      }
    }
    maxArea = Math.max(maxArea, Math.abs(rvd.adjacency.areas[i] - hull.areas[i]) / hull.areas[i]);
    sum += rvd.adjacency.areas[i];
  }
  return { rvd, cmp, maxLength, maxArea, sum };
}

describe('restricted Voronoi on the analytic sphere', () => {
  it('equals the convex hull (spherical Voronoi) for RSA sites: every neighbour set, lengths within 1e-4 µm', () => {
    const R = 50,
      count = 300;
    const seeded = randomSequentialSites(sphereSurface(R), count, 3, 11);
    const { rvd, cmp, maxLength, maxArea, sum } = compareWithHull(R, seeded.positions, count);
    console.log(
      `sphere R=${R}, ${count} RSA cells: ${cmp.same}/${count} neighbour sets equal the hull's, max |Δlength| ${maxLength.toExponential(2)} µm, max relative |Δarea| ${maxArea.toExponential(2)}, ${rvd.stats.ms.toFixed(0)} ms`,
    );
    expect(cmp.differ).toEqual([]);
    expect(maxLength).toBeLessThan(1e-4);
    expect(maxArea).toBeLessThan(1e-8);
    expect(Math.abs(sum - 4 * Math.PI * R * R) / (4 * Math.PI * R * R)).toBeLessThan(1e-10);
    expect(isSymmetric(rvd.adjacency, 1e-9)).toBe(true);
    expect(Array.from(rvd.adjacency.border).every((v) => v === 0)).toBe(true);
  });

  it('equals the hull for uniformly random (Poisson) sites, whose cells are irregular', () => {
    const R = 100,
      count = 1000;
    const random = createRandom(3);
    const positions = new Float64Array(3 * count);
    for (let i = 0; i < count; i++) {
      const z = 2 * random.next() - 1,
        l = 2 * Math.PI * random.next(),
        r = Math.sqrt(1 - z * z);
      positions[3 * i] = R * r * Math.cos(l);
      positions[3 * i + 1] = R * r * Math.sin(l);
      positions[3 * i + 2] = R * z;
    }
    const { cmp, maxLength, sum } = compareWithHull(R, positions, count);
    console.log(`sphere R=${R}, ${count} Poisson cells: ${cmp.same}/${count} equal, max |Δlength| ${maxLength.toExponential(2)} µm`);
    expect(cmp.differ).toEqual([]);
    expect(maxLength).toBeLessThan(1e-4);
    expect(Math.abs(sum - 4 * Math.PI * R * R) / (4 * Math.PI * R * R)).toBeLessThan(1e-10);
  });

  it('neighbours are sorted per cell and lengths are positive', () => {
    const seeded = randomSequentialSites(sphereSurface(20), 60, 1, 2);
    const { rvd } = compareWithHull(20, seeded.positions, 60);
    const { offsets, neighbours, lengths } = rvd.adjacency;
    for (let i = 0; i < 60; i++) {
      for (let k = offsets[i]; k + 1 < offsets[i + 1]; k++) expect(neighbours[k]).toBeLessThan(neighbours[k + 1]);
      for (let k = offsets[i]; k < offsets[i + 1]; k++) expect(lengths[k]).toBeGreaterThan(0);
    }
  });

  it('refuses sites off the ellipsoid with a message naming sites', () => {
    expect(() => restrictedVoronoi(sphereSurface(10), [10, 0, 0, 0, 11, 0], 2)).toThrow(/^sites: site 1 .* not on the ellipsoid/);
  });
});
