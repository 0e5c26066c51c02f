import { SIDE_CLASSES } from '../core/analysis';
import type { SheetResult } from './result';

/** The numbers a sweep writes per run (flattened into CSV columns). */
export function sweepSummary(result: SheetResult): Record<string, unknown> {
  const summary: Record<string, unknown> = {
    iterations: result.lloyd.iterations.length,
    finalEnergy: result.lloyd.finalEnergy,
    centroidPath: result.engine.centroidPath ?? 'none (exact engine)',
  };
  for (const analysis of result.analyses) {
    const s = analysis.summary;
    const perSurface: Record<string, unknown> = {};
    s.perSurface.forEach((surface, k) => {
      const name = (surface.label ?? `surface${k}`).replace(/\s+/g, '');
      const polygons: Record<string, number> = {};
      SIDE_CLASSES.forEach((sides, c) => (polygons[sides] = surface.polygonDistribution[c]));
      perSurface[name] = { meanSides: surface.meanSides, polygons };
    });
    summary[analysis.method] = {
      percentScutoids: s.percentScutoids,
      scutoids: s.scutoids,
      validCells: s.validCells,
      excludedCells: s.excludedCells,
      meanTransitions: s.meanTransitions,
      meanWon: s.meanWon,
      meanLost: s.meanLost,
      meanNeighbours3D: s.meanNeighbours3D,
      ...perSurface,
    };
  }
  return summary;
}
