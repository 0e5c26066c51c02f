import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import {
  analyzeTubeModel,
  layerRatios,
  neighbourExchange,
  projectTubeSites,
  tubeSurfaceGrid,
  tubeSurfaceVoronoi,
} from '../../src/core/analysis';
import { randomSites } from './helpers';

const tube = (width: number, height: number): Grid => ({ width, height, texelX: 1, texelY: 1, periodicX: true, periodicY: false });

describe('tube model geometry', () => {
  it('scales the circumference and the sites by s, keeps the axis', () => {
    const g = tubeSurfaceGrid(tube(512, 4096), 1.5);
    expect(g.width).toBeCloseTo(768);
    expect(g.height).toBe(4096);
    expect(g.texelX).toBe(1);
    expect(Array.from(projectTubeSites([10, 20, 30, 40], 2))).toEqual([20, 20, 60, 40]);
    expect(() => tubeSurfaceGrid(tube(8, 8), 0)).toThrow();
  });

  it('steps layer ratios linearly from 1 to s', () => {
    expect(layerRatios(2)).toEqual([1, 2]);
    const r = layerRatios(3, 3);
    expect(r.length).toBe(5);
    [1, 1.5, 2, 2.5, 3].forEach((x, k) => expect(r[k]).toBeCloseTo(x));
  });

  it('the outer surface has s times the area of the seeded one', () => {
    const g = tube(128, 256);
    const sites = randomSites(g, 40, 9, 3);
    const a1 = tubeSurfaceVoronoi(g, sites, 1).areas.reduce((a, b) => a + b, 0);
    const a3 = tubeSurfaceVoronoi(g, sites, 3).areas.reduce((a, b) => a + b, 0);
    expect(a1).toBeCloseTo(128 * 256, 4);
    expect(a3).toBeCloseTo(3 * 128 * 256, 4);
  });
});

describe('tube model: a hand-built neighbour exchange', () => {
  // A rhombus of four sites around (50, 50) on a tube 100 around: A, B = (50, 50 -/+ d) and
  // C, D = (50 -/+ e, 50); E = (0, 50) on the seam keeps C and D from touching around the back.
  // On the surface at ratio s the rhombus has diagonals |AB| = 2d and |CD| = 2es: the four sites
  // are cocircular when 2d = 2es, so the shared edge flips from C-D to A-B at s* = d / e.
  const g = tube(100, 100);
  for (const [d, e] of [[12, 10], [13, 10], [11, 8]]) {
    const sStar = d / e;
    const sites = new Float32Array([50, 50 - d, 50, 50 + d, 50 - e, 50, 50 + e, 50, 0, 50]);
    const seeded = tubeSurfaceVoronoi(g, sites, 1).adjacency;
    const exchanges = (s: number) => {
      const other = tubeSurfaceVoronoi(g, sites, s).adjacency;
      return [0, 1, 2, 3, 4].map((i) => neighbourExchange(seeded, other, i));
    };
    it(`d=${d}, e=${e}: no exchange just below s* = ${sStar.toFixed(4)}`, () => {
      for (const x of exchanges(sStar * (1 - 1e-4))) expect(x).toEqual({ won: [], lost: [] });
      const r = analyzeTubeModel(g, sites, { ratios: [sStar * (1 - 1e-4)] })[0].analysis;
      expect(Array.from(r.cells.changed)).toEqual([0, 0, 0, 0, 0]);
      expect(r.summary.percentScutoids).toBe(0);
    });
    it(`d=${d}, e=${e}: A and B win each other, C and D lose each other just above s*`, () => {
      expect(exchanges(sStar * (1 + 1e-4))).toEqual([
        { won: [1], lost: [] },
        { won: [0], lost: [] },
        { won: [], lost: [3] },
        { won: [], lost: [2] },
        { won: [], lost: [] },
      ]);
      const r = analyzeTubeModel(g, sites, { ratios: [sStar * (1 + 1e-4)] })[0].analysis;
      expect(Array.from(r.cells.transitions)).toEqual([1, 1, 1, 1, 0]);
      // A, B (nearest to the ends along x = 50s) and E touch the open ends; C and D are the
      // valid cells, and both are scutoids
      expect(Array.from(r.cells.valid)).toEqual([0, 0, 1, 1, 0]);
      expect(r.summary.percentScutoids).toBe(100);
    });
  }
});

describe('tube model: random sites (Voronoi 1)', () => {
  const g = tube(512, 4096);
  it('the seeded surface against itself (s = 1) has no scutoids', () => {
    const r = analyzeTubeModel(g, randomSites(g, 200, 1, 5), { ratios: [1], layers: 2 })[0];
    expect(r.analysis.summary.percentScutoids).toBe(0);
    expect(r.analysis.summary.meanTransitions).toBe(0);
  });

  it('% scutoids rises with s from 1 to 2 to 4 (10 realizations, 200 sites, 512 x 4096)', () => {
    const ratios = [1, 2, 4];
    const sums = [0, 0, 0];
    const transitions = [0, 0, 0];
    for (let r = 0; r < 10; r++) {
      const res = analyzeTubeModel(g, randomSites(g, 200, 100 + r, 5), { ratios });
      res.forEach((x, k) => {
        sums[k] += x.analysis.summary.percentScutoids / 10;
        transitions[k] += x.analysis.summary.meanTransitions / 10;
        // only the ends are excluded: a handful of cells around each end
        expect(x.analysis.summary.excludedCells).toBeGreaterThan(4);
        expect(x.analysis.summary.excludedCells).toBeLessThan(40);
      });
    }
    expect(sums[0]).toBe(0);
    expect(sums[1]).toBeGreaterThan(sums[0]);
    expect(sums[2]).toBeGreaterThan(sums[1]);
    expect(transitions[2]).toBeGreaterThan(transitions[1]);
  });

  it('layer-to-layer transitions are at least won + lost; 3D neighbours at least the sides on every surface', () => {
    const res = analyzeTubeModel(g, randomSites(g, 200, 7, 5), { ratios: [3], layers: 4 })[0];
    expect(res.stack.length).toBe(6);
    const c = res.analysis.cells;
    let strictly = 0;
    for (let i = 0; i < 200; i++) {
      expect(c.transitions[i]).toBeGreaterThanOrEqual(c.won[i] + c.lost[i]);
      if (c.transitions[i] > c.won[i] + c.lost[i]) strictly++;
      for (const sides of c.sides) expect(c.neighbours3D[i]).toBeGreaterThanOrEqual(sides[i]);
    }
    expect(strictly).toBeGreaterThan(0);
    const plain = analyzeTubeModel(g, randomSites(g, 200, 7, 5), { ratios: [3] })[0].analysis.summary;
    expect(res.analysis.summary.meanTransitions).toBeGreaterThan(plain.meanTransitions);
  });
});
