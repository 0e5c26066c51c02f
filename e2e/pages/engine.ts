// Test page: exposes the engine to Playwright so browser-only paths (additive float blending)
// can be checked against the portable path in the same WebGL2 context.
import type { Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { createCanvasContext } from '../../src/gpu/context';
import { GpuEngine } from '../../src/gpu/engine';
import { gridLayout } from '../../src/gpu/layout';

const context = createCanvasContext(document.getElementById('gl') as HTMLCanvasElement);

/**
 * Largest centroid difference (texels) and relative energy difference between the blend path
 * and each portable path (gather, readback), on the same sites in the same context.
 */
function compareCentroidPaths(grid: Grid, count: number, seed: number, weighted: boolean) {
  const sites = placeSites(grid, count, seed, 2 * grid.texelX);
  const weights = new Float32Array(grid.width * grid.height);
  for (let i = 0; i < weights.length; i++) {
    weights[i] = weighted ? 1 + 15 * ((i % grid.width) / grid.width > 0.5 ? 1 : 0) : 1;
  }
  const sumsOf = (centroidPath: 'blend' | 'gather' | 'readback') => {
    const engine = new GpuEngine(context, gridLayout(grid), count, { variant: 'jfa+2', centroidPath });
    engine.setGeometry(weights);
    engine.setSites(sites);
    engine.floodLabels();
    const sums = engine.computeSums().slice();
    engine.dispose();
    return sums;
  };
  const blend = sumsOf('blend');
  let emptyCells = 0;
  for (let i = 0; i < count; i++) if (!(blend[5 * i + 3] > 0)) emptyCells++;
  const against = (other: Float64Array) => {
    let worstCentroid = 0;
    let worstEnergy = 0;
    for (let i = 0; i < count; i++) {
      const dx = blend[5 * i] / blend[5 * i + 3] - other[5 * i] / other[5 * i + 3];
      const dy = blend[5 * i + 1] / blend[5 * i + 3] - other[5 * i + 1] / other[5 * i + 3];
      worstCentroid = Math.max(worstCentroid, Math.hypot(dx, dy));
      worstEnergy = Math.max(worstEnergy, Math.abs(blend[5 * i + 4] - other[5 * i + 4]) / other[5 * i + 4]);
    }
    return { worstCentroid, worstEnergy };
  };
  return { gather: against(sumsOf('gather')), readback: against(sumsOf('readback')), emptyCells, capabilities: context.capabilities };
}

Object.assign(window, { tissueSheetTest: { compareCentroidPaths, capabilities: context.capabilities } });
document.title = 'ready';
