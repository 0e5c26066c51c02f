/**
 * The summary columns a configuration's run writes to runs.csv, known before it runs, so the
 * header of a sweep is the union over every grid point (fixed from the spec before the first
 * run, never from whichever run finished first).
 *
 * It mirrors the pipeline's sweep summary (src/run/sweepSummary.ts), flattened with "." (see
 * flattenSummary): `iterations`, `finalEnergy`, `centroidPath`, then for each adjacency method
 * the config may produce on any renderer (possibleMethods; core/config/analysisMethods.ts, the
 * description the pipeline computes its analyses from: "labels" unless sheet.adjacency is
 * "exact", "exact" unless it is "labels", on every surface; only "exact" when the engine policy
 * picks the exact CPU engine): `<method>.percentScutoids`, `.scutoids`, `.validCells`,
 * `.excludedCells`, `.meanTransitions`, `.meanWon`, `.meanLost`, `.meanNeighbours3D`, and per
 * surface of the stack (seeded, "layer k" without its space, other) `<method>.<surface>.meanSides`
 * and `<method>.<surface>.polygons.<3..10+>`. A CLI test checks a real run's summary against this.
 */
import { SIDE_CLASSES } from '../analysis';
import { ADJACENCY_METHODS, methodsOnRenderer, type AdjacencyMethod, type Config } from '../config';
import { sheetOffsets } from '../sheetGeometry';

const TOP_COLUMNS = ['iterations', 'finalEnergy', 'centroidPath'] as const;
/** Summary columns holding text; every other summary column holds a number ("NaN" included). */
export const TEXT_COLUMNS: ReadonlySet<string> = new Set(['centroidPath']);
const METHOD_METRICS = ['percentScutoids', 'scutoids', 'validCells', 'excludedCells', 'meanTransitions', 'meanWon', 'meanLost', 'meanNeighbours3D'] as const;

/** Layers between the seeded and the other surface: as many as the stack has (sheetOffsets). */
function stackLayerCount(config: Config): number {
  return sheetOffsets(config).length - 2;
}

/** Surface names of the stack as they appear in column names (no spaces). */
export function surfaceColumnNames(config: Config): string[] {
  const { seeded } = config.sheet;
  const layers = stackLayerCount(config);
  const other = seeded === 'basal' ? 'apical' : 'basal';
  return [seeded, ...Array.from({ length: layers }, (_, k) => `layer${k + 1}`), other];
}

function surfaceColumns(method: string, surface: string): string[] {
  return [`${method}.${surface}.meanSides`, ...SIDE_CLASSES.map((c) => `${method}.${surface}.polygons.${c}`)];
}

/**
 * Methods a run of `config` may report on any renderer: the engine policy picks the exact
 * engine only on software renderers, and a runner that reuses a relaxed seeded surface keeps
 * the engine of the first run sharing it, so a sweep allows both outcomes; resume checks that
 * each method's columns are filled all or none (see resume.ts).
 */
function possibleMethods(config: Config): AdjacencyMethod[] {
  const both = new Set([...methodsOnRenderer(config, { softwareRenderer: false }), ...methodsOnRenderer(config, { softwareRenderer: true })]);
  return ADJACENCY_METHODS.filter((m) => both.has(m));
}

/** The summary columns one run of `config` may fill, in order. */
export function summaryColumns(config: Config): string[] {
  const columns: string[] = [...TOP_COLUMNS];
  for (const method of possibleMethods(config)) {
    columns.push(...METHOD_METRICS.map((m) => `${method}.${m}`));
    for (const surface of surfaceColumnNames(config)) columns.push(...surfaceColumns(method, surface));
  }
  return columns;
}

/**
 * The union of summaryColumns over `configs`, in a canonical order that does not depend on the
 * order of the configs' methods: top columns, then per method (labels, exact) its metrics and
 * its surfaces in order of first appearance.
 */
export function sweepColumns(configs: Iterable<Config>): string[] {
  const surfaces = new Map<string, string[]>(ADJACENCY_METHODS.map((m) => [m, []]));
  const used = new Set<string>();
  for (const config of configs) {
    for (const method of possibleMethods(config)) {
      used.add(method);
      const list = surfaces.get(method)!;
      for (const s of surfaceColumnNames(config)) if (!list.includes(s)) list.push(s);
    }
  }
  const columns: string[] = [...TOP_COLUMNS];
  for (const method of ADJACENCY_METHODS) {
    if (!used.has(method)) continue;
    columns.push(...METHOD_METRICS.map((m) => `${method}.${m}`));
    for (const s of surfaces.get(method)!) columns.push(...surfaceColumns(method, s));
  }
  return columns;
}
