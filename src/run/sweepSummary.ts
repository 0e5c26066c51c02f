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
      const name = columnName(surface.label ?? `surface${k}`);
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

/** A surface's label without white space (its column prefix), once per label: a sweep asks thousands of times. */
const columnNames = new Map<string, string>();
function columnName(label: string): string {
  let name = columnNames.get(label);
  if (name === undefined) {
    name = label.replace(/\s+/g, '');
    // Labels are few (the layers of a stack); a bound keeps odd callers from growing it.
    if (columnNames.size < 10_000) columnNames.set(label, name);
  }
  return name;
}
