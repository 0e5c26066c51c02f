/**
 * The shipped reference set (src/core/reference/tissueSheetVoronoiTube.json) must stay what the
 * engine computes: a few of its points are recomputed here from the seeds and spec it records,
 * once through the pipeline (SheetRunner, the runs a sweep of that spec makes) and once with the
 * reference per-ratio analysis (analyzeTubeLab), so neither the file nor the engine can drift
 * from the other silently. Regenerate with `npx tsx scripts/reference-curves.ts`.
 */
import { describe, expect, it } from 'vitest';
import shipped from '../../src/core/reference/tissueSheetVoronoiTube.json';
import { analyzeTubeLab } from '../../src/core/analysis';
import { makeGrid, type ConfigInput } from '../../src/core/config';
import { validatePlanarConfig } from '../planarConfig';
import { ExactLloydRun } from '../../src/core/exactEngine/exactLloyd';
import { validateReferenceDocument, type ReferenceDocument } from '../../src/core/reference';
import { placeSites } from '../../src/core/sites';
import { expandSweep, type SweepSpec } from '../../src/core/sweep';
import { SheetRunner } from '../../src/run/runSheet';
import { version } from '../../src/version';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();
const doc: ReferenceDocument = validateReferenceDocument(shipped);
const spec = (doc.provenance as { spec: SweepSpec }).spec;
const seeds = (doc.provenance as { seeds: number[] }).seeds;

function point(quantity: string, fixed: number, x: number) {
  const curve = doc.curves.find((c) => c.quantity === quantity && Object.values(c.fixed)[0] === fixed)!;
  return curve.points.find((p) => p.x === x)!;
}

function meanSd(values: number[]) {
  const mean = values.reduce((a, b) => a + b, 0) / values.length;
  const sd = Math.sqrt(values.reduce((a, v) => a + (v - mean) ** 2, 0) / (values.length - 1));
  return { mean, sd };
}

describe('the shipped reference set', () => {
  it('is valid, says on every point that it is our computation and not the paper, and names this version', () => {
    expect(doc.curves.length).toBeGreaterThanOrEqual(9);
    expect((doc.provenance as { software: { version: string } }).software.version).toBe(version);
    for (const curve of doc.curves) {
      expect(curve.kind).toBe('model');
      for (const p of curve.points) {
        expect(p.source).toContain(`computed by tissue-sheet ${version} (scripts/reference-curves.ts, protocol lab, exact engine)`);
        expect(p.source).toContain('not numbers taken from the paper');
        expect(p.n).toBe(seeds.length);
      }
    }
    expect(seeds.length).toBeGreaterThanOrEqual(10);
    // The seeds are the sweep's own for its spec.
    expect(
      expandSweep(spec)
        .slice(0, seeds.length)
        .map((r) => r.seed),
    ).toEqual(seeds);
    // Both axes hold the same numbers: Voronoi 4 at s = 2 is s = 2 at Voronoi 4.
    expect({ ...point('surfaceRatio', 4, 2), x: 0 }).toEqual({ ...point('voronoiK', 2, 4), x: 0 });
    // 0 % at s = 1 under the lab protocol.
    for (const k of [1, 4, 10]) expect(point('surfaceRatio', k, 1).percent).toBe(0);
  });

  it("Voronoi 4 at s = 2: the pipeline (SheetRunner) over the spec's runs gives the file's mean and SD", async () => {
    const runs = expandSweep(spec).filter((r) => r.point['lloyd.maxIterations'] === 3 && r.point['sheet.surfaceRatio'] === 2);
    expect(runs).toHaveLength(seeds.length);
    const runner = new SheetRunner(context);
    const values: number[] = [];
    for (const run of runs) {
      const { result } = await runner.run(validatePlanarConfig(run.config as ConfigInput));
      expect(result.engine.name).toBe('exact');
      values.push(result.analyses.find((a) => a.method === 'exact')!.summary.percentScutoids);
    }
    const { mean, sd } = meanSd(values);
    const shippedPoint = point('surfaceRatio', 4, 2);
    expect(shippedPoint.percent).toBeCloseTo(mean, 5);
    expect(shippedPoint.sd!).toBeCloseTo(sd, 5);
  }, 120_000);

  it("Voronoi 1 at s = 1.5 and Voronoi 10 at s = 1.25: the reference per-ratio analysis gives the file's means", () => {
    const config = validatePlanarConfig({ ...(spec.base as ConfigInput), seed: seeds[0] });
    const grid = makeGrid(config);
    for (const [k, s] of [
      [1, 1.5],
      [10, 1.25],
    ]) {
      const values = seeds.map((seed) => {
        const sites = placeSites(grid, config.cells, seed, config.minSpacing);
        const run = new ExactLloydRun(grid, sites, { ...config.lloyd, maxIterations: k - 1 });
        while (!run.done) run.step();
        return analyzeTubeLab(grid, sites, s).analysis.summary.percentScutoids;
      });
      expect(point('surfaceRatio', k, s).percent, `Voronoi ${k}, s = ${s}`).toBeCloseTo(meanSd(values).mean, 5);
    }
  }, 120_000);
});
