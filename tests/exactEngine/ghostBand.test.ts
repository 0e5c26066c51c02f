/**
 * The exact engine's own triangulation (a port of Delaunator into kept buffers) and the ghost
 * band of periodic copies (only the copies near a seam, every cell certified, the band widened
 * where a cell is not): same diagram as exactVoronoi's full copies, far fewer points.
 */
import Delaunator from 'delaunator';
import { describe, expect, it } from 'vitest';
import { exactVoronoi } from '../../src/core/exact';
import type { Grid } from '../../src/core/grid';
import { Random } from '../../src/core/random';
import { placeSites } from '../../src/core/sites';
import { Triangulation } from '../../src/core/exactEngine/delaunay';
import { ExactLloydRun } from '../../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../../src/core/exactEngine/exactSurface';
import { PlanarVoronoi } from '../../src/core/exactEngine/planarVoronoi';

function randomPoints(n: number, seed: number, scale = 100): Float64Array {
  const random = new Random(seed);
  const points = new Float64Array(2 * n);
  for (let k = 0; k < points.length; k++) points[k] = random.next() * scale;
  return points;
}

describe('Triangulation (Delaunator port into kept buffers)', () => {
  it("gives Delaunator's triangles and half-edges, for growing and shrinking point counts in one object", () => {
    const t = new Triangulation();
    for (const [n, seed] of [
      [500, 1],
      [2000, 2],
      [37, 3],
      [1200, 4],
      [3, 5],
    ] as const) {
      const points = randomPoints(n, seed);
      // A longer buffer: only the first n points count.
      const buffer = new Float64Array(2 * n + 40).fill(7);
      buffer.set(points);
      t.triangulate(buffer, n);
      const d = new Delaunator(points);
      expect(t.length).toBe(d.triangles.length);
      expect(Array.from(t.triangles.subarray(0, t.length))).toEqual(Array.from(d.triangles));
      expect(Array.from(t.halfedges.subarray(0, t.length))).toEqual(Array.from(d.halfedges));
    }
  });

  it('skips a later duplicate (no edge reaches it) and gives no triangle for collinear points', () => {
    const t = new Triangulation();
    t.triangulate(new Float64Array([0, 0, 1, 0, 0, 1, 1, 1, 1, 0]), 5);
    expect(t.inedges[4]).toBe(-1);
    t.triangulate(new Float64Array([0, 0, 1, 1, 2, 2, 3, 3]), 4);
    expect(t.length).toBe(0);
  });
});

describe('ghost band of periodic copies', () => {
  const torus: Grid = { width: 300, height: 260, texelX: 1, texelY: 1.2, periodicX: true, periodicY: true };
  const tube: Grid = { width: 256, height: 400, texelX: 1.1, texelY: 1, periodicX: true, periodicY: false };

  function expectSameAsReference(grid: Grid, sites: ArrayLike<number>, voronoi?: PlanarVoronoi) {
    const ref = exactVoronoi(grid, sites);
    const mine = exactSurface(grid, sites, undefined, voronoi);
    const adj = mine;
    expect(Array.from(adj.offsets)).toEqual(Array.from(ref.adjacency.offsets));
    expect(Array.from(adj.neighbours)).toEqual(Array.from(ref.adjacency.neighbours));
    expect(Array.from(mine.border)).toEqual(Array.from(ref.adjacency.border));
    for (let k = 0; k < adj.lengths.length; k++)
      expect(Math.abs(adj.lengths[k] - ref.adjacency.lengths![k])).toBeLessThanOrEqual(1e-9 * ref.adjacency.lengths![k]);
    for (let i = 0; i < ref.count; i++) expect(Math.abs(mine.areas[i] - ref.adjacency.areas[i])).toBeLessThanOrEqual(1e-9 * ref.adjacency.areas[i]);
  }

  it('triangulates a few per cent more points than sites, not 9 (torus) or 3 (tube) times as many', () => {
    for (const [grid, copies] of [
      [torus, 9],
      [tube, 3],
    ] as const) {
      const sites = placeSites(grid, 3000, 5, 1);
      const v = new PlanarVoronoi(grid, 3000).build(sites);
      expect(v.pointCount).toBeLessThan(1.5 * 3000);
      expect(v.pointCount).toBeLessThan(copies * 3000);
      expectSameAsReference(grid, sites, v);
      expect(v.retries).toBe(0);
    }
  });

  it('widens the band where a cell near a seam is not certified (sites crowded to one side), and still gives the exact diagram', () => {
    for (const grid of [torus, tube]) {
      const random = new Random(8);
      const sites = new Float32Array(2 * 400);
      for (let i = 0; i < 400; i++) {
        // Every site in the left fifth of the domain: cells reach far across the seam.
        sites[2 * i] = random.next() * grid.width * 0.2;
        sites[2 * i + 1] = random.next() * grid.height;
      }
      const v = new PlanarVoronoi(grid, 400);
      expectSameAsReference(grid, sites, v);
      expect(v.retries).toBeGreaterThan(0);
      // Every build starts again from the narrow band: the diagram depends on the sites only.
      const before = v.retries;
      expectSameAsReference(grid, placeSites(grid, 400, 3, 1), v);
      expect(v.retries).toBe(before);
    }
  });

  it('tiny domains (cells touching their own copies) take every copy, as exactVoronoi does', () => {
    const small: Grid = { width: 16, height: 16, texelX: 1, texelY: 1, periodicX: true, periodicY: true };
    for (const n of [1, 2, 3, 5]) expectSameAsReference(small, placeSites(small, n, n, 0));
  });

  it('an exact Lloyd run on a torus from random sites: diagram exact at every iteration', () => {
    const sites = placeSites(torus, 600, 4, 0);
    const run = new ExactLloydRun(torus, sites, { maxIterations: 6, tolerance: 0, overRelaxation: 1 });
    while (!run.done) {
      run.step();
      expectSameAsReference(torus, sites);
    }
  });
});
