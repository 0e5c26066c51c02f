import { SIDE_CLASSES } from '../core/analysis';
import type { SheetResult } from './result';

/** The method metrics a sweep writes per run, in column order (both functions below read this list). */
const METRICS = ['percentScutoids', 'scutoids', 'validCells', 'excludedCells', 'meanTransitions', 'meanWon', 'meanLost', 'meanNeighbours3D'] as const;

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
    const metrics: Record<string, unknown> = {};
    for (const metric of METRICS) metrics[metric] = s[metric];
    summary[analysis.method] = { ...metrics, ...perSurface };
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

const TOP = new Set(['iterations', 'finalEnergy', 'centroidPath']);
const FIXED = new Set<string>(METRICS);

/**
 * flatValues(sweepSummary(result)) without building the summary: its values in the same order,
 * and a shape that names its key list (the methods and surface names), for a sweep's threads,
 * which flatten thousands of summaries of a few shapes (the nested summary and its walk were
 * a fiftieth of a thread's time and a sixth of what it allocated). Null where an object of
 * the summary would not keep the order this writes (a repeated method or surface name, one
 * that is a top-level key or a metric, or an integer-like name, which an object puts first):
 * the caller flattens sweepSummary then. The sweep's threads also check, once per shape, that
 * the values are flatValues' (sweepWorkers.ts).
 */
export function sweepSummaryValues(result: SheetResult): { shape: string; values: unknown[] } | null {
  const values: unknown[] = [result.lloyd.iterations.length, result.lloyd.finalEnergy, result.engine.centroidPath ?? 'none (exact engine)'];
  let shape = '';
  const methods = new Set<string>();
  for (const analysis of result.analyses) {
    const method = analysis.method;
    if (methods.has(method) || TOP.has(method) || isIndexLike(method)) return null;
    methods.add(method);
    const s = analysis.summary;
    for (const metric of METRICS) values.push(s[metric]);
    shape += `${method.length}:${method}{`;
    const names = new Set<string>();
    const perSurface = s.perSurface;
    for (let k = 0; k < perSurface.length; k++) {
      const surface = perSurface[k];
      const name = columnName(surface.label ?? `surface${k}`);
      if (names.has(name) || FIXED.has(name) || isIndexLike(name)) return null;
      names.add(name);
      shape += `${name.length}:${name}`;
      values.push(surface.meanSides);
      const fractions = surface.polygonDistribution;
      for (let c = 0; c < SIDE_CLASSES.length; c++) values.push(fractions[c]);
    }
    shape += '}';
  }
  return { shape, values };
}

/** Whether an object orders `name` as an array index (before its other keys). */
function isIndexLike(name: string): boolean {
  return /^(?:0|[1-9]\d*)$/.test(name) && Number(name) < 2 ** 32 - 1;
}
