import { describe, expect, it } from 'vitest';
import { compareWithModel, l1Distance, measureTissue } from '../../src/core/measure';
import { exactVoronoi } from '../../src/core/exact';
import type { Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { memoryFile, png16, rasterizeVoronoi } from './images';

const W = 300;
const H = 400;
const n = 150;
const grid: Grid = { width: W, height: H, texelX: 1, texelY: 1, periodicX: true, periodicY: false };

/** A measured tissue rasterized from "Voronoi k" sites, its apical side twice as wide. */
function measuredFromModel(k: number) {
  let s = Float64Array.from(placeSites(grid, n, 5, 1.5));
  for (let i = 1; i < k; i++) s = Float64Array.from(exactVoronoi(grid, s).centroids);
  const sites = Array.from({ length: n }, (_, i) => [s[2 * i], s[2 * i + 1]]);
  const labels = sites.map((_, i) => i + 1);
  const basal = rasterizeVoronoi(W, H, sites, labels, true);
  const apical = rasterizeVoronoi(
    2 * W,
    H,
    sites.map(([x, y]) => [2 * x, y]),
    labels,
    true,
  );
  return measureTissue([memoryFile('basal.png', png16(basal)), memoryFile('apical.png', png16(apical))], { pixelSize: 1, periodicX: true, version: 'test' });
}

function compare(measured: ReturnType<typeof measuredFromModel>, surfaceRatio = measured.surfaceRatio.value) {
  return compareWithModel({
    width: W,
    height: H,
    pixelSize: 1,
    periodicX: true,
    cells: measured.inputs.layers[0].labels,
    distribution: measured.analyses[0].summary.perSurface[0].polygonDistribution,
    layers: 2,
    surfaceRatio,
    realizations: 6,
    seed: 100,
  });
}

describe('compareWithModel', () => {
  it('L1 distance: 0 for equal distributions, 2 for disjoint ones', () => {
    expect(l1Distance([0.2, 0.3, 0.5], [0.2, 0.3, 0.5])).toBe(0);
    expect(l1Distance([1, 0, 0], [0, 0, 1])).toBe(2);
  });

  it('finds Voronoi 1 for a tissue made of random sites, and a Lloyd-relaxed k for a relaxed one', () => {
    const random = compare(measuredFromModel(1));
    expect(random.bestK).toBe(1);
    expect(random.candidates).toHaveLength(10);
    const relaxed = compare(measuredFromModel(10));
    expect(relaxed.bestK).toBeGreaterThanOrEqual(5);
    // The best candidate has the smallest distance, by definition.
    for (const c of relaxed.candidates) expect(c.distance).toBeGreaterThanOrEqual(relaxed.candidates[relaxed.bestK - 1].distance);
  }, 60_000);

  it('reads the surface ratio from the widths, and the model at ratio 1 has no scutoid', () => {
    const measured = measuredFromModel(4);
    expect(measured.surfaceRatio).toEqual({ value: 2, source: 'widths' });
    const flat = compare(measured, 1);
    expect(flat.percentScutoids).toEqual(new Array(6).fill(0));
    const curved = compare(measured, 2);
    expect(curved.meanPercentScutoids).toBeGreaterThan(0);
    expect(curved.percentScutoids).toHaveLength(6);
    expect(curved.summary.surfaces).toBe(2);
  }, 60_000);
});
