/**
 * `tissue-sheet`: the library's public entry. Browser-safe: nothing here imports a Node module
 * or headless-gl, so a bundler can take it for a web page; Node-only pieces (a headless WebGL2
 * context, PNG files from disk) are in `tissue-sheet/node`.
 *
 *   import { runSheet, validateConfig, createCanvasContext } from 'tissue-sheet';
 *   const { result } = await runSheet(validateConfig(json), createCanvasContext());
 *
 * The `<tissue-sheet>` element is not defined by importing this module (its class extends
 * HTMLElement, which Node lacks): import `tissue-sheet/element`, or call
 * `defineTissueSheetElement()` in a browser.
 */

// The public API, named one by one (a semver promise each; api/tissue-sheet.api.md lists them
// and `npm run api:check` keeps that report true). Runtime values: at most 30.

// The pipeline, its GPU contexts and its result types (one shape for every surface).
export { runSheet, SheetRunner, sweepSummary, describeEngine, fetchMeshFile, createCanvasContext, GpuCapabilityError } from './run/index';
// A result whose per-cell lists are in a binary side file (RESULT.cells.bin; README "Result JSON").
export { decodeCellsFile, withCellRecords, type CellsFileRecord, type ResultCellTables } from './run/index';
export type {
  AnalysisRecord,
  CellRecord,
  CellStatisticsRecord,
  ClosedSurfaceRecord,
  EngineChoice,
  GpuCapabilities,
  GpuContext,
  GridRecord,
  Headline,
  IterationRecord,
  LabelImage,
  MeshFile,
  NeighbourContact,
  RunInputs,
  RunOptions,
  SheetOutput,
  SheetResult,
  SurfaceRecord,
} from './run/index';
export { describeHeadline } from './core/analysis/headline';
export type { ByConstruction } from './core/analysis/byConstruction';

// The configuration: JSON Schema, types, validation with one-line errors. `Config` is any
// configuration (planes, tubes and closed surfaces); `PlanarConfig` and `ClosedConfig` its two
// layouts. validateConfig fills every default and resolves the resolution; validateConfigDraft
// keeps a default resolution null, as forms and links do.
export { validateConfig, validateConfigDraft, ConfigError, configSchema, defaultResolution, isClosedConfig } from './core/config/index';
export type {
  Config,
  PlanarConfig,
  ClosedConfig,
  ConfigDraft,
  ConfigInput,
  AnySurfaceConfig as SurfaceConfig,
  DensitySpec,
  SheetConfig,
  LloydConfig,
  AdjacencyMethod,
} from './core/config/index';
export type { GrayImage } from './core/density';

// A headline's omitted methods (Headline.omittedMethods). The headline over realizations is
// computed by the page, the element and `tissue-sheet run --realizations N`
// (core/analysis/realizations.ts); the public API stays at 30 runtime values.
export type { OmittedMethod } from './core/analysis/headline';

// Parameter sweeps: the spec, expansion, tidy CSV rows, aggregation and the resumable loop.
export {
  validateSweepSpec,
  SweepSpecError,
  expandSweep,
  runSweep,
  aggregateRows,
  aggregateToCsv,
  aggregateToJson,
  flattenSummary,
  parseCsv,
  formatCsv,
  readCsvTable,
  variedFields,
  type Aggregate,
  type RunSweepOptions,
  type RunSweepResult,
  type SweepProgress,
  type SweepRun,
  type SweepRunner,
  type SweepSpec,
  type ValidSweepSpec,
} from './core/sweep/index';

// The element's types; its class and registration load with `defineTissueSheetElement`.
export type { TissueSheetElement } from './element/TissueSheetElement';
export type {
  TissueSheetCellHoverDetail,
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
