import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { exactVoronoi } from '../../src/core/exact';
import {
  adjacencyFromLists,
  analyzeSurfaces,
  labMinBoundaryLength,
  neighbourSet,
  SIDE_CLASSES,
  sideClassIndex,
  withMinBoundaryLength,
  type SurfaceAdjacency,
} from '../../src/core/analysis';
import { BORDER_Y_START } from '../../src/core/border';
import { isSymmetric } from '../oracles/adjacency';
import { randomSites } from './helpers';

/** Symmetric adjacency lists from an edge list. */
function fromEdges(count: number, edges: [number, number][]): number[][] {
  const lists: number[][] = Array.from({ length: count }, () => []);
  for (const [a, b] of edges) {
    lists[a].push(b);
    lists[b].push(a);
  }
  return lists;
}

// Hand-built stack of 6 cells: S0 (seeded), S1 (one layer), S2 (other surface).
const base: [number, number][] = [
  [0, 1],
  [0, 2],
  [0, 3],
  [1, 2],
  [2, 3],
  [2, 4],
  [3, 5],
  [4, 5],
];
const areas = Float64Array.from([1, 2, 3, 4, 5, 6]);
const surf = (edges: [number, number][], border: number[], label: string): SurfaceAdjacency => {
  const lists = fromEdges(6, edges);
  const lengths = lists.map((list) => list.map(() => 1));
  return adjacencyFromLists(lists, lengths, areas, Uint8Array.from([0, 1, 2, 3, 4, 5].map((i) => (border.includes(i) ? BORDER_Y_START : 0))), label);
};
const S0 = surf(base, [1], 'first'); // cell 1 touches an open end here only
const S1 = surf([...base, [0, 4]], [], 'layer'); // 0-4 appear in the layer only
const S2 = surf([...base, [0, 5]], [5], 'last'); // 0-5 appear on the last surface; 5 touches an end here only

describe('scutoid statistics on a hand-written adjacency', () => {
  it('excludes cells touching an open end on any surface, but keeps them as neighbours', () => {
    const { cells, summary } = analyzeSurfaces([S0, S1, S2]);
    expect(Array.from(cells.valid)).toEqual([1, 0, 1, 1, 1, 0]);
    expect(summary.validCells).toBe(4);
    expect(summary.excludedCells).toBe(2);
    // cell 0 wins the border cell 5
    expect(cells.won[0]).toBe(1);
    expect(cells.lost[0]).toBe(0);
  });

  it('counts transitions layer to layer, 3D neighbours as the union', () => {
    const { cells, summary } = analyzeSurfaces([S0, S1, S2]);
    // cell 0: {1,2,3} -> {1,2,3,4} -> {1,2,3,5}: 1 + 2 transitions; union {1,2,3,4,5}
    expect(cells.transitions[0]).toBe(3);
    expect(cells.neighbours3D[0]).toBe(5);
    // cell 4: {2,5} -> {0,2,5} -> {2,5}: same at both ends, 2 transitions through the layer
    expect(cells.won[4]).toBe(0);
    expect(cells.lost[4]).toBe(0);
    expect(cells.transitions[4]).toBe(2);
    expect(cells.neighbours3D[4]).toBe(3);
    expect(cells.scutoid[4]).toBe(1);
    // unchanged cells
    expect(cells.transitions[2]).toBe(0);
    expect(cells.transitions[3]).toBe(0);
    expect(cells.neighbours3D[2]).toBe(4);
    expect(cells.neighbours3D[3]).toBe(3);
    // border cell 5 changed but is no scutoid
    expect(cells.changed[5]).toBe(1);
    expect(cells.scutoid[5]).toBe(0);
    expect(summary.scutoids).toBe(2);
    expect(summary.percentScutoids).toBeCloseTo(50);
    expect(summary.percentScutoidsEnds).toBeCloseTo(25);
    expect(summary.meanTransitions).toBeCloseTo((3 + 0 + 0 + 2) / 4);
    expect(summary.meanWon).toBeCloseTo(0.25);
    expect(summary.meanLost).toBe(0);
    expect(summary.meanNeighbours3D).toBeCloseTo((5 + 4 + 3 + 3) / 4);
  });

  it('first-vs-last counting without the layer differs', () => {
    const { cells, summary } = analyzeSurfaces([S0, S2]);
    expect(cells.transitions[0]).toBe(1);
    expect(cells.transitions[4]).toBe(0);
    expect(cells.neighbours3D[0]).toBe(4);
    expect(summary.percentScutoids).toBeCloseTo(25);
    expect(summary.percentScutoidsEnds).toBeCloseTo(25);
    expect(summary.meanTransitions).toBeCloseTo(0.25);
  });

  it('computes the polygon distribution, Lewis and Aboav-Weaire on each surface', () => {
    const s0 = analyzeSurfaces([S0, S2]).summary.perSurface[0];
    // valid cells 0, 2, 3, 4 have 3, 4, 3, 2 sides on S0
    expect(s0.below3).toBe(1);
    expect(s0.polygonCounts).toEqual([2, 1, 0, 0, 0, 0, 0, 0]);
    expect(s0.polygonDistribution[0]).toBeCloseTo(0.5);
    expect(s0.polygonDistribution[1]).toBeCloseTo(0.25);
    expect(s0.meanSides).toBeCloseTo(3);
    expect(s0.meanArea).toBeCloseTo(3.25);
    expect(s0.lewis[0].count).toBe(2);
    expect(s0.lewis[0].meanArea).toBeCloseTo(2.5);
    expect(s0.lewis[0].normalizedArea).toBeCloseTo(2.5 / 3.25);
    expect(s0.lewis[1].normalizedArea).toBeCloseTo(3 / 3.25);
    expect(Number.isNaN(s0.lewis[2].meanArea)).toBe(true);
    // Aboav: cell 0's neighbours 1,2,3 have 2,4,3 sides; cell 3's 0,2,5 have 3,4,2 -> m(3) = 3
    expect(s0.aboavWeaire[0].meanNeighbourSides).toBeCloseTo(3);
    expect(s0.aboavWeaire[1].meanNeighbourSides).toBeCloseTo((3 + 2 + 3 + 2) / 4);
    const valid = analyzeSurfaces([S0, S2], { aboavNeighbours: 'valid' }).summary.perSurface[0];
    expect(valid.aboavWeaire[0].meanNeighbourSides).toBeCloseTo(3.5);
    expect(valid.aboavWeaire[1].meanNeighbourSides).toBeCloseTo(8 / 3);
  });

  it('ignores self entries and duplicates in a row', () => {
    const lists = fromEdges(6, base);
    lists[0].push(0, 1); // self and duplicate
    const messy = adjacencyFromLists(
      lists,
      lists.map((list) => list.map(() => 1)),
      S0.areas,
      S0.border,
      S0.label,
    );
    expect(Array.from(neighbourSet(messy, 0))).toEqual([1, 2, 3]);
    const a = analyzeSurfaces([messy, S2]).summary;
    const b = analyzeSurfaces([S0, S2]).summary;
    expect(a).toEqual(b);
  });

  it('gives NaN means, not zeros, when every cell is excluded', () => {
    const all = surf(base, [0, 1, 2, 3, 4, 5], 'x');
    const { summary } = analyzeSurfaces([all, all]);
    expect(summary.validCells).toBe(0);
    expect(Number.isNaN(summary.percentScutoids)).toBe(true);
  });

  it('rejects surfaces of different cell counts', () => {
    expect(() => analyzeSurfaces([S0, { ...S2, count: 5 }])).toThrow();
  });

  it('maps side counts to classes 3..9 and 10+', () => {
    expect(SIDE_CLASSES[sideClassIndex(6)]).toBe('6');
    expect(SIDE_CLASSES[sideClassIndex(13)]).toBe('10+');
    expect(sideClassIndex(2)).toBe(-1);
  });
});

describe('scutoid statistics on exact diagrams', () => {
  const plane: Grid = { width: 256, height: 256, texelX: 1, texelY: 1, periodicX: false, periodicY: false };

  it('the same sites on both surfaces of a plane give no scutoids', () => {
    const v = exactVoronoi(plane, randomSites(plane, 150, 3, 4));
    const { summary, cells } = analyzeSurfaces([v.adjacency, v.adjacency]);
    expect(summary.percentScutoids).toBe(0);
    expect(summary.meanTransitions).toBe(0);
    expect(summary.validCells).toBeGreaterThan(100);
    expect(summary.validCells + summary.excludedCells).toBe(150);
    for (let i = 0; i < v.count; i++) expect(cells.neighbours3D[i]).toBe(cells.sides[0][i]);
    // a closed planar Voronoi tessellation: interior cells have on average about 6 sides
    expect(summary.perSurface[0].meanSides).toBeGreaterThan(5.5);
    expect(summary.perSurface[0].meanSides).toBeLessThan(6.5);
    const fractions = summary.perSurface[0].polygonDistribution.reduce((a, b) => a + b, 0);
    expect(fractions).toBeCloseTo(1 - summary.perSurface[0].below3 / summary.validCells);
  });

  it('filters short contacts symmetrically at the given length', () => {
    const v = exactVoronoi(plane, randomSites(plane, 150, 5, 4));
    const threshold = 6;
    const f = withMinBoundaryLength(v.adjacency, threshold);
    expect(isSymmetric(v.adjacency)).toBe(true);
    expect(isSymmetric(f)).toBe(true);
    const short = Array.from(v.adjacency.lengths).filter((l) => l < threshold).length;
    expect(short).toBeGreaterThan(0);
    expect(f.neighbours.length).toBe(v.adjacency.neighbours.length - short);
    for (const l of f.lengths) expect(l).toBeGreaterThanOrEqual(threshold);
    const { summary } = analyzeSurfaces([v.adjacency, f]);
    expect(summary.scutoids).toBeGreaterThan(0); // lost short contacts show up as exchanges
    expect(summary.meanWon).toBe(0);
  });

  it('expresses the lab threshold (6 px at 512 px around) in µm', () => {
    // The lab's tube: 512 x 4096 µm, 200 cells -> exactly 6 µm; 4x the area per cell -> 12 µm.
    expect(labMinBoundaryLength(512 * 4096, 200)).toBeCloseTo(6, 12);
    expect(labMinBoundaryLength(512 * 4096, 50)).toBeCloseTo(12, 12);
    expect(labMinBoundaryLength(1000 * 600, 300)).toBeCloseTo((6 * Math.sqrt(2000)) / Math.sqrt((512 * 4096) / 200), 12);
  });
});
