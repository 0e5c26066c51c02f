import { describe, expect, it } from 'vitest';
import { distanceSquared, wrapDelta, type Grid } from '../../src/core/grid';
import { BORDER_X_END, BORDER_X_START, BORDER_Y_END, BORDER_Y_START } from '../../src/core/border';
import { accumulateCentroidRows, labelAdjacency } from '../../src/core/labels';
import { moveSitesToCentroids } from '../../src/core/lloydUpdate';
import { bruteForceLabels, centroidSites, cvtEnergy, reduceCentroids, sharedLength } from '../oracles/labels';
import { Random } from '../../src/core/random';

/** The definition, in O(sites x texels): nearest site, ties to the smaller id. */
function naiveLabels(grid: Grid, sites: Float32Array): Int32Array {
  const labels = new Int32Array(grid.width * grid.height).fill(-1);
  for (let j = 0; j < grid.height; j++) {
    for (let i = 0; i < grid.width; i++) {
      let best = Infinity;
      for (let id = 0; id < sites.length / 2; id++) {
        const d = distanceSquared(grid, i + 0.5, j + 0.5, sites[2 * id], sites[2 * id + 1]);
        if (d < best) {
          best = d;
          labels[j * grid.width + i] = id;
        }
      }
    }
  }
  return labels;
}

function randomSites(grid: Grid, count: number, seed: number): Float32Array {
  const random = new Random(seed);
  const sites = new Float32Array(2 * count);
  for (let id = 0; id < count; id++) {
    sites[2 * id] = random.next() * grid.width;
    sites[2 * id + 1] = random.next() * grid.height;
  }
  return sites;
}

const grids: Grid[] = [
  { width: 23, height: 17, texelX: 1, texelY: 1, periodicX: false, periodicY: false },
  { width: 16, height: 40, texelX: 2, texelY: 1.5, periodicX: true, periodicY: false },
  { width: 31, height: 12, texelX: 0.7, texelY: 2.2, periodicX: true, periodicY: true },
  { width: 9, height: 30, texelX: 1, texelY: 1, periodicX: false, periodicY: true },
];

describe('bruteForceLabels', () => {
  it('agrees with the naive definition on random cases, periodic or not', () => {
    let seed = 1;
    for (const grid of grids) {
      for (const count of [1, 2, 3, 7, 40, 150]) {
        const sites = randomSites(grid, count, seed++);
        expect(Array.from(bruteForceLabels(grid, sites)), `${JSON.stringify(grid)} ${count}`).toEqual(Array.from(naiveLabels(grid, sites)));
      }
    }
  });

  it('labels across a periodic seam', () => {
    const grid = grids[1];
    const sites = Float32Array.from([0.2, 20, 8, 20]); // the first site sits just right of the seam
    const labels = bruteForceLabels(grid, sites);
    // Texel x = 15 (centre 15.5) is 0.7 texels from site 0 through the seam, 7.5 from site 1.
    expect(labels[20 * grid.width + 15]).toBe(0);
    expect(labels[20 * grid.width + 7]).toBe(1);
  });

  it('breaks exact ties towards the smaller id', () => {
    const grid: Grid = { width: 4, height: 2, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    // Texel centres x = 1.5 lie exactly between sites at x = 0.5 and x = 2.5 (listed larger id first).
    const sites = Float32Array.from([2.5, 1, 0.5, 1]);
    const labels = bruteForceLabels(grid, sites);
    expect(labels[1]).toBe(0);
    expect(labels[0]).toBe(1);
    expect(Array.from(labels)).toEqual(Array.from(naiveLabels(grid, sites)));
    // Ties between sites in different buckets: sites at x = 0.5, 2.5, ..., 14.5 with ids
    // descending, so each texel's own bucket holds the larger of its two tied sites.
    const row: Grid = { width: 16, height: 1, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const spread = new Float32Array(16);
    for (let m = 0; m < 8; m++) [spread[2 * (7 - m)], spread[2 * (7 - m) + 1]] = [0.5 + 2 * m, 0.5];
    const tied = bruteForceLabels(row, spread);
    for (let m = 0; m < 7; m++) expect(tied[1 + 2 * m]).toBe(6 - m);
    expect(Array.from(tied)).toEqual(Array.from(naiveLabels(row, spread)));
    // Coincident sites: the smaller id wins everywhere.
    expect(Array.from(bruteForceLabels(grid, Float32Array.from([1, 1, 1, 1]))).every((l) => l === 0)).toBe(true);
  });

  it('fills -1 without sites and writes into a given array', () => {
    const grid = grids[0];
    expect(Array.from(bruteForceLabels(grid, new Float32Array(0))).every((l) => l === -1)).toBe(true);
    const out = new Int32Array(grid.width * grid.height);
    const sites = randomSites(grid, 5, 9);
    expect(bruteForceLabels(grid, sites, out)).toBe(out);
    expect(() => bruteForceLabels(grid, sites, new Int32Array(3))).toThrow(/out/);
  });

  // Its speed is a measurement: bench/cpuReferences.ts.
  it('labels 512 x 512 texels with 2000 sites as the definition does (300 random texels)', () => {
    const grid: Grid = { width: 512, height: 512, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
    const sites = randomSites(grid, 2000, 3);
    const labels = bruteForceLabels(grid, sites);
    // Spot-check rows against the definition.
    const random = new Random(4);
    for (let k = 0; k < 300; k++) {
      const t = random.nextInt(512 * 512);
      const [i, j] = [t % 512, Math.floor(t / 512)];
      let best = Infinity;
      let bestId = -1;
      for (let id = 0; id < 2000; id++) {
        const d = distanceSquared(grid, i + 0.5, j + 0.5, sites[2 * id], sites[2 * id + 1]);
        if (d < best) [best, bestId] = [d, id];
      }
      expect(labels[t]).toBe(bestId);
    }
  });
});

describe('reduceCentroids and the Lloyd move', () => {
  // 10 x 4, periodic in x, texels 2 x 3 µm. Cell 0 holds columns 8, 9, 0, 1 (straddling the seam).
  const grid: Grid = { width: 10, height: 4, texelX: 2, texelY: 3, periodicX: true, periodicY: false };
  const labels = new Int32Array(40);
  for (let j = 0; j < 4; j++) for (let i = 0; i < 10; i++) labels[j * 10 + i] = i >= 8 || i <= 1 ? 0 : 1;

  it('unwraps a cell that straddles the seam', () => {
    const sites = Float32Array.from([9.7, 1.0, 5, 2]);
    const sums = reduceCentroids(grid, labels, sites, null);
    // Column centres 8.5, 9.5, 10.5, 11.5 seen from 9.7: offsets -1.2, -0.2, 0.8, 1.8 (sum 1.2 per row).
    expect(sums[0]).toBeCloseTo(4 * 1.2, 5);
    // Row centres 0.5..3.5 seen from y = 1: -0.5, 0.5, 1.5, 2.5, 4 columns each.
    expect(sums[1]).toBeCloseTo(4 * 4, 5);
    expect(sums[2]).toBe(16);
    let d2 = 0;
    for (const dx of [-1.2, -0.2, 0.8, 1.8]) for (const dy of [-0.5, 0.5, 1.5, 2.5]) d2 += (dx * 2) ** 2 + (dy * 3) ** 2;
    expect(sums[3]).toBeCloseTo(d2, 4);
    // Cell 1: columns 2..7, centroid x = 5, y = 2.
    expect(sums[4] / sums[6]).toBeCloseTo(0, 6);
    expect(sums[5] / sums[6]).toBeCloseTo(0, 6);

    const { sites: moved, move } = centroidSites(grid, sites, sums);
    // Centroid of columns 8..11 is x = 10, i.e. the seam, x = 0.
    expect(Math.abs(wrapDelta(moved[0], 10, true))).toBeLessThan(1e-5);
    expect(moved[1]).toBeCloseTo(2, 6);
    expect(moved[2]).toBeCloseTo(5, 6);
    expect(sites[0]).toBeCloseTo(9.7, 5); // input untouched
    expect(move.maxDisplacement).toBeCloseTo(Math.hypot(0.3 * 2, 1 * 3), 4);
    expect(move.emptyCells).toBe(0);
  });

  it('applies weights and over-relaxation', () => {
    // Weight 3 on column 9, 1 elsewhere.
    const weight = new Float32Array(40).fill(1);
    for (let j = 0; j < 4; j++) weight[j * 10 + 9] = 3;
    const sites = Float32Array.from([9.7, 2, 5, 2]);
    const sums = reduceCentroids(grid, labels, sites, weight);
    const mean = (8.5 + 3 * 9.5 + 10.5 + 11.5) / 6; // weighted centroid x
    expect(sums[2]).toBe(24);
    expect(sums[0] / sums[2]).toBeCloseTo(mean - 9.7, 5);
    const { sites: relaxed } = centroidSites(grid, sites, sums, 1.5);
    expect(relaxed[0]).toBeCloseTo(9.7 + 1.5 * (mean - 9.7), 5);
  });

  it('leaves sites with empty cells in place and skips unlabelled texels', () => {
    const partial = labels.slice();
    partial[0] = -1;
    const sites = Float32Array.from([9.7, 1.0, 5, 2, 3.3, 3.3]);
    const sums = reduceCentroids(grid, partial, sites, null);
    expect(sums[2]).toBe(15);
    expect(sums.slice(8)).toEqual(new Float64Array(4));
    const { sites: moved, move } = centroidSites(grid, sites, sums);
    expect([moved[4], moved[5]]).toEqual([sites[4], sites[5]]);
    expect(move.emptyCells).toBe(1);
    expect(() =>
      reduceCentroids(
        grid,
        Int32Array.from({ length: 40 }, () => 3),
        sites,
        null,
      ),
    ).toThrow(/label 3/);
  });

  it('computes the CVT energy as Σ w·d²·texel area, and Lloyd does not increase it', () => {
    const g = grids[2];
    let sites = randomSites(g, 12, 21);
    const weight = new Float32Array(g.width * g.height).map((_, k) => 1 + (k % 5));
    let previous = Infinity;
    for (let iteration = 0; iteration < 6; iteration++) {
      const l = bruteForceLabels(g, sites);
      const sums = reduceCentroids(g, l, sites, weight);
      let naive = 0;
      for (let j = 0; j < g.height; j++) {
        for (let i = 0; i < g.width; i++) {
          const id = l[j * g.width + i];
          naive += weight[j * g.width + i] * distanceSquared(g, i + 0.5, j + 0.5, sites[2 * id], sites[2 * id + 1]);
        }
      }
      const energy = cvtEnergy(g, sums);
      expect(energy).toBeCloseTo(naive * g.texelX * g.texelY, 6);
      expect(energy).toBeLessThanOrEqual(previous * (1 + 1e-9));
      previous = energy;
      sites = centroidSites(g, sites, sums).sites;
    }
  });

  it('moveSitesToCentroids moves every site as the definition does (the oracle centroidSites)', () => {
    let seed = 40;
    for (const g of grids) {
      for (const omega of [1, 1.7]) {
        const sites = randomSites(g, 30, seed++);
        const l = bruteForceLabels(g, sites);
        l[0] = -1;
        const sums = reduceCentroids(g, l, sites, null);
        sums.fill(0, 4 * 7, 4 * 8); // site 7: an empty cell, stays put
        const expected = centroidSites(g, sites, sums, omega);
        const moved = sites.slice();
        const move = moveSitesToCentroids(g, moved, sums, 30, omega, { energy: 0, maxDisplacement: 0, maxDisplacementTexels: 0, emptyCells: 0 });
        for (let k = 0; k < moved.length; k++) expect(moved[k]).toBeCloseTo(expected.sites[k], 4);
        expect([moved[14], moved[15]]).toEqual([sites[14], sites[15]]);
        expect(move.emptyCells).toBe(expected.move.emptyCells);
        expect(move.energy).toBeCloseTo(expected.move.energy, 6);
        expect(move.maxDisplacement).toBeCloseTo(expected.move.maxDisplacement, 4);
        expect(move.maxDisplacementTexels).toBeCloseTo(expected.move.maxDisplacementTexels, 4);
      }
    }
  });

  it('sums band by band, over runs of equal labels, exactly as texel by texel', () => {
    // Labels with holes (-1) and cells broken into several runs per row, on every grid kind;
    // sites with stride 4 (the engine's site texture), bands of 5 rows.
    let seed = 40;
    for (const g of grids) {
      const count = 6;
      const random = new Random(seed++);
      const labels = Int32Array.from({ length: g.width * g.height }, () => Math.floor(random.next() * (count + 1)) - 1);
      for (let k = 0; k < labels.length; k += 3) labels[k + 1] = labels[k]; // runs of 2 and more
      const sites2 = randomSites(g, count, seed++);
      const sites4 = new Float32Array(4 * count);
      for (let i = 0; i < count; i++) [sites4[4 * i], sites4[4 * i + 1]] = [sites2[2 * i], sites2[2 * i + 1]];
      const weight = Float32Array.from({ length: labels.length }, () => 0.5 + random.next());
      const banded = new Float64Array(4 * count);
      for (let y0 = 0; y0 < g.height; y0 += 5) {
        const rows = Math.min(5, g.height - y0);
        accumulateCentroidRows(g, labels.subarray(y0 * g.width, (y0 + rows) * g.width), y0, rows, sites4, count, weight, banded);
      }
      // The oracle sums texel by texel from the definition (tests/oracles/labels.ts).
      const direct = reduceCentroids(g, labels, sites2, weight);
      for (let k = 0; k < 4 * count; k++) expect(banded[k]).toBeCloseTo(direct[k], 9);
    }
  });
});

/** Σ over all texel edges with different labels on both sides (the definition, directly). */
function totalBoundary(grid: Grid, labels: Int32Array): number {
  let total = 0;
  const { width: w, height: h } = grid;
  for (let j = 0; j < h; j++) {
    for (let i = 0; i < w; i++) {
      const a = labels[j * w + i];
      const inside = (x: number, y: number) => x >= 0 && x < w && y >= 0 && y < h;
      const right = grid.periodicX ? [(i + 1) % w, j] : [i + 1, j];
      const up = grid.periodicY ? [i, (j + 1) % h] : [i, j + 1];
      if (inside(right[0], right[1]) && !(w === 1 && grid.periodicX)) {
        const b = labels[right[1] * w + right[0]];
        if (a >= 0 && b >= 0 && a !== b) total += grid.texelY;
      }
      if (inside(up[0], up[1]) && !(h === 1 && grid.periodicY)) {
        const b = labels[up[1] * w + up[0]];
        if (a >= 0 && b >= 0 && a !== b) total += grid.texelX;
      }
    }
  }
  return total;
}

/** The label adjacency with both contact lengths (the true ones and the staircase) and texels per cell. */
function bothLengths(grid: Grid, labels: ArrayLike<number>, count: number) {
  const adjacency = labelAdjacency(grid, labels, count);
  const staircase = labelAdjacency(grid, labels, count, 'staircase');
  expect(staircase.neighbours).toEqual(adjacency.neighbours);
  const texels = Array.from(adjacency.areas, (a) => Math.round(a / (grid.texelX * grid.texelY)));
  return { ...adjacency, staircaseLengths: staircase.lengths, texels };
}
type Both = ReturnType<typeof bothLengths>;

/** The staircase (plain sum of texel edges) between cells a and b. */
function staircase(adjacency: Both, a: number, b: number): number {
  return sharedLength({ ...adjacency, lengths: adjacency.staircaseLengths }, a, b);
}

function checkStructure(adjacency: Both, count: number) {
  expect(adjacency.offsets.length).toBe(count + 1);
  expect(adjacency.offsets[0]).toBe(0);
  for (let c = 0; c < count; c++) {
    for (let k = adjacency.offsets[c]; k < adjacency.offsets[c + 1]; k++) {
      const n = adjacency.neighbours[k];
      expect(n).not.toBe(c);
      if (k > adjacency.offsets[c]) expect(n).toBeGreaterThan(adjacency.neighbours[k - 1]);
      expect(adjacency.lengths[k]).toBeGreaterThan(0);
      expect(sharedLength(adjacency, n, c)).toBe(adjacency.lengths[k]);
      expect(staircase(adjacency, n, c)).toBe(adjacency.staircaseLengths[k]);
      // Unbiased length of a boundary of h horizontal and v vertical edges: between the
      // longer of h, v (never shorter than 1/sqrt(2) of the staircase) and the staircase.
      expect(adjacency.lengths[k]).toBeLessThanOrEqual(adjacency.staircaseLengths[k]);
      expect(adjacency.lengths[k]).toBeGreaterThanOrEqual(adjacency.staircaseLengths[k] / Math.SQRT2 - 1e-12);
    }
  }
}

describe('labelAdjacency', () => {
  it('is symmetric, sums to the total boundary and the domain area, on random Voronoi labels', () => {
    let seed = 100;
    for (const grid of grids) {
      for (const count of [2, 9, 60]) {
        const labels = bruteForceLabels(grid, randomSites(grid, count, seed++));
        const adjacency = bothLengths(grid, labels, count);
        checkStructure(adjacency, count);
        const sum = adjacency.staircaseLengths.reduce((a, b) => a + b, 0);
        expect(sum).toBeCloseTo(2 * totalBoundary(grid, labels), 6);
        const area = adjacency.areas.reduce((a, b) => a + b, 0);
        expect(area).toBeCloseTo(grid.width * grid.texelX * grid.height * grid.texelY, 6);
        expect(adjacency.texels.reduce((a, b) => a + b, 0)).toBe(grid.width * grid.height);
      }
    }
  });

  it('measures hand-built boundaries and border sides on a tube', () => {
    // Tube 4 x 3 (x periodic), texels 2 x 5 µm; rows labelled 0, 1, 2 from the y = 0 end.
    const tube: Grid = { width: 4, height: 3, texelX: 2, texelY: 5, periodicX: true, periodicY: false };
    const labels = Int32Array.from([0, 0, 0, 0, 1, 1, 1, 1, 2, 2, 2, 2]);
    const adjacency = bothLengths(tube, labels, 3);
    checkStructure(adjacency, 3);
    expect(sharedLength(adjacency, 0, 1)).toBe(8); // 4 texel edges of texelX = 2 µm
    expect(sharedLength(adjacency, 1, 2)).toBe(8);
    expect(sharedLength(adjacency, 0, 2)).toBe(0); // the ends of a tube do not meet
    expect(Array.from(adjacency.areas)).toEqual([40, 40, 40]);
    expect(Array.from(adjacency.border)).toEqual([BORDER_Y_START, 0, BORDER_Y_END]);
    expect(Array.from(adjacency.border, (b) => (b ? 1 : 0))).toEqual([1, 0, 1]);
    // Made periodic in y too (a torus), rows 0 and 2 meet across the seam.
    const torus = labelAdjacency({ ...tube, periodicY: true }, labels, 3);
    expect(sharedLength(torus, 0, 2)).toBe(8);
    expect(Array.from(torus.border)).toEqual([0, 0, 0]);
  });

  it('counts both shared edges of two columns on a periodic strip, and open-plane borders', () => {
    const strip: Grid = { width: 2, height: 3, texelX: 1, texelY: 4, periodicX: true, periodicY: false };
    const columns = Int32Array.from([0, 1, 0, 1, 0, 1]);
    expect(sharedLength(labelAdjacency(strip, columns, 2), 0, 1)).toBe(2 * 3 * 4);

    // Open 4 x 3 plane:    row 2: 2 2 3 3
    //                      row 1: 0 2 3 1
    //                      row 0: 0 0 1 1      (cell 4 owns nothing)
    const plane: Grid = { width: 4, height: 3, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const labels = Int32Array.from([0, 0, 1, 1, 0, 2, 3, 1, 2, 2, 3, 3]);
    const adjacency = bothLengths(plane, labels, 5);
    checkStructure(adjacency, 5);
    expect(Array.from(adjacency.border)).toEqual([
      BORDER_X_START | BORDER_Y_START,
      BORDER_X_END | BORDER_Y_START,
      BORDER_X_START | BORDER_Y_END,
      BORDER_X_END | BORDER_Y_END,
      0,
    ]);
    expect(Array.from(adjacency.border, (b) => (b ? 1 : 0))).toEqual([1, 1, 1, 1, 0]);
    expect(sharedLength(adjacency, 0, 1)).toBe(1);
    // (0,1)|(1,1) vertical; (1,0)-(1,1), (0,1)-(0,2) horizontal: a staircase of 3 edges, a
    // diagonal boundary of length sqrt(2² + 1²).
    expect(staircase(adjacency, 0, 2)).toBe(3);
    expect(sharedLength(adjacency, 0, 2)).toBe(Math.sqrt(5));
    expect(sharedLength(adjacency, 2, 3)).toBe(2);
    expect(staircase(adjacency, 1, 3)).toBe(3); // (2,0)-(2,1), (3,1)|(2,1), (3,1)-(3,2)
    expect(sharedLength(adjacency, 1, 3)).toBe(Math.sqrt(5));
    expect(sharedLength(adjacency, 1, 2)).toBe(0); // diagonal only
    expect(sharedLength(adjacency, 0, 3)).toBe(0);
    expect(adjacency.texels).toEqual([3, 3, 3, 3, 0]);
    expect(adjacency.offsets[5] - adjacency.offsets[4]).toBe(0);
  });

  it('ignores unlabelled texels and rejects labels out of range', () => {
    const plane: Grid = { width: 3, height: 1, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const adjacency = labelAdjacency(plane, Int32Array.from([0, -1, 1]), 2);
    expect(adjacency.neighbours.length).toBe(0);
    expect(() => labelAdjacency(plane, Int32Array.from([0, 2, 1]), 2)).toThrow(/label 2/);
  });
});
