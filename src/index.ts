/**
 * `tissue-sheet`: the library's public entry. Browser-safe: nothing here imports a Node module
 * or headless-gl, so a bundler can take it for a web page; Node-only pieces (a headless WebGL2
 * context, PNG files from disk) are in `tissue-sheet/node`.
 *
 *   import { runSheet, validateAnyConfig, createCanvasContext } from 'tissue-sheet';
 *   const { result } = await runSheet(validateAnyConfig(json), createCanvasContext());
 *
 * The `<tissue-sheet>` element is not defined by importing this module (its class extends
 * HTMLElement, which Node lacks): import `tissue-sheet/element`, or call
 * `defineTissueSheetElement()` in a browser.
 */

// The pipeline, its GPU contexts and its result types (one shape for every surface).
export * from './run/index';

// The configuration: JSON Schema, types, validation with one-line errors, feasibility checks.
export * from './core/config/index';
export type { GrayImage } from './core/density';

// The headline over realizations (the mean % scutoids with its 95 % CI and n), as the page, the
// element and `tissue-sheet run --realizations N` compute it.
export { describeHeadline, describeRealizations, type OmittedMethod } from './core/analysis/headline';
export {
  combineHeadlines,
  DEFAULT_REALIZATIONS,
  headlineOverRealizations,
  meanInterval,
  realizationSeed,
  realizationSeeds,
  tQuantile975,
} from './core/analysis/realizations';

// Parameter sweeps: expansion, tidy CSV rows, aggregation and the resumable loop. (Their
// generic `Config` record is not re-exported: it would shadow the run configuration's type.)
export {
  aggregateRows,
  aggregateToCsv,
  aggregateToJson,
  expandSweep,
  flattenSummary,
  formatCsv,
  parseCsv,
  readCsvTable,
  remainingRuns,
  runSweep,
  variedFields,
  type Aggregate,
  type RunSweepOptions,
  type RunSweepResult,
  type SweepProgress,
  type SweepRun,
  type SweepRunner,
  type SweepSpec,
} from './core/sweep/index';

// The element's types; its class and registration load with `defineTissueSheetElement`.
export type { TissueSheetElement } from './element/TissueSheetElement';
export type {
  TissueSheetErrorDetail,
  TissueSheetEventMap,
  TissueSheetProgressDetail,
  TissueSheetResultDetail,
} from './element/events';

export { version } from './version';

/**
 * Defines `<tissue-sheet>` (once) and returns its class. A dynamic import, so that importing
 * the library in Node, where HTMLElement does not exist, does not evaluate the element.
 */
export async function defineTissueSheetElement(): Promise<typeof import('./element/TissueSheetElement').TissueSheetElement> {
  const { TissueSheetElement } = await import('./element/index');
  return TissueSheetElement;
}
