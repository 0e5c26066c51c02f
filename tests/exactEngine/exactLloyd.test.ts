import { describe, expect, it } from 'vitest';
import { exactVoronoi } from '../../src/core/exact';
import { wrapDelta, type Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { ExactCentroids, ExactLloydRun } from '../../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../../src/core/exactEngine/exactSurface';
import { densityField } from '../../src/core/density';
import type { ExactDensity } from '../../src/core/exactEngine/cellIntegrals';

const tube: Grid = { width: 128, height: 400, texelX: 1.1, texelY: 1, periodicX: true, periodicY: false };
const plane: Grid = { width: 220, height: 160, texelX: 1, texelY: 1.25, periodicX: false, periodicY: false };
const torus: Grid = { width: 150, height: 130, texelX: 1, texelY: 1, periodicX: true, periodicY: true };
const plain = { maxIterations: 25, tolerance: 0, overRelaxation: 1 };

/** Centroids (texel units) from the engine's sums, for comparison with exactVoronoi's. */
function engineCentroids(grid: Grid, sites: Float32Array, density?: ExactDensity): Float64Array {
  const c = new ExactCentroids(grid, sites.length / 2, density);
  c.build(sites);
  const sums = c.computeSums();
  const out = new Float64Array(sites.length);
  for (let i = 0; i < sites.length / 2; i++) {
    out[2 * i] = sites[2 * i] + sums[4 * i] / sums[4 * i + 2];
    out[2 * i + 1] = sites[2 * i + 1] + sums[4 * i + 1] / sums[4 * i + 2];
  }
  return out;
}

describe('exact Lloyd energy', () => {
  for (const [name, grid] of [
    ['tube', tube],
    ['plane', plane],
    ['torus', torus],
  ] as const) {
    it(`${name}: never rises under plain Lloyd and falls overall`, () => {
      const sites = placeSites(grid, 150, 5, 1.5);
      const run = new ExactLloydRun(grid, sites, plain);
      while (!run.done) run.step();
      const energies = [...run.iterations.map((r) => r.energy), run.finish().energy];
      for (let k = 1; k < energies.length; k++) expect(energies[k]).toBeLessThanOrEqual(energies[k - 1] * (1 + 1e-12));
      expect(energies.at(-1)!).toBeLessThan(energies[0] * 0.9);
      expect(run.iterations.every((r) => r.jumpFloodPasses === 0)).toBe(true);
    });
  }

  it('energy equals the sum of exact second moments about the sites (independent formula)', () => {
    const sites = placeSites(tube, 60, 2, 2);
    const run = new ExactLloydRun(tube, sites.slice(), { ...plain, maxIterations: 1 });
    const record = run.step();
    // ∫|x - z|² over a polygon by the fan of triangles (site, v_k, v_k+1): ∫ = A/6 (|a|² + |b|² + a·b) with z at the origin.
    const v = exactVoronoi(tube, sites);
    let energy = 0;
    for (const cell of v.cells) {
      const p = cell.polygon;
      const m = p.length / 2;
      const zx = sites[2 * cell.id];
      const zy = sites[2 * cell.id + 1];
      for (let k = 0; k < m; k++) {
        const l = (k + 1) % m;
        const ax = (p[2 * k] - zx) * tube.texelX;
        const ay = (p[2 * k + 1] - zy) * tube.texelY;
        const bx = (p[2 * l] - zx) * tube.texelX;
        const by = (p[2 * l + 1] - zy) * tube.texelY;
        const area = Math.abs(ax * by - bx * ay) / 2;
        energy += (area / 6) * (ax * ax + ay * ay + bx * bx + by * by + ax * bx + ay * by);
      }
    }
    expect(record.energy).toBeCloseTo(energy, 6);
  });

  it('stops at the tolerance and over-relaxation lowers the energy reached', () => {
    const energyAfter = (omega: number) => {
      const run = new ExactLloydRun(plane, placeSites(plane, 100, 8, 1.5), { maxIterations: 20, tolerance: 0, overRelaxation: omega });
      while (!run.done) run.step();
      return run.finish().energy;
    };
    expect(energyAfter(1.6)).toBeLessThan(energyAfter(1));
    const run = new ExactLloydRun(plane, placeSites(plane, 100, 8, 1.5), { maxIterations: 500, tolerance: 0.05, overRelaxation: 1 });
    while (!run.done) run.step();
    expect(run.converged).toBe(true);
    expect(run.iterations.at(-1)!.maxDisplacement).toBeLessThan(0.05);
  });
});

describe('fixed points and centroids', () => {
  it('a hexagonal arrangement on a periodic plane is a Lloyd fixed point', () => {
    // 8 x 10 sites of a hexagonal lattice, spacing a: rows a·√3/2 apart, odd rows shifted by a/2.
    const a = 10;
    const cols = 8;
    const rows = 10;
    const grid: Grid = { width: cols * a, height: (rows * a * Math.sqrt(3)) / 2, texelX: 1, texelY: 1, periodicX: true, periodicY: true };
    const sites = new Float32Array(2 * cols * rows);
    for (let r = 0; r < rows; r++) {
      for (let c = 0; c < cols; c++) {
        sites[2 * (r * cols + c)] = (c + 0.25 + (r % 2) * 0.5) * a;
        sites[2 * (r * cols + c) + 1] = (r + 0.5) * ((a * Math.sqrt(3)) / 2);
      }
    }
    const before = sites.slice();
    const run = new ExactLloydRun(grid, sites, { maxIterations: 3, tolerance: 0, overRelaxation: 1 });
    while (!run.done) run.step();
    for (const record of run.iterations) expect(record.maxDisplacement).toBeLessThan(1e-4);
    for (let k = 0; k < sites.length; k++) expect(Math.abs(sites[k] - before[k])).toBeLessThan(1e-4);
    // Every cell is a regular hexagon with 6 neighbours.
    const surface = exactSurface(grid, sites);
    for (let i = 0; i < cols * rows; i++) expect(surface.offsets[i + 1] - surface.offsets[i]).toBe(6);
  });

  it('the centroid of a single cell is the centroid of its polygon (the whole domain)', () => {
    const sites = new Float32Array([40.5, 97.25]);
    const c = engineCentroids(plane, sites);
    expect(c[0]).toBeCloseTo(plane.width / 2, 9);
    expect(c[1]).toBeCloseTo(plane.height / 2, 9);
  });

  for (const [name, grid] of [
    ['tube', tube],
    ['plane', plane],
    ['torus', torus],
  ] as const) {
    it(`${name}: every centroid equals exactVoronoi's polygon centroid`, () => {
      const sites = placeSites(grid, 120, 9, 1);
      const mine = engineCentroids(grid, sites);
      const ref = exactVoronoi(grid, sites).centroids;
      for (let i = 0; i < 120; i++) {
        expect(Math.abs(wrapDelta(mine[2 * i] - ref[2 * i], grid.width, grid.periodicX))).toBeLessThan(1e-7);
        expect(Math.abs(wrapDelta(mine[2 * i + 1] - ref[2 * i + 1], grid.height, grid.periodicY))).toBeLessThan(1e-7);
      }
    });
  }
});

describe('density integration', () => {
  const sites = placeSites(tube, 80, 4, 2);
  const uniform = () => {
    const c = new ExactCentroids(tube, 80);
    c.build(sites);
    return c.computeSums().slice();
  };
  const sumsFor = (density: ExactDensity, grid = tube) => {
    const c = new ExactCentroids(grid, 80, density);
    c.build(sites);
    return c.computeSums().slice();
  };

  it('quadrature of a constant density equals the closed form for uniform (rule and cuts)', () => {
    const closed = uniform();
    const constants: ExactDensity[] = [
      { kind: 'linear', axis: 'x', from: 1, to: 1 },
      { kind: 'gaussian', center: [30, 40], sigma: 15, peak: 1 },
      { kind: 'stripes', axis: 'y', period: 37, low: 1, high: 1 },
      { kind: 'texels', field: new Float32Array(tube.width * tube.height).fill(1) },
    ];
    for (const density of constants) {
      const sums = sumsFor(density);
      for (let k = 0; k < closed.length; k++) expect(sums[k]).toBeCloseTo(closed[k], 6);
    }
  });

  it('linear densities are integrated exactly: a ramp of slope 0 in y but 2 in x (seam cut on the tube)', () => {
    // Independent check: weight of every cell = ∫(from + (to - from)·x/W) = area·ρ(centroid x) for a cell that
    // does not cross the seam (linear in x; exact formula).
    const density: ExactDensity = { kind: 'linear', axis: 'x', from: 1, to: 3 };
    const sums = sumsFor(density);
    const v = exactVoronoi(tube, sites);
    const W = tube.width * tube.texelX;
    let checked = 0;
    for (const cell of v.cells) {
      const xs = Array.from(cell.polygon.filter((_, k) => k % 2 === 0));
      if (Math.min(...xs) < 0 || Math.max(...xs) > tube.width) continue;
      const expected = (cell.area * (1 + (2 * cell.centroidX * tube.texelX) / W)) / (tube.texelX * tube.texelY);
      expect(sums[4 * cell.id + 2]).toBeCloseTo(expected, 6);
      checked++;
    }
    expect(checked).toBeGreaterThan(40);
  });

  it('a gaussian by quadrature agrees with a fine per-texel midpoint sum (1e-3)', () => {
    const density: ExactDensity & { kind: 'gaussian' } = { kind: 'gaussian', center: [40, 200], sigma: 18, peak: 5 };
    const exact = sumsFor(density);
    // Reference: the field sampled at the centres of an 8x finer grid, integrated per texel (midpoint rule).
    const fine: Grid = { ...tube, width: tube.width * 8, height: tube.height * 8, texelX: tube.texelX / 8, texelY: tube.texelY / 8 };
    const field = densityField(density, fine);
    const c = new ExactCentroids(fine, 80, { kind: 'texels', field });
    const fineSites = new Float32Array(sites.length);
    for (let k = 0; k < sites.length; k++) fineSites[k] = sites[k] * 8;
    c.build(fineSites);
    const ref = c.computeSums();
    for (let i = 0; i < 80; i++) {
      // fine sums are in fine texels: weight x 64, offsets x 8 per unit weight.
      expect(Math.abs(exact[4 * i + 2] * 64 - ref[4 * i + 2]) / ref[4 * i + 2]).toBeLessThan(1e-3);
      const cx = exact[4 * i] / exact[4 * i + 2];
      const rx = ref[4 * i] / ref[4 * i + 2] / 8;
      expect(Math.abs(cx - rx)).toBeLessThan(2e-2);
    }
  });
});

describe('exactSurface against exactVoronoi', () => {
  for (const [name, grid] of [
    ['tube', tube],
    ['plane', plane],
    ['torus', torus],
  ] as const) {
    it(`${name}: identical neighbours, lengths, areas and open-end contacts`, () => {
      for (const seed of [1, 2, 3]) {
        const sites = placeSites(grid, 150, seed, 1);
        const ref = exactVoronoi(grid, sites);
        const mine = exactSurface(grid, sites);
        const adj = mine;
        expect(Array.from(adj.offsets)).toEqual(Array.from(ref.adjacency.offsets));
        expect(Array.from(adj.neighbours)).toEqual(Array.from(ref.adjacency.neighbours));
        for (let k = 0; k < adj.lengths.length; k++) expect(adj.lengths[k]).toBeCloseTo(ref.adjacency.lengths![k], 6);
        expect(Array.from(mine.border)).toEqual(Array.from(ref.adjacency.border));
        for (let i = 0; i < 150; i++) expect(mine.areas[i]).toBeCloseTo(ref.adjacency.areas[i], 6);
      }
    });
  }
});
