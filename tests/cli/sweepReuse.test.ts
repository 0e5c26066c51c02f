import { afterAll, describe, expect, it } from 'vitest';
import { validateConfig, type Config } from '../../src/core/config';
import { createHeadlessContext } from '../../src/node/headless';
import { adjacencyFromLists, analyzeLabStack, invalidOnAnySurface, type SurfaceAdjacency } from '../../src/core/analysis';
import { exactSurface } from '../../src/core/exactEngine';
import type { Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { SheetRunner, sweepSummary } from '../../src/run/index';
import { analyzeLabStackReusing } from '../../src/run/labStackReuse';
import type { SheetResult } from '../../src/run/result';

// What a sweep reuses between grid points must give exactly what each grid point gives alone:
// one Lloyd run serves every Voronoi k on its way (k = sites after k - 1 iterations), one seeded
// surface every sheet.* value, the layers and lab validity every ratio.
const context = createHeadlessContext();
afterAll(() => context.dispose());

const base = {
  surface: { kind: 'tube', radius: 40, length: 300 },
  resolution: 128,
  cells: 24,
  engine: 'exact',
  seed: 7,
  lloyd: { tolerance: 0 },
  sheet: { protocol: 'lab', validityMaxRatio: 4, adjacency: 'exact' },
};
const config = (maxIterations: number, surfaceRatio: number, extra: Record<string, unknown> = {}): Config =>
  validateConfig({ ...base, ...extra, lloyd: { ...base.lloyd, ...(extra.lloyd as object), maxIterations }, sheet: { ...base.sheet, surfaceRatio } });

/** The result without wall-clock timings (the only fields that may differ between two computations). */
function comparable(result: SheetResult): unknown {
  const { timings: _timings, ...rest } = result;
  return JSON.parse(
    JSON.stringify({ ...rest, lloyd: { ...rest.lloyd, iterations: rest.lloyd.iterations.map(({ diagramMs: _d, centroidMs: _c, ...r }) => r) } }),
  );
}

async function alone(c: Config): Promise<SheetResult> {
  return (await new SheetRunner(context).run(c, { views: false })).result;
}

describe('SheetRunner reuse equals computing each grid point alone (exact engine)', () => {
  it('a reused Voronoi k equals a fresh run with that maxIterations, bit for bit', async () => {
    const shared = new SheetRunner(context);
    const setups = new Set<number>();
    // Voronoi 1..5 at two ratios each, in the order a sweep's worker takes them.
    for (const k of [1, 2, 3, 4, 5]) {
      for (const s of [1.5, 3]) {
        const reused = (await shared.run(config(k - 1, s), { views: false })).result;
        const fresh = await alone(config(k - 1, s));
        expect(reused.lloyd.iterations.length).toBe(k - 1);
        setups.add(reused.timings.setupMs);
        expect(comparable(reused), `Voronoi ${k}, s = ${s}`).toEqual(comparable(fresh));
        expect(JSON.stringify(sweepSummary(reused))).toBe(JSON.stringify(sweepSummary(fresh)));
      }
    }
    // One Lloyd run served every k (its set-up time is reported by each).
    expect(setups.size).toBe(1);
  });

  it('skipping Voronoi k, going back, another seed or another tolerance: still the fresh result', async () => {
    const shared = new SheetRunner(context);
    const order: [number, number, Record<string, unknown>][] = [
      [4, 2, {}],
      [9, 2, {}],
      [2, 2, {}], // fewer iterations than the kept run: a new run
      [9, 4, { seed: 8 }],
      [6, 1, { lloyd: { tolerance: 0.5 } }], // converges before 6 iterations: stops where a fresh run stops
      [8, 1, { lloyd: { tolerance: 0.5 } }],
    ];
    for (const [max, s, extra] of order) {
      const c = config(max, s, extra);
      const reused = (await shared.run(c, { views: false })).result;
      expect(comparable(reused), `maxIterations ${max}`).toEqual(comparable(await alone(c)));
    }
  });
});

describe('analyzeLabStackReusing', () => {
  it('equals analyzeLabStack for every stack, in any order, whatever it carried before', () => {
    const grid: Grid = { width: 32, height: 256, texelX: 2, texelY: 2, periodicX: true, periodicY: false };
    const sites = placeSites(grid, 40, 3, 2);
    const layerAt = (s: number, label: string): SurfaceAdjacency => {
      const projected = new Float64Array(sites.length);
      for (let k = 0; k < sites.length; k += 2) {
        projected[k] = sites[k] * s;
        projected[k + 1] = sites[k + 1];
      }
      return exactSurface({ ...grid, width: grid.width * s }, projected, label);
    };
    const ratios = Array.from({ length: 13 }, (_, k) => 1 + 0.25 * k);
    // Shared layers (one object per ratio, as planarFamily keeps them), and each stack's own outer surface.
    const layers = ratios.map((s, k) => layerAt(s, k === 0 ? 'apical' : `layer ${k}`));
    const invalid = invalidOnAnySurface(layers, 40);
    const stackTo = (k: number, ownOuter: boolean): SurfaceAdjacency[] => [
      ...layers.slice(0, Math.max(1, k)),
      ownOuter ? layerAt(ratios[k], 'basal') : { ...layers[k], label: 'basal' },
    ];
    const order = [0, 1, 2, 4, 8, 12, 12, 3, 5, 12, 0, 7, 6, 9];
    order.forEach((k, n) => {
      const stack = stackTo(k, n % 2 === 0);
      const reused = analyzeLabStackReusing(stack, invalid);
      const fresh = analyzeLabStack(
        stack.map((s) => ({ ...s })),
        invalid,
      );
      expect(reused, `stack to s = ${ratios[k]} (call ${n})`).toEqual(fresh);
      expect(JSON.stringify(reused.summary)).toBe(JSON.stringify(fresh.summary));
    });
    // Neighbour lists that are not ascending (labels adjacency): reversed, one repeated, the cell itself.
    const messy = (surface: SurfaceAdjacency): SurfaceAdjacency => {
      const csr = surface;
      const lists = Array.from({ length: surface.count }, (_, i) => {
        const list = Array.from(csr.neighbours.subarray(csr.offsets[i], csr.offsets[i + 1])).reverse();
        return list.length > 0 ? [...list, list[0], i] : list;
      });
      // and side counts of its own on some surfaces
      const sides = surface.label === 'layer 2' || surface.label === 'basal' ? Int32Array.from(lists, (l) => l.length) : undefined;
      const messed = adjacencyFromLists(
        lists,
        lists.map((list) => list.map(() => 1)),
        surface.areas,
        surface.border,
        surface.label,
      );
      return { ...messed, ...(sides ? { sides } : {}) };
    };
    const messyLayers = layers.map(messy);
    for (const k of [3, 6, 2, 12]) {
      const stack = [...messyLayers.slice(0, k), messy(layerAt(ratios[k], 'basal'))];
      expect(analyzeLabStackReusing(stack, invalid), `lists, s = ${ratios[k]}`).toEqual(analyzeLabStack(stack, invalid));
    }
    // No validity of its own (every cell valid but those on a border of the stack's surfaces):
    // the borders of the carried layers, and of each outer surface, decide which cells count.
    const none = new Uint8Array(40);
    for (const k of [2, 5, 12, 1, 9, 12, 4]) {
      const stack = stackTo(k, k % 2 === 0);
      expect(analyzeLabStackReusing(stack, none), `no validity, s = ${ratios[k]}`).toEqual(analyzeLabStack(stack, none));
    }
    // A valid set that differs (a cell excluded beyond the validity layers) is not a stale summary.
    const more = invalid.slice();
    more[more.indexOf(0)] = 1;
    expect(analyzeLabStackReusing(stackTo(6, false), more)).toEqual(analyzeLabStack(stackTo(6, false), more));
  });
  it('equals analyzeLabStack on random stacks: neighbours lost and won back, borders on middle layers only', () => {
    // A small generator (no library state): neighbour sets that change a lot between layers, so
    // cells lose neighbours and win them back, win ones of the first set again, and have a
    // border on one layer only; ascending lists (the exact records' form) and messy ones.
    let state = 12345;
    const random = () => (state = (state * 1103515245 + 12345) % 2147483648) / 2147483648;
    const count = 14;
    const surface = (label: string, messy: boolean): SurfaceAdjacency => {
      const lists = Array.from({ length: count }, (_, i) => {
        const list: number[] = [];
        for (let j = 0; j < count; j++) if (j !== i && random() < 0.3) list.push(j);
        if (messy && list.length > 1) list.reverse().push(list[0], i);
        return list;
      });
      const border = Uint8Array.from({ length: count }, () => (random() < 0.08 ? 1 : 0));
      const areas = Float64Array.from({ length: count }, () => 1 + random());
      return adjacencyFromLists(
        lists,
        lists.map((list) => list.map(() => 1)),
        areas,
        border,
        label,
      );
    };
    for (const messy of [false, true]) {
      const layers = Array.from({ length: 9 }, (_, k) => surface(k === 0 ? 'apical' : `layer ${k}`, messy));
      const invalid = Uint8Array.from({ length: count }, () => (random() < 0.1 ? 1 : 0));
      for (const k of [1, 2, 3, 5, 8, 8, 4, 6, 7, 1, 8, 2, 3]) {
        const outer = random() < 0.5 ? surface('basal', messy) : { ...layers[k], label: 'basal' };
        const stack = [...layers.slice(0, k), outer];
        expect(analyzeLabStackReusing(stack, invalid), `${messy ? 'messy ' : ''}stack of ${k + 1}`).toEqual(analyzeLabStack(stack, invalid));
      }
    }
  });
});
