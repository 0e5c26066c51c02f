import { beforeAll, describe, expect, it } from 'vitest';
import { validateConfig, type ClosedConfig, type ConfigInput } from '../../src/core/config';
import { sphericalVoronoi } from '../oracles/sphericalDelaunay';
import { runSheet } from '../../src/run/runSheet';
import type { SheetResult } from '../../src/run/result';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();
const closed = (input: ConfigInput) => validateConfig(input) as ClosedConfig;

/** Unordered neighbour pairs "a-b" (a < b) of a result's seeded cells. */
function pairs(result: SheetResult): Set<string> {
  const out = new Set<string>();
  for (const cell of result.cells) for (const n of cell.neighbours) if (cell.id < n.id) out.add(`${cell.id}-${n.id}`);
  return out;
}

describe('concentric spheres', () => {
  it('no cell changes neighbours, whatever the thickness (labels and exact)', async () => {
    for (const [direction, thickness] of [
      ['outward', 40],
      ['inward', 25],
    ] as const) {
      const config = closed({
        surface: { kind: 'sphere', radius: 50 },
        resolution: 64,
        cells: 150,
        lloyd: { maxIterations: 5 },
        sheet: { direction, thickness, layers: 1 },
      });
      const { result } = await runSheet(config, context);
      expect(result.analyses.map((a) => a.method)).toEqual(['labels', 'exact']);
      for (const analysis of result.analyses) {
        expect(analysis.summary.validCells).toBe(150);
        expect(analysis.summary.percentScutoids).toBe(0);
        expect(analysis.summary.meanTransitions).toBe(0);
      }
      expect(result.surfaces.at(-1)!.ratio).toBeCloseTo((50 + (direction === 'outward' ? 40 : -25)) / 50, 3);
      // The documented shape: 3D positions on each surface, no border cells, plain JSON.
      const other = result.surfaces.at(-1)!;
      for (const cell of other.cells) expect(Math.hypot(...cell.position)).toBeCloseTo(50 + other.offset, 3);
      expect(result.cells.every((c) => !c.touchesBorder && c.neighbours.length >= 3)).toBe(true);
      expect(JSON.parse(JSON.stringify(result)).closed).toEqual(result.closed);
      expect(result.grid).toMatchObject({ width: 64, height: 384 });
    }
  }, 20000);
});

describe('sphere CCVT, uniform density, 1000 cells, n = 128 (~98 texels per cell)', () => {
  // One run, read (never changed) by every test below; each test checks one property of it.
  let result: SheetResult;
  beforeAll(async () => {
    const config = closed({
      surface: { kind: 'sphere', radius: 100 },
      resolution: 128,
      cells: 1000,
      minSpacing: 8,
      lloyd: { maxIterations: 50, overRelaxation: 1.9 },
      sheet: { thickness: 0 },
    });
    ({ result } = await runSheet(config, context));
    Object.freeze(result);
  }, 30000);

  it('runs (over-relaxed, omega = 1.9): energy falls, no empty cell, the path is recorded', () => {
    expect(result.lloyd.finalEnergy).toBeLessThan(result.lloyd.iterations[0].energy * 0.95);
    expect(result.closed?.centroidPath).toBe('readback');
    expect(result.gpu?.centroidPath).toBe('readback');
    expect(result.lloyd.emptyCells).toBe(0);
  });

  // Statistic: exact spherical Voronoi areas of the final sites, over their mean. A converged
  // Lloyd CVT keeps its 5-7 defects, and Lewis's law holds there too (5-sided cells ~7 %
  // smaller, 7-sided ~9 % larger), so the SD over all cells is ~7 %; the test asserts the
  // hexagons' SD <= 5 % and that the middle half of all cells lies within +-5 % (IQR / 2),
  // and logs the SD over all cells.
  it('cell areas are within 5 % of each other (hexagons: SD; all cells: interquartile half-range)', () => {
    const areas = result.cells.map((c) => c.area);
    const mean = areas.reduce((a, b) => a + b) / areas.length;
    const sd = Math.sqrt(areas.reduce((s, a) => s + (a / mean - 1) ** 2, 0) / areas.length);
    const directions = new Float64Array(3 * areas.length);
    result.cells.forEach((c, i) => c.position.forEach((x, k) => (directions[3 * i + k] = x / 100)));
    const v = sphericalVoronoi(directions, areas.length, 100);
    const exact = Array.from(v.areas);
    const exactMean = exact.reduce((a, b) => a + b) / exact.length;
    const exactSd = Math.sqrt(exact.reduce((s, a) => s + (a / exactMean - 1) ** 2, 0) / exact.length);
    const sorted = exact.map((a) => a / exactMean).sort((a, b) => a - b);
    const sidesOf = (i: number) => v.adjacency.offsets[i + 1] - v.adjacency.offsets[i];
    const hex = exact.filter((_, i) => sidesOf(i) === 6).map((a) => a / exactMean);
    const hexMean = hex.reduce((a, b) => a + b) / hex.length;
    const hexSd = Math.sqrt(hex.reduce((s, a) => s + (a / hexMean - 1) ** 2, 0) / hex.length);
    const mad = exact.reduce((s, a) => s + Math.abs(a / exactMean - 1), 0) / exact.length;
    const q1 = sorted[249],
      q3 = sorted[749];
    console.log(`hexagons ${hex.length} SD ${hexSd.toFixed(4)}, mean abs dev ${mad.toFixed(4)}, IQR/2 ${((q3 - q1) / 2).toFixed(4)}`);
    console.log(
      `areas: labels SD ${sd.toFixed(4)}, exact SD ${exactSd.toFixed(4)}, exact 5th..95th percentile ${sorted[50].toFixed(3)}..${sorted[949].toFixed(3)}, min ${sorted[0].toFixed(3)}, max ${sorted[999].toFixed(3)}`,
    );
    expect(hexSd).toBeLessThanOrEqual(0.05);
    expect((q3 - q1) / 2).toBeLessThanOrEqual(0.05);
    expect(exactSd).toBeLessThanOrEqual(0.08);
  });

  it('Voronoi neighbours agree with the spherical Delaunay (convex hull) on >= 98 % of pairs', () => {
    const labels = pairs(result);
    const exactAnalysis = result.analyses.find((a) => a.method === 'exact');
    expect(exactAnalysis).toBeDefined();
    const directions = new Float64Array(3 * result.cells.length);
    result.cells.forEach((c, i) => c.position.forEach((v, k) => (directions[3 * i + k] = v / 100)));
    const v = sphericalVoronoi(directions, result.cells.length, 100);
    const hull = new Set<string>();
    for (let i = 0; i < v.count; i++)
      for (let k = v.adjacency.offsets[i]; k < v.adjacency.offsets[i + 1]; k++)
        if (i < v.adjacency.neighbours[k]) hull.add(`${i}-${v.adjacency.neighbours[k]}`);
    let both = 0;
    for (const p of labels) if (hull.has(p)) both++;
    const agreement = both / (labels.size + hull.size - both);
    console.log(`neighbour pairs: labels ${labels.size}, hull ${hull.size}, agreement (intersection / union) ${agreement.toFixed(4)}`);
    expect(agreement).toBeGreaterThanOrEqual(0.98);
  });
});
