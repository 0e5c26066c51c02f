/**
 * A triangulation moved with its points and flipped back to Delaunay (delaunayFlip.ts), and the
 * exact diagrams built that way layer after layer (PlanarVoronoi.build with `continues`): the
 * same triangulation as a fresh one where it is unique, a Delaunay one (robust in-circle test)
 * on cocircular lattices, a refusal where the moved triangulation is invalid, and every layer's
 * diagram the same as exactVoronoi's (d3-delaunay, an independent implementation).
 */
import { incircle, orient2d } from 'robust-predicates';
import { describe, expect, it } from 'vitest';
import { exactVoronoi } from '../../src/core/exact';
import type { Grid } from '../../src/core/grid';
import { Random } from '../../src/core/random';
import { placeSites } from '../../src/core/sites';
import { Triangulation } from '../../src/core/exactEngine/delaunay';
import { restoreDelaunay } from '../../src/core/exactEngine/delaunayFlip';
import { ExactLloydRun } from '../../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../../src/core/exactEngine/exactSurface';
import { PlanarVoronoi } from '../../src/core/exactEngine/planarVoronoi';

function randomPoints(n: number, seed: number, scale = 100): Float64Array {
  const random = new Random(seed);
  const points = new Float64Array(2 * n);
  for (let k = 0; k < points.length; k++) points[k] = random.next() * scale;
  return points;
}

/** The triangulation's edges as sorted "p q" pairs. */
function edges(t: Triangulation): string[] {
  const out = new Set<string>();
  for (let e = 0; e < t.length; e++) {
    const p = t.triangles[e];
    const q = t.triangles[e % 3 === 2 ? e - 2 : e + 1];
    out.add(p < q ? `${p} ${q}` : `${q} ${p}`);
  }
  return [...out].sort();
}

/** Every triangle positive and no point strictly inside the circumcircle across any edge (exact predicates). */
function expectDelaunay(t: Triangulation, c: Float64Array): void {
  const { triangles, halfedges } = t;
  const bad: string[] = [];
  for (let e = 0; e < t.length; e++) {
    const t0 = e - (e % 3);
    const [a, b, d] = [2 * triangles[t0], 2 * triangles[t0 + 1], 2 * triangles[t0 + 2]];
    const orientation = orient2d(c[a], c[a + 1], c[b], c[b + 1], c[d], c[d + 1]);
    if (!(orientation > 0)) bad.push(`triangle ${t0 / 3} not positive`);
    const twin = halfedges[e];
    if (twin === -1) continue;
    const opposite = 2 * triangles[twin - (twin % 3) + ((twin + 2) % 3)];
    // robust-predicates: incircle and orient2d have opposite signs for a point inside.
    if (incircle(c[a], c[a + 1], c[b], c[b + 1], c[d], c[d + 1], c[opposite], c[opposite + 1]) * orientation < 0) bad.push(`edge ${e} not Delaunay`);
  }
  expect(bad).toEqual([]);
}

/** inedges as Triangulation.triangulate sets them: a half-edge ending at each point, a hull edge on the hull. */
function expectInedges(t: Triangulation): void {
  const end = (e: number) => t.triangles[e % 3 === 2 ? e - 2 : e + 1];
  const bad: number[] = [];
  for (let p = 0; p < t.count; p++) if (!(t.inedges[p] >= 0 && end(t.inedges[p]) === p)) bad.push(p);
  for (let e = 0; e < t.length; e++) if (t.halfedges[e] === -1 && t.halfedges[t.inedges[end(e)]] !== -1) bad.push(end(e));
  expect(bad).toEqual([]);
}

describe('restoreDelaunay (edge flips after the points moved)', () => {
  it('gives the fresh triangulation of points scaled along x or y and jittered, in general position', () => {
    const random = new Random(7);
    for (let trial = 0; trial < 16; trial++) {
      const n = 20 + Math.floor(random.next() * 400);
      const points = randomPoints(n, 100 + trial);
      const t = new Triangulation().triangulate(points, n);
      let changed = 0;
      for (let step = 0; step < 6; step++) {
        const sx = 0.5 + random.next() * 1.5;
        const sy = step % 3 === 2 ? 0.7 + random.next() * 0.6 : 1;
        for (let i = 0; i < n; i++) {
          points[2 * i] = points[2 * i] * sx + (step % 2 === 1 ? (random.next() - 0.5) * 0.02 : 0);
          points[2 * i + 1] *= sy;
        }
        const before = edges(t).join();
        const fresh = new Triangulation().triangulate(points, n);
        if (!restoreDelaunay(t, points)) {
          // Refused (the jitter inverted a sliver): the caller triangulates afresh.
          expect(step % 2).toBe(1);
          t.triangulate(points, n);
          continue;
        }
        expect(t.length).toBe(fresh.length);
        expect(edges(t)).toEqual(edges(fresh));
        expectDelaunay(t, points);
        expectInedges(t);
        if (before !== edges(t).join()) changed++;
      }
      // The flips were exercised: the scalings changed the triangulation.
      expect(changed).toBeGreaterThanOrEqual(3);
    }
  });

  it('gives a Delaunay triangulation of cocircular lattices (square and offset rows) scaled and scaled back', () => {
    let changed = 0;
    for (const [columns, rows, offset] of [
      [7, 5, 0],
      [12, 12, 0],
      [3, 9, 0],
      [9, 8, 0.5],
      [6, 13, 0.5],
    ]) {
      const n = columns * rows;
      // Rows 10 apart; every other row shifted by `offset` of a column (isosceles trapezoids:
      // cocircular fours at every scale).
      const lattice = (sx: number) => {
        const points = new Float64Array(2 * n);
        for (let i = 0; i < n; i++) {
          const row = Math.floor(i / columns);
          points[2 * i] = ((i % columns) + (row % 2) * offset) * 10 * sx;
          points[2 * i + 1] = row * 10;
        }
        return points;
      };
      const points = lattice(1.7);
      const t = new Triangulation().triangulate(points, n);
      for (const sx of [1, 0.6, 2.5, 0.3, 1]) {
        points.set(lattice(sx));
        const before = edges(t).join();
        expect(restoreDelaunay(t, points)).toBe(true);
        expectDelaunay(t, points);
        expectInedges(t);
        // As many triangles as a fresh triangulation (the same hull, every point used).
        expect(t.length).toBe(new Triangulation().triangulate(points, n).length);
        if (edges(t).join() !== before) changed++;
      }
    }
    expect(changed).toBeGreaterThan(0);
  });

  it('refuses a moved triangulation with an inverted triangle or a hull no longer convex', () => {
    const square = new Float64Array([0, 0, 10, 0, 10, 10, 0, 10, 5, 5]);
    const t = new Triangulation().triangulate(square, 5);
    // The centre point thrown out of the square: triangles invert.
    expect(restoreDelaunay(t, new Float64Array([0, 0, 10, 0, 10, 10, 0, 10, 30, 5]))).toBe(false);
    // A corner pushed in past the diagonal of its neighbours: every triangle still positive
    // around the low centre point, but the hull is no longer convex.
    const low = new Float64Array([0, 0, 10, 0, 10, 10, 0, 10, 5, 2]);
    const t2 = new Triangulation().triangulate(low, 5);
    const moved = new Float64Array([0, 0, 10, 0, 5, 4.5, 0, 10, 5, 2]);
    for (let e = 0; e < t2.length; e += 3) {
      const [a, b, c] = [2 * t2.triangles[e], 2 * t2.triangles[e + 1], 2 * t2.triangles[e + 2]];
      expect(orient2d(moved[a], moved[a + 1], moved[b], moved[b + 1], moved[c], moved[c + 1])).toBeGreaterThan(0);
    }
    expect(restoreDelaunay(t2, moved)).toBe(false);
    expect(restoreDelaunay(new Triangulation().triangulate(new Float64Array([0, 0, 1, 1, 2, 2]), 3), new Float64Array(6))).toBe(false);
  });
});

describe('PlanarVoronoi layer after layer (build with continues)', () => {
  function expectSameAsReference(grid: Grid, sites: ArrayLike<number>, voronoi: PlanarVoronoi, continues: boolean) {
    const ref = exactVoronoi(grid, sites).adjacency;
    const mine = exactSurface(grid, sites, undefined, voronoi, continues);
    expect(Array.from(mine.offsets)).toEqual(Array.from(ref.offsets));
    expect(Array.from(mine.neighbours)).toEqual(Array.from(ref.neighbours));
    expect(Array.from(mine.border)).toEqual(Array.from(ref.border));
    for (let k = 0; k < mine.lengths.length; k++) expect(Math.abs(mine.lengths[k] - ref.lengths![k])).toBeLessThanOrEqual(1e-9 * ref.lengths![k]);
    for (let i = 0; i < ref.count; i++) expect(Math.abs(mine.areas[i] - ref.areas[i])).toBeLessThanOrEqual(1e-9 * ref.areas[i]);
  }

  /** The sites on the layer of ratio s: the circumference (x) scaled, as a tube's layers are. */
  function layer(grid: Grid, sites: Float32Array, s: number): { grid: Grid; sites: Float32Array } {
    const width = Math.round(grid.width * s);
    const scaled = new Float32Array(sites.length);
    for (let i = 0; i < sites.length; i += 2) {
      scaled[i] = Math.min(sites[i] * (width / grid.width), width * (1 - Number.EPSILON));
      scaled[i + 1] = sites[i + 1];
    }
    return { grid: { ...grid, width, texelX: (grid.width * grid.texelX * s) / width }, sites: scaled };
  }

  const tube: Grid = { width: 128, height: 512, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
  const torus: Grid = { width: 150, height: 130, texelX: 1, texelY: 1.2, periodicX: true, periodicY: true };
  const plane: Grid = { width: 200, height: 160, texelX: 1, texelY: 1, periodicX: false, periodicY: false };

  for (const [name, grid, cells, ratios] of [
    ['tube, outward', tube, 60, [1.25, 1.5, 2, 2.25, 3, 4, 6, 8, 10]],
    ['tube, inward', tube, 60, [1, 0.9, 0.75, 0.6, 0.5]],
    ['torus', torus, 80, [1, 1.3, 1.7, 2.5, 0.8]],
    ['plane', plane, 70, [1, 1.5, 2.5, 4]],
  ] as const) {
    it(`gives exactVoronoi's diagram on every layer of a ${name}, most layers moved`, () => {
      for (const seed of [1, 2, 3]) {
        const sites = placeSites(grid, cells, seed, 1);
        // Relaxed sites (the sweep's case) and the raw random ones.
        if (seed > 1) new ExactLloydRun(grid, sites, { maxIterations: 3, tolerance: 0, overRelaxation: 1 }).finish();
        // With the first band of a chain of layers (narrower) and the usual one.
        const v = new PlanarVoronoi(grid, cells, seed !== 2);
        ratios.forEach((s, k) => {
          const l = layer(grid, sites, s);
          expectSameAsReference(l.grid, l.sites, v, k > 0);
        });
        expect(v.moved).toBeGreaterThanOrEqual(ratios.length - 3);
      }
    });
  }

  it("gives exactVoronoi's diagram on every layer of a tube whose sites are a lattice (cocircular fours)", () => {
    // 8 columns around, 16 rows along; every other row offset by half a column.
    const sites = new Float32Array(2 * 128);
    for (let i = 0; i < 128; i++) {
      const row = Math.floor(i / 8);
      sites[2 * i] = ((i % 8) + 0.25 + (row % 2) * 0.5) * 16;
      sites[2 * i + 1] = (row + 0.5) * 32;
    }
    const v = new PlanarVoronoi(tube, 128);
    [1, 1.25, 1.5, 2, 3, 4.5].forEach((s, k) => {
      const l = layer(tube, sites, s);
      expectSameAsReference(l.grid, l.sites, v, k > 0);
    });
    expect(v.moved).toBeGreaterThan(0);
  });

  it('widens the band where the moved copies no longer certify a layer (a tube shrunk to a tenth), still exact', () => {
    // 600 cells: the first band is a third of the circumference; shrinking the tube widens the
    // cells relative to it until a cell reaches past it.
    const sites = placeSites(tube, 600, 2, 1);
    const v = new PlanarVoronoi(tube, 600, true);
    [1, 0.6, 0.4, 0.25, 0.15, 0.1].forEach((s, k) => {
      const l = layer(tube, sites, s);
      expectSameAsReference(l.grid, l.sites, v, k > 0);
    });
    expect(v.moved).toBeGreaterThan(0);
    expect(v.retries).toBeGreaterThan(0);
  });

  it('triangulates afresh where the sites moved too far (other sites), with the same diagram', () => {
    const v = new PlanarVoronoi(tube, 60);
    for (const seed of [4, 5, 6]) expectSameAsReference(tube, placeSites(tube, 60, seed, 1), v, true);
    expect(v.moved).toBe(0);
  });
});
