import { describe, expect, it } from 'vitest';
import { validatePlanarConfig } from '../planarConfig';
import { runSheet } from '../../src/run/runSheet';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();

describe('CVT density law (Du et al.): in 2D cell diameter ~ density^(-1/4)', () => {
  it('a density ratio of 16 between two halves gives a mean cell diameter ratio of 2 within 10 %', async () => {
    const width = 400;
    const config = validatePlanarConfig({
      // A flat torus, so no open edge disturbs the cells; stripes with period = width give two
      // halves: density 1 on x in [0, 200), 16 on [200, 400).
      surface: { kind: 'plane', width, height: 200, periodicX: true, periodicY: true },
      resolution: 512,
      cells: 500,
      seed: 4,
      density: { kind: 'stripes', axis: 'x', period: width, low: 1, high: 16 },
      lloyd: { maxIterations: 60 },
      sheet: { adjacency: 'labels' },
    });
    const { result } = await runSheet(config, context);
    // Stay two large cells away from the two interfaces (x = 0 and x = 200).
    const margin = 40;
    const diameters = { low: [] as number[], high: [] as number[] };
    for (const cell of result.cells) {
      const x = cell.surface[0];
      if (x > margin && x < width / 2 - margin) diameters.low.push(Math.sqrt(cell.area));
      if (x > width / 2 + margin && x < width - margin) diameters.high.push(Math.sqrt(cell.area));
    }
    const mean = (values: number[]) => values.reduce((a, b) => a + b, 0) / values.length;
    expect(diameters.low.length).toBeGreaterThan(10);
    expect(diameters.high.length).toBeGreaterThan(100);
    const ratio = mean(diameters.low) / mean(diameters.high);
    console.log(`mean diameter ratio low/high density: ${ratio.toFixed(3)} (${diameters.low.length} and ${diameters.high.length} cells)`);
    expect(ratio).toBeGreaterThan(2 * 0.9);
    expect(ratio).toBeLessThan(2 * 1.1);
  });
});
