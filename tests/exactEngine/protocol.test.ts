import { describe, expect, it } from 'vitest';
import type { Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { ExactLloydRun } from '../../src/core/exactEngine/exactLloyd';
import { exactSurface } from '../../src/core/exactEngine/exactSurface';
import { LAB_PROTOCOL, labelContactThresholdTexels, labLayerRatios, protocolProblem, ratioSteps, validityRatios } from '../../src/core/analysis/protocol';
import { analyzeTubeLab, labTubeTable } from '../../src/core/analysis/protocolTube';

// The lab's tube: 512 px around, 4096 along, 200 cells 5 px apart.
const labTube: Grid = { width: 512, height: 4096, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
const RATIOS = [1, 1.25, 1.5, 1.75, 2, 2.5, 3, 4, 5, 6, 8, 10];
const fast = (grid: Grid, sites: ArrayLike<number>, label: string) => exactSurface(grid, sites, label);

function voronoiK(seed: number, k: number): Float32Array {
  const sites = placeSites(labTube, 200, seed, 5);
  const run = new ExactLloydRun(labTube, sites, { maxIterations: k - 1, tolerance: 0, overRelaxation: 1 });
  while (!run.done) run.step();
  return sites;
}

describe('protocol definitions', () => {
  it('layers step by 0.25 from 1 to the apical ratio, ends included exactly once', () => {
    expect(labLayerRatios(2)).toEqual([1, 1.25, 1.5, 1.75, 2]);
    expect(labLayerRatios(1.6)).toEqual([1, 1.25, 1.5, 1.6]);
    expect(validityRatios(LAB_PROTOCOL)).toHaveLength(37);
    expect(ratioSteps(1, 1, 0.25)).toEqual([1]);
    expect(() => ratioSteps(1, 10, 0)).toThrow(/sheet\.layerStep/);
    expect(() => ratioSteps(1, 10, 1e-6)).toThrow(/sheet\.layerStep/);
  });

  it('refuses the lab protocol where it does not apply, naming the field', () => {
    expect(protocolProblem('default', 'plane', null)).toBeNull();
    expect(protocolProblem('lab', 'tube', 3)).toBeNull();
    for (const problem of [protocolProblem('lab', 'plane', null), protocolProblem('lab', 'sphere', null), protocolProblem('lab', 'tube', null)]) {
      expect(problem).toMatch(/^sheet\.protocol: /);
      expect(problem!.split('\n')).toHaveLength(1);
    }
  });

  it('the pixel contact rule scales with the grid around the tube', () => {
    expect(labelContactThresholdTexels(labTube)).toBe(6);
    expect(labelContactThresholdTexels({ ...labTube, width: 256 })).toBe(3);
  });
});

describe('lab protocol on the published tube', () => {
  it('0 % at s = 1, % non-decreasing in s, the same valid set at every ratio', () => {
    for (const seed of [1, 2, 3]) {
      const sites = voronoiK(seed, 1);
      const rows = labTubeTable(labTube, sites, RATIOS, LAB_PROTOCOL, fast);
      expect(rows[0].percentScutoids).toBe(0);
      expect(rows[0].meanTransitions).toBe(0);
      for (let k = 1; k < rows.length; k++) {
        expect(rows[k].percentScutoids).toBeGreaterThanOrEqual(rows[k - 1].percentScutoids);
        expect(rows[k].meanNeighbours3D).toBeGreaterThanOrEqual(rows[k - 1].meanNeighbours3D);
        expect(rows[k].validCells).toBe(rows[0].validCells);
      }
      expect(rows.at(-1)!.percentScutoids).toBeGreaterThan(50);
      // Per-ratio analyses with the reference adjacency (exactVoronoi): identical valid sets and numbers.
      const masks = [1, 1.5, 4, 10].map((s) => analyzeTubeLab(labTube, sites, s));
      for (const m of masks) expect(Array.from(m.invalid)).toEqual(Array.from(masks[0].invalid));
      for (const m of masks) {
        const row = rows[RATIOS.indexOf(m.ratio)];
        expect(m.analysis.summary.validCells).toBe(row.validCells);
        expect(m.analysis.summary.percentScutoids).toBeCloseTo(row.percentScutoids, 9);
        expect(m.analysis.summary.meanTransitions).toBeCloseTo(row.meanTransitions, 9);
        expect(m.analysis.summary.meanNeighbours3D).toBeCloseTo(row.meanNeighbours3D, 9);
      }
      // The lab's valid set is never larger than the per-run one of the two end surfaces.
      expect(masks[0].analysis.summary.excludedCells).toBeGreaterThan(0);
    }
  });

  it('more Lloyd iterations give fewer scutoids at s <= 1.75 (20 realizations)', () => {
    const low = [1.25, 1.5, 1.75];
    const mean = (k: number) => {
      const totals = low.map(() => 0);
      for (let seed = 1; seed <= 20; seed++) {
        const rows = labTubeTable(labTube, voronoiK(seed, k), low, LAB_PROTOCOL, fast);
        rows.forEach((r, t) => (totals[t] += r.percentScutoids / 20));
      }
      return totals;
    };
    const v1 = mean(1);
    const v5 = mean(5);
    for (let t = 0; t < low.length; t++) expect(v5[t]).toBeLessThan(v1[t]);
  });
});
