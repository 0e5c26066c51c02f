/**
 * The small layered tube the tests of a result's cell lists share (lazyRecords, recordTables,
 * the app's exports): 50 cells, exact engine, one layer between the surfaces, run with its
 * per-cell columns (`cellTables: true`).
 */
import { validateConfig } from '../../src/core/config';
import { SheetRunner } from '../../src/run/runSheet';
import type { GpuContext } from '../../src/gpu/context';

export function runLayeredTube(context: GpuContext) {
  const config = validateConfig({
    surface: { kind: 'tube', radius: 40, length: 300 },
    resolution: 128,
    cells: 50,
    engine: 'exact',
    lloyd: { maxIterations: 2 },
    sheet: { surfaceRatio: 2, layers: 1 },
  });
  return new SheetRunner(context).run(config, { cellTables: true });
}
