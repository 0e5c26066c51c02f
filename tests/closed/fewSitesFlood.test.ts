import { describe, expect, it } from 'vitest';
import { validateConfig, type ClosedConfig } from '../../src/core/config';
import { placeClosedSites, type ClosedSites } from '../../src/core/closed/geometry';
import { ellipsoidProjector, sphereProjector, type ClosedProjector } from '../../src/core/closed/projector';
import { sampleSurface } from '../../src/core/cubemap/sample';
import { GpuEngine } from '../../src/gpu/engine';
import { cubeLayout } from '../../src/gpu/layout';
import { closedSites, GpuLloydRun } from '../../src/gpu/lloyd';
import { runSheet } from '../../src/run/runSheet';
import { cubeBruteForceLabels } from '../oracles/cubeMap';
import { mislabeledFraction, useHeadlessContext } from '../gpu/context';

/**
 * A cold flood from one to a few sites must label every texel of the cube map: steps of at
 * most half a face carry a label less than a face's width, so a face with no site and far from
 * every site stayed empty before the schedule hopped across faces (docs/closed-surfaces.md).
 * Labels are compared with the brute-force nearest site; the few differences left are the jump
 * flood's usual errors where two sites are nearly equidistant: at most 1e-3 of the texels, the
 * bound of tests/closed/jumpFlood.test.ts (4e-5 was the worst seen here).
 */
const context = useHeadlessContext();
const TOLERANCE = 1e-3;

const surfaces: ReadonlyArray<readonly [string, (n: number) => ReturnType<typeof sampleSurface>, ClosedProjector]> = [
  ['sphere R=20', (n) => sampleSurface({ kind: 'sphere', radius: 20 }, n), sphereProjector(20)],
  ['ellipsoid 2:1:1', (n) => sampleSurface({ kind: 'ellipsoid', a: 40, b: 20, c: 20 }, n), ellipsoidProjector(40, 20, 20)],
];

function unlabelled(labels: Int32Array): number {
  let count = 0;
  for (const id of labels) if (id < 0) count++;
  return count;
}

function flood(n: number, sites: ClosedSites, image: ReturnType<typeof sampleSurface>): { empty: number; wrong: number } {
  const engine = new GpuEngine(context, cubeLayout(n), sites.count, { variant: 'jfa+2', centroidPath: 'auto' });
  try {
    engine.setGeometry(image.area, image.position);
    engine.setSites(sites.positions, sites.texels);
    engine.floodLabels();
    const labels = engine.readLabels();
    const reference = cubeBruteForceLabels(image.position, Float32Array.from(sites.positions), sites.count);
    return { empty: unlabelled(labels), wrong: mislabeledFraction(labels, reference) };
  } finally {
    engine.dispose();
  }
}

describe('cold flood from 1 to 7 sites covers the cube map', () => {
  for (const [name, sample, projector] of surfaces) {
    for (const n of [16, 24, 32, 64]) {
      it(`${name}, n=${n}: every texel labelled, labels = nearest site (<= ${TOLERANCE} differ)`, () => {
        const image = sample(n);
        let worst = 0;
        for (const count of [1, 2, 3, 4, 5, 7]) {
          for (const seed of [1, 2, 3]) {
            const { empty, wrong } = flood(n, placeClosedSites(image, projector, count, seed, 0), image);
            expect(empty, `${count} sites, seed ${seed}: unlabelled texels`).toBe(0);
            expect(wrong, `${count} sites, seed ${seed}: mislabeled`).toBeLessThanOrEqual(TOLERANCE);
            worst = Math.max(worst, wrong);
          }
        }
        console.log(`${name}, n=${n}: worst mislabeled fraction ${worst}`);
      });
    }
  }

  it('7 sites crowded on one face, or 2 sites on opposite faces: every texel labelled', () => {
    const n = 32;
    const image = surfaces[0][1](n);
    const many = placeClosedSites(image, surfaces[0][2], 400, 4, 0);
    const faceOf = (i: number) => Math.floor(many.texels[i] / (n * n));
    const onFace = (face: number, k: number) => [...Array(many.count).keys()].filter((i) => faceOf(i) === face).slice(0, k);
    for (const picked of [onFace(0, 7), [...onFace(2, 1), ...onFace(3, 1)]]) {
      const faces = picked.map(faceOf);
      const sites: ClosedSites = {
        count: picked.length,
        positions: Float64Array.from(picked.flatMap((i) => [...many.positions.subarray(3 * i, 3 * i + 3)])),
        normals: Float64Array.from(picked.flatMap((i) => [...many.normals.subarray(3 * i, 3 * i + 3)])),
        directions: Float64Array.from(picked.flatMap((i) => [...many.directions.subarray(3 * i, 3 * i + 3)])),
        texels: Int32Array.from(picked.map((i) => many.texels[i])),
      };
      const { empty, wrong } = flood(n, sites, image);
      expect(empty, `faces ${faces}: unlabelled texels`).toBe(0);
      expect(wrong, `faces ${faces}: mislabeled`).toBeLessThanOrEqual(TOLERANCE);
    }
  });
});

describe('the cold flood and the warm floods after it from few sites are complete', () => {
  for (const count of [1, 2, 4]) {
    it(`${count} sites on the 2:1:1 ellipsoid, n=32: cold flood and 5 warm-started Lloyd iterations`, () => {
      const [, sample, projector] = surfaces[1];
      const image = sample(32);
      const sites = placeClosedSites(image, projector, count, 7, 0);
      const engine = new GpuEngine(context, cubeLayout(32), count, { variant: 'jfa+2', centroidPath: 'auto' });
      try {
        engine.setGeometry(image.area, image.position);
        const spacing = 0.9 * Math.sqrt(Math.min(...image.area));
        const run = new GpuLloydRun(engine, closedSites(projector, sites, spacing), { maxIterations: 5, tolerance: 0, overRelaxation: 1, warmStart: true });
        const check = () => {
          const labels = engine.readLabels();
          expect(unlabelled(labels)).toBe(0);
          const reference = cubeBruteForceLabels(image.position, Float32Array.from(sites.positions), count);
          expect(mislabeledFraction(labels, reference)).toBeLessThanOrEqual(TOLERANCE);
        };
        check(); // the cold flood, run by the constructor
        while (!run.done) {
          run.step();
          check();
        }
      } finally {
        engine.dispose();
      }
    });
  }
});

describe('the pipeline with 1 and 4 cells on a sphere with a thickness', () => {
  // Every surface is flooded from scratch with so few sites (the seeded one: maxIterations 0).
  for (const [cells, maxIterations, seed] of [
    [1, 0, 1],
    [4, 0, 1],
    [4, 0, 2],
    [4, 0, 5],
    [4, 3, 1],
  ] as const) {
    it(`${cells} cells, ${maxIterations} Lloyd iterations, seed ${seed}: the labels method's areas cover each surface and equal the exact run's`, async () => {
      const run = async (adjacency: 'both' | 'exact') =>
        (
          await runSheet(
            validateConfig({
              surface: { kind: 'sphere', radius: 20 },
              resolution: 32,
              cells,
              seed,
              lloyd: { maxIterations },
              sheet: { thickness: 10, layers: 1, adjacency },
            }) as ClosedConfig,
            context,
          )
        ).result;
      const [labels, exact] = [await run('both'), await run('exact')];
      const surfaces = (r: typeof labels) => [{ offset: 0, cells: r.cells }, ...r.surfaces];
      const exactSurfaces = surfaces(exact);
      expect(surfaces(labels).length).toBe(3);
      surfaces(labels).forEach((surface, k) => {
        const sphere = 4 * Math.PI * (20 + surface.offset) ** 2;
        const total = surface.cells.reduce((sum, c) => sum + c.area, 0);
        expect(Math.abs(total / sphere - 1), `offset ${surface.offset}: area sum ${total} vs ${sphere}`).toBeLessThan(1e-3);
        // Per cell: within about a texel row of the cell's boundary (n = 32: 1.5 % of the surface).
        surface.cells.forEach((cell, i) => expect(Math.abs(cell.area - exactSurfaces[k].cells[i].area) / sphere).toBeLessThan(0.015));
      });
    }, 30000);
  }
});
