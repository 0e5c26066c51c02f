import { describe, expect, it } from 'vitest';
import { isSymmetric } from '../oracles/adjacency';
import { ellipsoidArea } from '../../src/core/closed/conicArc';
import { randomSequentialSites } from './randomSequentialSites';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import { icosphere } from '../../src/core/mesh/generate';
import { compareNeighbourSets, ellipsoidContactsReference, neighbourLists } from './restrictedReference';

/** Prolate spheroid (a > b = c) surface area in closed form. */
function prolateArea(a: number, b: number): number {
  const e = Math.sqrt(1 - (b * b) / (a * a));
  return 2 * Math.PI * b * b * (1 + (a / (b * e)) * Math.asin(e));
}

describe('restricted Voronoi on the analytic ellipsoid', () => {
  it('ellipsoidArea matches the closed form of a prolate spheroid and of a sphere', () => {
    expect(Math.abs(ellipsoidArea(90, 45, 45) / prolateArea(90, 45) - 1)).toBeLessThan(1e-12);
    expect(Math.abs(ellipsoidArea(45, 90, 45) / prolateArea(90, 45) - 1)).toBeLessThan(1e-12);
    expect(Math.abs(ellipsoidArea(30, 30, 30) / (4 * Math.PI * 900) - 1)).toBeLessThan(1e-13);
  });

  for (const [a, b, c, count, spacing] of [
    [90, 45, 45, 200, 6],
    [80, 50, 35, 200, 5],
  ] as const) {
    it(`${a}:${b}:${c} µm, ${count} RSA cells: neighbour sets and conic-arc lengths against bisector plane ∩ ellipsoid sampled densely`, () => {
      const seeded = randomSequentialSites({ kind: 'ellipsoid', a, b, c }, count, spacing, 7);
      const rvd = restrictedVoronoi({ kind: 'ellipsoid', a, b, c }, seeded.positions, count);
      const area = ellipsoidArea(a, b, c);
      const cutoff = 3 * Math.sqrt(area / count);
      const ref = ellipsoidContactsReference(seeded.positions, count, a, b, c, cutoff);
      const lists = neighbourLists(ref, 1e-6);
      const cmp = compareNeighbourSets(rvd.adjacency, lists);
      // Lengths of the contacts both found; and every RVD contact lies within the cutoff.
      let maxLength = 0,
        pairs = 0,
        shortest = Infinity;
      for (let i = 0; i < count; i++) {
        for (let k = rvd.adjacency.offsets[i]; k < rvd.adjacency.offsets[i + 1]; k++) {
          const j = rvd.adjacency.neighbours[k];
          const d = Math.hypot(
            seeded.positions[3 * j] - seeded.positions[3 * i],
            seeded.positions[3 * j + 1] - seeded.positions[3 * i + 1],
            seeded.positions[3 * j + 2] - seeded.positions[3 * i + 2],
          );
          expect(d).toBeLessThan(cutoff);
          shortest = Math.min(shortest, rvd.adjacency.lengths[k]);
          const other = ref.lengths.get(Math.min(i, j) * count + Math.max(i, j));
          if (other === undefined) continue;
          pairs++;
          maxLength = Math.max(maxLength, Math.abs(other - rvd.adjacency.lengths[k]));
        }
      }
      const sum = rvd.adjacency.areas.reduce((s, v) => s + v, 0);
      console.log(
        `ellipsoid ${a}:${b}:${c}, ${count} cells: ${cmp.same}/${count} neighbour sets equal the dense conic reference (${(100 * cmp.fraction).toFixed(2)} %), differ ${JSON.stringify(cmp.differ)}; ` +
          `max |Δlength| ${maxLength.toExponential(2)} µm over ${pairs / 2} contacts (shortest RVD contact ${shortest.toExponential(2)} µm); Σ areas / area - 1 = ${(sum / area - 1).toExponential(2)}; ${rvd.stats.ms.toFixed(0)} ms, ${JSON.stringify(rvd.stats)}`,
      );
      expect(cmp.fraction).toBeGreaterThanOrEqual(0.995);
      expect(maxLength).toBeLessThan(1e-3);
      expect(Math.abs(sum / area - 1)).toBeLessThan(1e-9);
      expect(isSymmetric(rvd.adjacency, 1e-9)).toBe(true);
      for (const v of rvd.adjacency.areas) expect(v).toBeGreaterThan(0);
    }, 60000);
  }

  it('a triangulated ellipsoid (mesh RVD) converges to the analytic one', () => {
    // Same sites, analytic vs an icosphere stretched onto the ellipsoid: the neighbour sets
    // agree and lengths differ by the chord error only.
    const a = 60,
      b = 40,
      c = 30,
      count = 150;
    const seeded = randomSequentialSites({ kind: 'ellipsoid', a, b, c }, count, 4, 3);
    const analytic = restrictedVoronoi({ kind: 'ellipsoid', a, b, c }, seeded.positions, count);
    const lists = Array.from({ length: count }, (_, i) =>
      Array.from(analytic.adjacency.neighbours.subarray(analytic.adjacency.offsets[i], analytic.adjacency.offsets[i + 1])),
    );
    // Vertices exactly on the ellipsoid: icosphere directions mapped by diag(a, b, c).
    const f = 48;
    const ico = icosphere(f);
    const positions = new Float64Array(ico.positions.length);
    for (let v = 0; v < positions.length; v += 3) {
      const l = Math.hypot(ico.positions[v], ico.positions[v + 1], ico.positions[v + 2]);
      positions[v] = (a * ico.positions[v]) / l;
      positions[v + 1] = (b * ico.positions[v + 1]) / l;
      positions[v + 2] = (c * ico.positions[v + 2]) / l;
    }
    const mesh = restrictedVoronoi({ kind: 'mesh', positions, indices: ico.indices }, seeded.positions, count);
    const cmp = compareNeighbourSets(mesh.adjacency, lists);
    let worst = 0;
    for (let i = 0; i < count; i++) worst = Math.max(worst, Math.abs(mesh.adjacency.areas[i] / analytic.adjacency.areas[i] - 1));
    console.log(
      `ellipsoid ${a}:${b}:${c} as ${ico.indices.length / 3} triangles: ${cmp.same}/${count} neighbour sets equal the analytic RVD; worst relative cell-area difference ${worst.toExponential(2)}`,
    );
    expect(cmp.fraction).toBeGreaterThanOrEqual(0.98);
    expect(worst).toBeLessThan(0.01);
  });
});
