import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { BORDER_X_END as BORDER_X1, BORDER_X_START as BORDER_X0, BORDER_Y_END as BORDER_Y1, BORDER_Y_START as BORDER_Y0 } from '../../src/core/border';
import { exactVoronoi } from '../../src/core/exact';
import { bruteForceLabels, randomSites } from './helpers';

/** True when the point (texel units) lies inside the cell polygon (texel units), tried at every periodic image. */
function cellContains(grid: Grid, polygon: Float64Array, x: number, y: number): boolean {
  const shiftsX = grid.periodicX ? [0, -grid.width, grid.width] : [0];
  const shiftsY = grid.periodicY ? [0, -grid.height, grid.height] : [0];
  for (const oy of shiftsY) {
    for (const ox of shiftsX) {
      if (pointInPolygon(polygon, x + ox, y + oy)) return true;
    }
  }
  return false;
}

/** Even-odd point-in-polygon test; polygon interleaved x, y. */
function pointInPolygon(polygon: Float64Array, x: number, y: number): boolean {
  const m = polygon.length / 2;
  let inside = false;
  for (let k = 0, l = m - 1; k < m; l = k++) {
    const xk = polygon[2 * k];
    const yk = polygon[2 * k + 1];
    const xl = polygon[2 * l];
    const yl = polygon[2 * l + 1];
    if (yk > y !== yl > y && x < ((xl - xk) * (y - yk)) / (yl - yk) + xk) inside = !inside;
  }
  return inside;
}

const grid = (width: number, height: number, periodicX: boolean, periodicY: boolean, texelX = 1, texelY = 1): Grid => ({
  width,
  height,
  texelX,
  texelY,
  periodicX,
  periodicY,
});

const cases: [string, Grid][] = [
  ['plane', grid(64, 48, false, false, 0.5, 0.75)],
  ['tube', grid(64, 96, true, false, 1.5, 1)],
  ['periodic plane', grid(50, 40, true, true, 1, 2)],
];

describe('exactVoronoi', () => {
  for (const [name, g] of cases) {
    const sites = randomSites(g, 60, 11);
    const v = exactVoronoi(g, sites);

    it(`${name}: areas sum to the physical domain area`, () => {
      const total = v.adjacency.areas.reduce((a, b) => a + b, 0);
      expect(total).toBeCloseTo(g.width * g.texelX * g.height * g.texelY, 6);
      for (const a of v.adjacency.areas) expect(a).toBeGreaterThan(0);
    });

    it(`${name}: each centroid lies inside its own cell and inside the domain`, () => {
      for (const cell of v.cells) {
        expect(cellContains(g, cell.polygon, cell.centroidX, cell.centroidY)).toBe(true);
        expect(cell.centroidX).toBeGreaterThanOrEqual(0);
        expect(cell.centroidX).toBeLessThanOrEqual(g.width);
        expect(cell.centroidY).toBeGreaterThanOrEqual(0);
        expect(cell.centroidY).toBeLessThanOrEqual(g.height);
        // the site is inside its own (unwrapped) polygon
        expect(cellContains(g, cell.polygon, sites[2 * cell.id], sites[2 * cell.id + 1])).toBe(true);
      }
    });

    it(`${name}: neighbours are symmetric with equal shared lengths, never self`, () => {
      const { offsets, neighbours, lengths } = v.adjacency;
      for (let i = 0; i < v.count; i++) {
        for (let k = offsets[i]; k < offsets[i + 1]; k++) {
          const j = neighbours[k];
          expect(j).not.toBe(i);
          const back = Array.from(neighbours.subarray(offsets[j], offsets[j + 1])).indexOf(i);
          expect(back).toBeGreaterThanOrEqual(0);
          expect(lengths![offsets[j] + back]).toBeCloseTo(lengths![k], 6);
        }
        // the polygon perimeter = shared edges + domain edges (+ self contact)
        expect(v.cells[i].neighbours.length).toBe(offsets[i + 1] - offsets[i]);
      }
    });

    it(`${name}: agrees with a brute-force pixel Voronoi`, () => {
      const { labels, gap } = bruteForceLabels(g, sites);
      const counts = new Float64Array(v.count);
      let checked = 0;
      for (let j = 0; j < g.height; j++) {
        for (let i = 0; i < g.width; i++) {
          const label = labels[j * g.width + i];
          counts[label] += g.texelX * g.texelY;
          if (gap[j * g.width + i] < 1e-6) continue; // a tie: either answer is right
          expect(cellContains(g, v.cells[label].polygon, i + 0.5, j + 0.5)).toBe(true);
          checked++;
        }
      }
      expect(checked).toBeGreaterThan(0.99 * g.width * g.height);
      // pixel-count areas approximate the exact areas (boundary texels only differ)
      let err = 0;
      for (let s = 0; s < v.count; s++) err += Math.abs(counts[s] - v.adjacency.areas[s]);
      expect(err / (g.width * g.height * g.texelX * g.texelY)).toBeLessThan(0.05);
      // neighbours through a long shared edge are pixel neighbours (4-connectivity), and vice versa mostly
      const pixelPairs = new Set<string>();
      const add = (a: number, b: number) => {
        if (a !== b) pixelPairs.add(a < b ? `${a},${b}` : `${b},${a}`);
      };
      for (let j = 0; j < g.height; j++) {
        for (let i = 0; i < g.width; i++) {
          const a = labels[j * g.width + i];
          if (i + 1 < g.width || g.periodicX) add(a, labels[j * g.width + ((i + 1) % g.width)]);
          if (j + 1 < g.height || g.periodicY) add(a, labels[((j + 1) % g.height) * g.width + i]);
        }
      }
      const exactPairs = new Set<string>();
      const texel = Math.max(g.texelX, g.texelY);
      for (const cell of v.cells) {
        cell.neighbours.forEach((j, k) => {
          if (cell.id < j) {
            exactPairs.add(`${cell.id},${j}`);
            if (cell.lengths[k] > 3 * texel) expect(pixelPairs.has(`${cell.id},${j}`)).toBe(true);
          }
        });
      }
      let agree = 0;
      for (const p of pixelPairs) if (exactPairs.has(p)) agree++;
      expect(agree / pixelPairs.size).toBeGreaterThan(0.95);
    });
  }

  it('hand case: two sites on a plane split it in halves', () => {
    const g = grid(10, 10, false, false, 2, 1);
    const v = exactVoronoi(g, new Float32Array([2.5, 5, 7.5, 5]));
    expect(v.adjacency.areas[0]).toBeCloseTo(100);
    expect(v.adjacency.areas[1]).toBeCloseTo(100);
    expect(Array.from(v.cells[0].neighbours)).toEqual([1]);
    expect(v.cells[0].lengths[0]).toBeCloseTo(10); // vertical bisector x = 5, 10 texels of 1 µm
    expect(v.cells[0].border).toBe(BORDER_Y0 | BORDER_Y1 | BORDER_X0);
    expect(v.cells[1].border).toBe(BORDER_Y0 | BORDER_Y1 | BORDER_X1);
    expect(v.cells[0].centroidX).toBeCloseTo(2.5);
    expect(v.cells[0].centroidY).toBeCloseTo(5);
  });

  it('hand case: anisotropic texels move the bisector (physical metric)', () => {
    // texelX = 2 µm: sites (1, 0.5) and (0.5... ) -> check on a diagonal pair
    const g = grid(10, 10, false, false, 2, 1);
    // sites at texel (2, 2) and (4, 6): physical (4, 2) and (8, 6); bisector: x + y = 10 (µm)
    const v = exactVoronoi(g, new Float32Array([2, 2, 4, 6]));
    // cell 0 is {x_um + y_um < 10} within [0,20]x[0,10]: triangle area 50 µm²
    expect(v.adjacency.areas[0]).toBeCloseTo(50);
    expect(v.adjacency.areas[1]).toBeCloseTo(150);
    expect(v.cells[0].lengths[0]).toBeCloseTo(10 * Math.SQRT2);
  });

  it('hand case: tube cells wrap across the seam and only open ends are borders', () => {
    const g = grid(20, 10, true, false);
    const v = exactVoronoi(g, new Float32Array([1, 5, 11, 5]));
    // bisectors at x = 6 and x = 16 (= -4): both cells 10 wide, two shared edges each 10 long
    expect(v.adjacency.areas[0]).toBeCloseTo(100);
    expect(Array.from(v.cells[0].neighbours)).toEqual([1]);
    expect(v.cells[0].lengths[0]).toBeCloseTo(20);
    expect(v.cells[0].edgeCount).toBe(2);
    expect(v.cells[0].border).toBe(BORDER_Y0 | BORDER_Y1);
    const xs = Array.from(v.cells[0].polygon.filter((_, k) => k % 2 === 0));
    expect(Math.min(...xs)).toBeCloseTo(-4); // unwrapped around the site
    expect(Math.max(...xs)).toBeCloseTo(6);
  });

  it('a domain so small that a cell touches its own copy reports self contact, not a self neighbour', () => {
    const tube = exactVoronoi(grid(8, 10, true, false), new Float32Array([3, 4]));
    expect(tube.adjacency.areas[0]).toBeCloseTo(80);
    expect(tube.cells[0].neighbours.length).toBe(0);
    expect(tube.cells[0].selfContact).toBeCloseTo(20);
    expect(tube.cells[0].border).not.toBe(0);
    const torus = exactVoronoi(grid(8, 6, true, true), new Float32Array([3, 4, 7, 1]));
    expect(torus.adjacency.areas[0] + torus.adjacency.areas[1]).toBeCloseTo(48);
    expect(torus.adjacency.border[0]).toBe(0);
    expect(Array.from(torus.cells[0].neighbours)).toEqual([1]);
  });

  it('gives a duplicated site an empty cell and keeps the area sum', () => {
    const g = grid(10, 10, false, false);
    const v = exactVoronoi(g, new Float32Array([2, 2, 2, 2, 7, 7]));
    expect(v.adjacency.areas[0] + v.adjacency.areas[1] + v.adjacency.areas[2]).toBeCloseTo(100);
    expect(Math.min(v.adjacency.areas[0], v.adjacency.areas[1])).toBe(0);
  });
});
