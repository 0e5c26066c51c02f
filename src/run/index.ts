/**
 * The pipeline's public face: what its consumers (the CLI, `<tissue-sheet>`, the app) import.
 * Consumers never reach into src/gpu or each other; they take the pipeline, its context
 * factories and its result types from here.
 */
export { runSheet, SheetRunner, seededKey, type RunInputs, type RunOptions } from './runSheet';
export { sweepSummary, sweepSummaryValues } from './sweepSummary';
export { decodeCellsFile, withCellRecords, type CellsFileRecord, type ResultCellTables } from './cellTables';
export { WorkerSheetRunner, type ComputeSite } from './worker/workerRunner';
export { describeEngine, type EngineChoice } from './enginePolicy';
export { fetchMeshFile, type MeshFile } from './closedMesh';
export type {
  AnalysisRecord,
  CellRecord,
  CellStatisticsRecord,
  ClosedSurfaceRecord,
  GridRecord,
  Headline,
  LabelImage,
  NeighbourContact,
  SheetOutput,
  SheetResult,
  SurfaceRecord,
} from './result';
export { createCanvasContext, GpuCapabilityError, type GpuCapabilities, type GpuContext } from '../gpu/context';
export type { IterationRecord } from '../gpu/lloyd';
