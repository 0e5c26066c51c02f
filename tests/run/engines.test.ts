import { describe, expect, it } from 'vitest';
import { analyzeTubeLab, LAB_PROTOCOL } from '../../src/core/analysis';
import { validateConfig, type ConfigInput } from '../../src/core/config';
import { validatePlanarConfig } from '../planarConfig';
import { exactVoronoi } from '../../src/core/exact';
import { chooseEngine } from '../../src/run/enginePolicy';
import { SheetRunner } from '../../src/run/runSheet';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();
const software = { renderer: 'llvmpipe', maxTextureSize: 8192, floatBlend: false, softwareRenderer: true };
const hardware = { renderer: 'NVIDIA H100', maxTextureSize: 16384, floatBlend: true, softwareRenderer: false };

/** A small published-like tube: 200 cells on a 512 x 1024 µm strip. */
const tube = (extra: ConfigInput = {}) =>
  validatePlanarConfig({
    surface: { kind: 'tube', radius: 512 / (2 * Math.PI), length: 1024 },
    resolution: 256,
    cells: 120,
    minSpacing: 5,
    seed: 11,
    ...extra,
    sheet: { ...extra.sheet },
  });

describe('the engine policy', () => {
  it('auto: exact on a software renderer for planes and tubes, GPU on hardware, GPU where labels are asked for', () => {
    expect(chooseEngine(tube(), 'planar grid', software).name).toBe('exact');
    expect(chooseEngine(tube(), 'planar grid', hardware)).toMatchObject({ name: 'gpu', centroidPath: 'blend' });
    expect(chooseEngine(tube({ sheet: { adjacency: 'labels' } }), 'planar grid', software)).toMatchObject({ name: 'gpu', centroidPath: 'readback' });
    expect(chooseEngine(tube({ engine: 'gpu' }), 'planar grid', software).name).toBe('gpu');
    expect(chooseEngine(tube({ engine: 'exact' }), 'planar grid', hardware).name).toBe('exact');
    const sphere = validateConfig({ surface: { kind: 'sphere', radius: 40 }, engine: 'auto' });
    expect(chooseEngine(sphere, 'cube map', software)).toMatchObject({ name: 'gpu', family: 'cube map' });
    for (const choice of [chooseEngine(tube(), 'planar grid', software), chooseEngine(tube(), 'planar grid', hardware)]) {
      expect(choice.reason.length).toBeGreaterThan(10);
    }
  });

  it('refuses what an engine or protocol cannot do, naming the field', async () => {
    const runner = new SheetRunner(context);
    const refusals: Array<[ConfigInput, string]> = [
      [{ surface: { kind: 'sphere', radius: 40 }, engine: 'exact' }, 'engine'],
      [{ engine: 'exact', sheet: { adjacency: 'labels' } }, 'sheet.adjacency'],
      [{ surface: { kind: 'plane', width: 200, height: 200 }, sheet: { protocol: 'lab', thickness: 5 } }, 'sheet.protocol'],
      [{ sheet: { protocol: 'lab' } }, 'sheet.protocol'],
      [{ sheet: { protocol: 'lab', surfaceRatio: 2, direction: 'inward' } }, 'sheet.direction'],
      [{ sheet: { surfaceRatio: 2, layers: 2, layerStep: 0.5 } }, 'sheet.layers'],
      [{ sheet: { surfaceRatio: 2, layerStep: 1e-5 } }, 'sheet.layerStep'],
    ];
    for (const [input, field] of refusals) {
      const error = await runner.run(validateConfig({ cells: 20, resolution: 64, ...input })).then(
        () => null,
        (e: Error & { field?: string }) => e,
      );
      expect(error?.name, JSON.stringify(input)).toBe('ConfigError');
      expect(error?.field, error?.message).toBe(field);
      expect(error?.message.split('\n')).toHaveLength(1);
    }
  });
});

describe('the seeded surface cache', () => {
  it('is shared only by runs on the same engine (a sweep over sheet.adjacency switches engines)', async () => {
    const runner = new SheetRunner(context);
    const labels = await runner.run(tube({ lloyd: { maxIterations: 2 }, sheet: { adjacency: 'labels', surfaceRatio: 1.5 } }));
    const both = await runner.run(tube({ lloyd: { maxIterations: 2 }, sheet: { adjacency: 'both', surfaceRatio: 1.5 } }));
    const alone = await new SheetRunner(context).run(tube({ lloyd: { maxIterations: 2 }, sheet: { adjacency: 'both', surfaceRatio: 1.5 } }));
    expect(labels.result.engine.name).toBe('gpu');
    expect(both.result.engine.name).toBe(alone.result.engine.name);
    expect(both.result.lloyd.finalEnergy).toBe(alone.result.lloyd.finalEnergy);
  });
});

describe('the exact engine through the pipeline', () => {
  it('records itself, makes only exact analyses, and its cells are the exact Voronoi cells of its sites', async () => {
    const output = await new SheetRunner(context).run(tube({ engine: 'exact', lloyd: { maxIterations: 5 }, sheet: { surfaceRatio: 1.5 } }));
    const { result } = output;
    expect(result.engine.name).toBe('exact');
    expect(result.gpu).toBeNull();
    expect(result.analyses.map((a) => a.method)).toEqual(['exact']);
    for (let k = 1; k < result.lloyd.iterations.length; k++) {
      expect(result.lloyd.iterations[k].energy).toBeLessThanOrEqual(result.lloyd.iterations[k - 1].energy * (1 + 1e-9));
    }
    // The seeded cells are the exact diagram of the final sites.
    const grid = output.labelImages[0].grid;
    const sites = new Float64Array(result.cells.flatMap((c) => [c.surface[0] / grid.texelX, c.surface[1] / grid.texelY]));
    const exact = exactVoronoi(grid, sites);
    result.cells.forEach((cell, id) => {
      expect(cell.neighbours.map((n) => n.id)).toEqual(Array.from(exact.cells[id].neighbours));
      expect(cell.area).toBeCloseTo(exact.cells[id].area, 6);
    });
    // Views still get a label image: the exact cells drawn on the texels.
    const labels = output.labelImages[0].labels;
    expect(labels).toHaveLength(grid.width * grid.height);
    const owned = new Set(labels);
    expect(owned.has(-1)).toBe(false);
    expect(owned.size).toBe(result.cells.length);
  });
});

describe('the lab protocol through the pipeline', () => {
  const ratios = [1, 1.25, 1.5, 2, 3];

  it('layers every 0.25 of s, one valid set at every ratio, 0 % at s = 1, % never falls with s, equal to the independent analyzeTubeLab', async () => {
    const runner = new SheetRunner(context);
    const valid: string[] = [];
    let previous = -Infinity;
    for (const s of ratios) {
      const { result } = await runner.run(tube({ engine: 'exact', lloyd: { maxIterations: 3 }, sheet: { surfaceRatio: s, protocol: 'lab' } }));
      // Layers at s = 1.25, 1.5, ... and the other surface (also at s = 1 itself).
      expect(result.surfaces).toHaveLength(Math.max(1, Math.round((s - 1) / 0.25)));
      const exact = result.analyses[0];
      valid.push(
        exact.cells
          .filter((c) => c.valid)
          .map((c) => c.id)
          .join(),
      );
      if (s === 1) expect(exact.summary.percentScutoids).toBe(0);
      expect(exact.summary.percentScutoids).toBeGreaterThanOrEqual(previous);
      previous = exact.summary.percentScutoids;
      // The same statistics from the protocol module alone, on the pipeline's own sites.
      const grid = { width: 256, height: 512, texelX: 2, texelY: 2, periodicX: true, periodicY: false };
      const sites = new Float64Array(result.cells.flatMap((c) => [c.surface[0] / grid.texelX, c.surface[1] / grid.texelY]));
      const reference = analyzeTubeLab(grid, sites, s, LAB_PROTOCOL);
      expect(exact.summary.validCells).toBe(reference.analysis.summary.validCells);
      expect(exact.summary.percentScutoids).toBeCloseTo(reference.analysis.summary.percentScutoids, 9);
      expect(exact.summary.meanTransitions).toBeCloseTo(reference.analysis.summary.meanTransitions, 9);
    }
    expect(new Set(valid).size).toBe(1);
  });

  it('the labels method on the GPU uses the same valid cells and the pixel rule (6 texel edges of a 512-wide image)', async () => {
    const { result } = await new SheetRunner(context).run(tube({ engine: 'gpu', lloyd: { maxIterations: 2 }, sheet: { surfaceRatio: 1.5, protocol: 'lab' } }));
    const [labels, exact] = result.analyses;
    expect(labels.method).toBe('labels');
    expect(labels.minContactLength).toBeCloseTo(6 * (256 / 512) * 2, 12);
    expect(labels.cells.map((c) => c.valid)).toEqual(exact.cells.map((c) => c.valid));
  });
});
