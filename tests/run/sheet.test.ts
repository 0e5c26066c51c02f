import { describe, expect, it } from 'vitest';
import { ConfigError, validateConfig, type Config, type ConfigInput } from '../../src/core/config';
import { validatePlanarConfig } from '../planarConfig';
import { exactVoronoi } from '../../src/core/exact';
import { withMinBoundaryLength } from '../../src/core/analysis';
import { labelAdjacency } from '../../src/core/labels';
import { chooseEngine } from '../../src/run/enginePolicy';
import { defaultMinContactLength, planarFamily, type PlanarGeometry } from '../../src/run/planarFamily';
import { relaxSeededSurface, type SeededSurface } from '../../src/run/relax';
import { runSheet, SheetRunner } from '../../src/run/runSheet';
import { analyzeStack } from '../../src/run/stack';
import { useHeadlessContext } from '../gpu/context';
import { GpuEngine } from '../../src/gpu/engine';
import { gridLayout } from '../../src/gpu/layout';

const context = useHeadlessContext();

/** The published tube (512 x 4096 µm strip, 200 cells, spacing 5) at the default resolution. */
const tube = (extra: ConfigInput = {}) => validatePlanarConfig({ cells: 200, minSpacing: 5, ...extra, sheet: { seeded: 'apical', ...extra.sheet } });

function pairSet(offsets: Int32Array, neighbours: Int32Array): Set<number> {
  const pairs = new Set<number>();
  for (let i = 0; i + 1 < offsets.length; i++) {
    for (let k = offsets[i]; k < offsets[i + 1]; k++) if (i < neighbours[k]) pairs.add(i * 100_000 + neighbours[k]);
  }
  return pairs;
}

describe('sheet geometry invariants', () => {
  it('a plane and its offset never exchange neighbours (labels and exact)', async () => {
    const config = validatePlanarConfig({
      surface: { kind: 'plane', width: 300, height: 200 },
      resolution: 300,
      cells: 120,
      lloyd: { maxIterations: 3 },
      sheet: { thickness: 25, layers: 2 },
    });
    const { result } = await runSheet(config, context);
    expect(result.surfaces.map((s) => s.name)).toEqual(['layer 1', 'layer 2', 'apical']);
    for (const analysis of result.analyses) {
      expect(analysis.summary.percentScutoids).toBe(0);
      expect(analysis.summary.meanTransitions).toBe(0);
    }
    expect(result.surfaces.at(-1)!.cells[7].position[2]).toBeCloseTo(25);
  });

  it('a tube at surface ratio 1 has no scutoids', async () => {
    const { result } = await runSheet(tube({ lloyd: { maxIterations: 2 }, sheet: { surfaceRatio: 1 } }), context);
    for (const analysis of result.analyses) expect(analysis.summary.percentScutoids).toBe(0);
  });

  it('an outward ratio s makes the other tube s times wider around, with the same sites', async () => {
    const { result } = await runSheet(tube({ lloyd: { maxIterations: 1 }, sheet: { surfaceRatio: 2.5 } }), context);
    const other = result.surfaces.at(-1)!;
    expect(other.grid.width).toBe(result.grid.width * 2.5);
    const r0 = Math.hypot(result.cells[3].position[0], result.cells[3].position[1]);
    const r1 = Math.hypot(other.cells[3].position[0], other.cells[3].position[1]);
    expect(r1 / r0).toBeCloseTo(2.5, 6);
    expect(other.cells[3].position[2]).toBeCloseTo(result.cells[3].position[2], 6);
  });
});

describe('a hand-built exchange: rhombi of four sites whose shared edge flips when the strip is stretched', () => {
  // A centred rectangular lattice on a tube: rows h apart along the axis, sites 2w apart around
  // it, every other row shifted by w. In each rhombus of four sites, the two side by side
  // (2w apart) share an edge while 2w < 2h, and the two above each other (2h apart) share it
  // once the circumference is stretched by s with 2ws > 2h: the edge flips at s* = h / w.
  const w = 10;
  const h = 15;
  const columns = 6;
  const rows = 10;
  const flip = h / w;
  const width = 2 * w * columns;
  const height = h * rows;

  async function stackAt(method: 'labels' | 'exact', s: number) {
    const config = validatePlanarConfig({
      surface: { kind: 'tube', radius: width / (2 * Math.PI), length: height },
      resolution: height,
      cells: columns * rows,
      lloyd: { maxIterations: 0 },
      sheet: { surfaceRatio: s, adjacency: method, minContactLength: 0 },
    });
    const grid = { width, height, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
    const sites = new Float32Array(2 * columns * rows);
    for (let j = 0; j < rows; j++) {
      for (let i = 0; i < columns; i++) {
        const id = j * columns + i;
        sites[2 * id] = 2 * w * i + (j % 2) * w + w / 2;
        sites[2 * id + 1] = h * j + h / 2;
      }
    }
    const engine = new GpuEngine(context, gridLayout(grid), columns * rows, { variant: 'jfa+2', centroidPath: 'auto' });
    engine.setSites(sites);
    engine.floodLabels();
    const seeded: SeededSurface<PlanarGeometry, Float32Array> = {
      geometry: { grid, density: new Float32Array(width * height).fill(1) },
      sites,
      labels: engine.readLabels(),
      engine: chooseEngine(config, 'planar grid', context.capabilities),
      iterations: [],
      converged: false,
      finalEnergy: 0,
      emptyCells: 0,
      setupMs: 0,
      lloydMs: 0,
    };
    engine.dispose();
    return analyzeStack(planarFamily, config, seeded, context);
  }

  for (const method of ['exact', 'labels'] as const) {
    it(`${method}: every interior cell exchanges neighbours just past s* = h/w and none just before`, async () => {
      // Pixels resolve the flip to about a texel of the 2w gap: stay 10 % away from s* there.
      const margin = method === 'exact' ? 1e-3 : 0.1;
      const before = (await stackAt(method, flip * (1 - margin))).analyses[0];
      const after = (await stackAt(method, flip * (1 + margin))).analyses[0];
      // Border cells: the two rows at each end touch the open ends.
      expect(before.summary.validCells).toBe(columns * (rows - 2));
      expect(before.summary.percentScutoids).toBe(0);
      expect(after.summary.percentScutoids).toBe(100);
      const interior = after.cells[5 * columns + 2];
      // Lost both side-by-side neighbours, won the two above and below: 2 + 2 transitions,
      // 6 neighbours on each surface, 8 in 3D.
      expect([interior.won, interior.lost, interior.transitions, interior.neighbours3D]).toEqual([2, 2, 4, 8]);
    });
  }
});

describe('the published tube model over 10 realizations', () => {
  it('% scutoids rises with s, and at s = 1.25 and 1.5 falls as Lloyd iterations grow', async () => {
    const ratios = [1.25, 1.5, 2, 4];
    const voronoi = [1, 5, 10]; // "Voronoi k" = k - 1 Lloyd iterations
    const mean: Record<string, number> = {};
    const runner = new SheetRunner(context);
    for (const v of voronoi) {
      for (const s of ratios) {
        let total = 0;
        for (let realization = 0; realization < 10; realization++) {
          const config = tube({ seed: 100 + realization, lloyd: { maxIterations: v - 1 }, sheet: { surfaceRatio: s, adjacency: 'labels' } });
          total += (await runner.run(config)).result.analyses[0].summary.percentScutoids;
        }
        mean[`${v}@${s}`] = total / 10;
      }
    }
    for (const v of voronoi) {
      for (let k = 1; k < ratios.length; k++) expect(mean[`${v}@${ratios[k]}`]).toBeGreaterThan(mean[`${v}@${ratios[k - 1]}`]);
    }
    for (const s of [1.25, 1.5]) {
      expect(mean[`5@${s}`]).toBeLessThan(mean[`1@${s}`]);
      expect(mean[`10@${s}`]).toBeLessThan(mean[`5@${s}`]);
    }
    console.log('mean % scutoids (Voronoi k @ s):', JSON.stringify(mean));
  }, 300_000);
});

describe('pixel adjacency against exact adjacency at the default resolution', () => {
  const cases: Array<[string, ConfigInput]> = [
    ['tube', { cells: 200, minSpacing: 5, lloyd: { maxIterations: 10 } }],
    ['plane', { surface: { kind: 'plane', width: 1000, height: 600 }, cells: 300, lloyd: { maxIterations: 10 } }],
  ];
  for (const [name, input] of cases) {
    it(`${name}: >= 98 % of neighbour pairs agree`, async () => {
      // The GPU engine's label adjacency is what is compared: ask for it (auto takes the exact
      // engine on this software renderer).
      const config = validatePlanarConfig({ ...input, engine: 'gpu' });
      const seeded = await relaxSeededSurface(planarFamily, config, context, chooseEngine(config, 'planar grid', context.capabilities));
      const { grid } = seeded.geometry;
      const labels = labelAdjacency(grid, seeded.labels!, config.cells);
      const pixel = withMinBoundaryLength(labels, defaultMinContactLength(grid, config.cells));
      const exact = exactVoronoi(grid, seeded.sites).adjacency;
      const p = pairSet(pixel.offsets, pixel.neighbours);
      const e = pairSet(exact.offsets, exact.neighbours);
      let both = 0;
      for (const pair of p) if (e.has(pair)) both++;
      const agreement = both / (p.size + e.size - both);
      expect(agreement).toBeGreaterThanOrEqual(0.98);
    });
  }
});

describe('runSheet checks a library caller config as the CLI does', () => {
  const small = () =>
    validateConfig({ surface: { kind: 'plane', width: 100, height: 100 }, resolution: 32, cells: 10, engine: 'exact', lloyd: { maxIterations: 1 } });
  const refusal = (config: unknown) =>
    runSheet(config as Config, context).then(
      () => null,
      (error: unknown) => error as ConfigError,
    );

  it('validates again: a config changed since it was validated is refused naming the field', async () => {
    const changed = (edit: (c: Record<string, Record<string, unknown>>) => void) => {
      const c = small() as unknown as Record<string, Record<string, unknown>>;
      edit(c);
      return c;
    };
    expect((await refusal(changed((c) => (c.lloyd.maxIterations = 1e9))))?.field).toBe('lloyd.maxIterations');
    expect((await refusal(changed((c) => (c.surface.width = NaN))))?.field).toBe('surface.width');
    expect((await refusal(changed((c) => (c.surface.kind = 'torus'))))?.field).toBe('surface.kind');
    expect((await refusal(changed((c) => ((c as unknown as { cells: number }).cells = -5))))?.field).toBe('cells');
  });

  it('holds it to the scale guards and the texture size, whatever the budget', async () => {
    const tooFar = await refusal(validateConfig({ surface: { kind: 'plane', width: 100, height: 100 }, resolution: 32, cells: 10, sheet: { thickness: 2e7 } }));
    expect(tooFar).toBeInstanceOf(ConfigError);
    expect(tooFar?.field).toBe('sheet.thickness');
    const max = context.capabilities.maxTextureSize;
    const wide = await refusal(
      validateConfig({ surface: { kind: 'sphere', radius: 50 }, resolution: Math.min(16384, 2 * max), cells: 20, sheet: { thickness: 5 } }),
    );
    expect(wide?.field).toBe('resolution');
    expect(wide?.message).toMatch(/this GPU allows at most/);
    // A valid config still runs.
    expect((await runSheet(small(), context)).result.cells).toHaveLength(10);
  });
});
