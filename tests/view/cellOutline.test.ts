import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { mulberry32 } from '../../src/core/mesh/generate';
import { exactVoronoi } from '../../src/core/exact';
import { candidateIds, cellOutline, exactCell, type OutlineCells } from '../../src/view/cellOutline';

/** Random sites (µm) on `grid`, every site a "neighbour" of every other (brute force). */
function allSites(grid: Grid, n: number, seed: number): { sites: [number, number][]; cells: (neighbours: (id: number) => number[]) => OutlineCells } {
  const random = mulberry32(seed);
  const sites = Array.from({ length: n }, () => [grid.width * grid.texelX * random(), grid.height * grid.texelY * random()] as [number, number]);
  return { sites, cells: (neighbours) => ({ length: n, site: (id) => sites[id], neighbours }) };
}

/** Squared periodic distance (µm) between two points of the grid. */
function distance2(grid: Grid, a: readonly number[], b: readonly number[]): number {
  const w = grid.width * grid.texelX;
  const h = grid.height * grid.texelY;
  let dx = Math.abs(a[0] - b[0]);
  let dy = Math.abs(a[1] - b[1]);
  if (grid.periodicX) dx = Math.min(dx, w - dx);
  if (grid.periodicY) dy = Math.min(dy, h - dy);
  return dx * dx + dy * dy;
}

/** Whether texel point (x, y) lies in convex CCW `polygon` (texel units), any periodic copy. */
function inside(grid: Grid, polygon: Float64Array, x: number, y: number): boolean {
  for (const shift of grid.periodicX ? [-grid.width, 0, grid.width] : [0]) {
    let ok = true;
    for (let k = 0; k < polygon.length && ok; k += 2) {
      const ax = polygon[k];
      const ay = polygon[k + 1];
      const bx = polygon[(k + 2) % polygon.length];
      const by = polygon[(k + 3) % polygon.length];
      ok = (bx - ax) * (y - ay) - (by - ay) * (x + shift - ax) >= -1e-9;
    }
    if (ok) return true;
  }
  return false;
}

const GRIDS: [string, Grid][] = [
  ['a tube (periodic around, anisotropic texels)', { width: 96, height: 160, texelX: 1.7, texelY: 2.5, periodicX: true, periodicY: false }],
  ['a plane', { width: 120, height: 80, texelX: 1, texelY: 1, periodicX: false, periodicY: false }],
];

describe('cellOutline (the picked cell drawn alone)', () => {
  for (const [name, grid] of GRIDS) {
    it(`${name}: a point is inside the outline exactly when its nearest site is the cell's (brute force)`, () => {
      const n = 60;
      const { sites, cells } = allSites(grid, n, 7);
      const everyone = cells((id) => Array.from({ length: n }, (_, k) => k).filter((k) => k !== id));
      const random = mulberry32(99);
      for (const id of [0, 17, 42]) {
        const polygon = cellOutline(grid, everyone, id);
        expect(polygon.length).toBeGreaterThanOrEqual(6);
        let checked = 0;
        for (let t = 0; t < 4000; t++) {
          const x = grid.width * random();
          const y = grid.height * random();
          const point = [x * grid.texelX, y * grid.texelY];
          const d = sites.map((s) => distance2(grid, point, s));
          const mine = d[id];
          const others = Math.min(...d.filter((_, k) => k !== id));
          // Points within rounding of an edge may go either way.
          if (Math.abs(Math.sqrt(mine) - Math.sqrt(others)) < 1e-6) continue;
          expect(inside(grid, polygon, x, y)).toBe(mine < others);
          checked++;
        }
        expect(checked).toBeGreaterThan(3900);
      }
    });

    it(`${name}: two rings of true neighbours give the same outline as every site`, () => {
      const n = 80;
      const { sites, cells } = allSites(grid, n, 3);
      const everyone = cells((id) => Array.from({ length: n }, (_, k) => k).filter((k) => k !== id));
      // Delaunay neighbours by brute force: k borders id when the outline of id has an edge on their bisector.
      const outlines = Array.from({ length: n }, (_, id) => cellOutline(grid, everyone, id));
      const touches = (a: number, b: number) => {
        const pa = outlines[a];
        for (let k = 0; k < pa.length; k += 2) {
          const v = [pa[k] * grid.texelX, pa[k + 1] * grid.texelY];
          if (Math.abs(Math.sqrt(distance2(grid, v, sites[a])) - Math.sqrt(distance2(grid, v, sites[b]))) < 1e-6) return true;
        }
        return false;
      };
      const neighbours = Array.from({ length: n }, (_, a) => Array.from({ length: n }, (_, b) => b).filter((b) => b !== a && touches(a, b)));
      const ringed = cells((id) => neighbours[id]);
      for (let id = 0; id < n; id++) {
        expect(candidateIds(ringed, id)).not.toContain(id);
        expect(area(cellOutline(grid, ringed, id))).toBeCloseTo(area(outlines[id]), 6);
      }
    });
  }
});

describe('exactCell (a picked cell and its neighbours, alone)', () => {
  for (const [name, grid] of GRIDS) {
    it(`${name}: the neighbours and polygon of core/exact.ts's exact cells of the whole surface`, () => {
      const n = 200;
      const { sites } = allSites(grid, n, 11);
      const voronoi = exactVoronoi(
        grid,
        sites.flatMap(([x, y]) => [x / grid.texelX, y / grid.texelY]),
      );
      const cells: OutlineCells = { length: n, site: (id) => sites[id], neighbours: (id) => voronoi.cells[id].neighbours };
      for (let id = 0; id < n; id++) {
        const cell = exactCell(grid, cells, id);
        expect(cell.neighbours).toEqual(Array.from(voronoi.cells[id].neighbours));
        expect(area(cell.polygon) * grid.texelX * grid.texelY).toBeCloseTo(voronoi.cells[id].area, 6);
      }
    });
  }
});

function area(polygon: Float64Array): number {
  let sum = 0;
  for (let k = 0; k < polygon.length; k += 2) sum += polygon[k] * polygon[(k + 3) % polygon.length] - polygon[(k + 2) % polygon.length] * polygon[k + 1];
  return sum / 2;
}
