// Test page for the closed-surface engine's browser-only path (additive float blending): the
// blend and readback sums of the same labels, and a short blend-path Lloyd run. Driven by
// tests/closed/chromium-blend.ts (`npx tsx tests/closed/chromium-blend.ts`).
import { placeClosedSites } from '../../src/core/closed/geometry';
import { ellipsoidProjector } from '../../src/core/closed/projector';
import { sampleSurface } from '../../src/core/cubemap/sample';
import { createCanvasContext } from '../../src/gpu/context';
import { GpuEngine, SUMS_STRIDE } from '../../src/gpu/engine';
import { cubeLayout } from '../../src/gpu/layout';
import { closedSites, GpuLloydRun } from '../../src/gpu/lloyd';

const context = createCanvasContext(document.getElementById('gl') as HTMLCanvasElement);

function compare(n: number, count: number) {
  const image = sampleSurface({ kind: 'ellipsoid', a: 80, b: 40, c: 40 }, n);
  const projector = ellipsoidProjector(80, 40, 40);
  const sites = placeClosedSites(image, projector, count, 7, 0);
  const sums: Float64Array[] = [];
  const paths: string[] = [];
  for (const centroidPath of ['blend', 'readback'] as const) {
    const engine = new GpuEngine(context, cubeLayout(n), count, { variant: 'jfa+2', centroidPath });
    engine.setGeometry(image.area, image.position);
    engine.setSites(sites.positions, sites.texels);
    engine.floodLabels();
    sums.push(engine.computeSums().slice());
    paths.push(engine.centroidPath);
    engine.dispose();
  }
  const [blend, readback] = sums;
  let worstCentroid = 0,
    worstEnergy = 0;
  for (let i = 0; i < count; i++) {
    const o = SUMS_STRIDE * i;
    const d = [0, 1, 2].map((c) => blend[o + c] / blend[o + 3] - readback[o + c] / readback[o + 3]);
    worstCentroid = Math.max(worstCentroid, Math.hypot(d[0], d[1], d[2]));
    worstEnergy = Math.max(worstEnergy, Math.abs(blend[o + 4] - readback[o + 4]) / readback[o + 4]);
  }
  // A plain Lloyd run on the blend path: the energy must not increase.
  const engine = new GpuEngine(context, cubeLayout(n), count, { variant: 'jfa+2', centroidPath: 'blend' });
  engine.setGeometry(image.area, image.position);
  const run = new GpuLloydRun(engine, closedSites(projector, sites, 0.5), { maxIterations: 15, tolerance: 0, overRelaxation: 1, warmStart: true });
  while (!run.done) run.step();
  const energies = [...run.iterations.map((r) => r.energy), run.finish().energy];
  engine.dispose();
  let increases = 0;
  for (let k = 1; k < energies.length; k++) if (energies[k] > energies[k - 1] * (1 + 1e-6)) increases++;
  return { paths, worstCentroid, worstEnergy, energies, increases, capabilities: context.capabilities };
}

Object.assign(window, { closedTest: { compare } });
document.title = 'ready';
