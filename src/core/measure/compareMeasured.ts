/**
 * The comparison of `tissue-sheet measure --compare` for a measured result (docs/measure.md,
 * "Comparison with the model"): the model sheet takes the basal layer's size, pixel size,
 * periodicity and label count, the basal polygon distribution, the number of layers and the
 * surface ratio, exactly as the CLI passes them to compareWithModel.
 */
import { compareWithModel, type ModelComparison } from './compare';
import type { MeasuredResult } from './measuredResult';

export interface CompareMeasuredOptions {
  readonly realizations: number;
  readonly seed: number;
  readonly onProgress?: (line: string) => void;
}

/** Null comparison with a note when the basal layer has nothing to compare (no valid cell, fewer than 3 labels). */
export function compareMeasured(
  result: MeasuredResult,
  options: CompareMeasuredOptions,
): { comparison: ModelComparison; note: null } | { comparison: null; note: string } {
  const basal = result.inputs.layers[0];
  const summary = result.analyses[0].summary;
  if (summary.validCells === 0 || basal.labels < 3) {
    return { comparison: null, note: 'no comparison with the model: the basal layer has no valid cell' };
  }
  const comparison = compareWithModel({
    width: basal.width,
    height: basal.height,
    pixelSize: result.inputs.pixelSize.value,
    periodicX: result.inputs.options.periodicX,
    cells: basal.labels,
    distribution: summary.perSurface[0].polygonDistribution,
    layers: result.inputs.layers.length,
    surfaceRatio: result.surfaceRatio.value,
    realizations: options.realizations,
    seed: options.seed,
    onProgress: options.onProgress,
  });
  return { comparison, note: null };
}
