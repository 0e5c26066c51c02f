import { describe, expect, it } from 'vitest';
import { placeClosedSites } from '../../src/core/closed/geometry';
import { cubeBruteForceLabels } from '../oracles/cubeMap';
import { ellipsoidProjector, sphereProjector } from '../../src/core/closed/projector';
import { sampleSurface } from '../../src/core/cubemap/sample';
import { mislabeledFraction, useHeadlessContext } from '../gpu/context';
import { GpuEngine } from '../../src/gpu/engine';
import { cubeLayout } from '../../src/gpu/layout';
import { closedSites, GpuLloydRun } from '../../src/gpu/lloyd';

const context = useHeadlessContext();

describe('jump flood on the cube map vs brute-force nearest site (3D distance)', () => {
  const cases = [
    ['sphere R=50, n=64, 300 sites', sampleSurface({ kind: 'sphere', radius: 50 }, 64), sphereProjector(50), 300],
    ['ellipsoid 2:1:1, n=64, 200 sites', sampleSurface({ kind: 'ellipsoid', a: 60, b: 30, c: 30 }, 64), ellipsoidProjector(60, 30, 30), 200],
    ['sphere, n=64, 12 sites (cells span faces)', sampleSurface({ kind: 'sphere', radius: 10 }, 64), sphereProjector(10), 12],
  ] as const;
  for (const [name, image, projector, count] of cases) {
    it(`${name}: <= 1e-3 mislabeled (jfa+2)`, () => {
      const sites = placeClosedSites(image, projector, count, 5, 0);
      const engine = new GpuEngine(context, cubeLayout(image.n), count, { variant: 'jfa+2', centroidPath: 'auto' });
      try {
        engine.setGeometry(image.area, image.position);
        engine.setSites(sites.positions, sites.texels);
        engine.floodLabels();
        const gpu = engine.readLabels();
        const f32 = Float32Array.from(sites.positions);
        const reference = cubeBruteForceLabels(image.position, f32, count);
        const wrong = mislabeledFraction(gpu, reference);
        console.log(`${name}: mislabeled ${wrong}`);
        expect(wrong).toBeLessThanOrEqual(1e-3);
      } finally {
        engine.dispose();
      }
    });
  }
});

describe('warm-started floods during Lloyd', () => {
  it('labels after 6 warm-started iterations still match brute force (<= 1e-3)', () => {
    const image = sampleSurface({ kind: 'ellipsoid', a: 60, b: 30, c: 45 }, 64);
    const projector = ellipsoidProjector(60, 30, 45);
    const sites = placeClosedSites(image, projector, 250, 8, 0);
    const engine = new GpuEngine(context, cubeLayout(64), 250, { variant: 'jfa+2', centroidPath: 'auto' });
    try {
      engine.setGeometry(image.area, image.position);
      const spacing = 0.9 * Math.sqrt(Math.min(...image.area));
      const run = new GpuLloydRun(engine, closedSites(projector, sites, spacing), { maxIterations: 6, tolerance: 0, overRelaxation: 1, warmStart: true });
      while (!run.done) run.step();
      expect(run.iterations.at(-1)!.jumpFloodPasses).toBeLessThan(9);
      const wrong = mislabeledFraction(engine.readLabels(), cubeBruteForceLabels(image.position, Float32Array.from(sites.positions), 250));
      console.log(`warm-started flood after 6 iterations: mislabeled ${wrong}`);
      expect(wrong).toBeLessThanOrEqual(1e-3);
    } finally {
      engine.dispose();
    }
  });
});
