import { describe, expect, it } from 'vitest';
import { cubeBruteForceLabels, placeClosedSites } from '../../src/core/closed/geometry';
import { ellipsoidProjector, sphereProjector } from '../../src/core/closed/projector';
import { sampleSurface } from '../../src/core/cubemap/sample';
import { CubeCcvtEngine } from '../../src/gpu/cubeEngine';
import { mislabeledFraction, useHeadlessContext } from '../gpu/context';

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
      const engine = new CubeCcvtEngine(context, image.n, count, { variant: 'jfa+2', centroidPath: 'auto' });
      try {
        engine.setGeometry(image.position, image.area);
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
