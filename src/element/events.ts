/** The element's events and their typed `detail`. */
import type { Headline, SheetResult } from '../run';
import type { PageSweepProgress, PageSweepResult } from '../view/pageSweep';

export interface TissueSheetProgressDetail {
  /** 1-based Lloyd iteration just finished. */
  iteration: number;
  maxIterations: number;
  /** CVT energy before the iteration's move, µm⁴. */
  energy: number;
  /** Largest site displacement of the iteration, µm. */
  maxDisplacement: number;
}

export interface TissueSheetResultDetail {
  /** The documented result JSON (the same document `tissue-sheet run` writes). */
  result: SheetResult;
  /**
   * `result.headline`: the number shown, with its method, counts, Voronoi k and uncertainty: the
   * mean % scutoids over `realizations` (the attribute, default 5) with its 95 % CI (`ci95`), SD,
   * every realization's seed and %, the first being the one drawn (the configuration's seed).
   */
  headline: Headline | null;
  /**
   * % scutoids of the cells shown (realization 1, the configuration's own seed), by the headline's
   * method: exact wherever it ran, else labels (NaN when no cell was counted). The mean over the
   * realizations is `headline.percentScutoids`.
   */
  percentScutoids: number;
  /** Which adjacency method `percentScutoids` comes from. */
  method: 'labels' | 'exact';
  /** Why the value is fixed by the geometry (s = 1, thickness 0, parallel planes, concentric spheres), when it is. */
  byConstruction?: string;
}

export interface TissueSheetErrorDetail {
  /** One line, in words: what went wrong and what to change. */
  message: string;
  /** "ConfigError", "GpuCapabilityError", or another error's name. */
  name: string;
  /** The config field at fault, for a ConfigError. */
  field?: string;
}

/** After every finished run of `sweep()`: counts, the run (key, point, seed) and its runs.csv row. */
export type TissueSheetSweepProgressDetail = PageSweepProgress;

export interface TissueSheetSweepOptions {
  /** Aborting stops the sweep after the run in flight; the finished runs are returned. */
  signal?: AbortSignal;
  /** runs.csv of an earlier run of the same spec: its runs are kept, the others computed. */
  resume?: string;
  /** Web Workers to spread the runs over (1 to 8); default: the browser's cores less one for the page, at least 1. */
  workers?: number;
}

/**
 * What `sweep()` resolves with: runs.csv's `header` and rows (`runs`, text cells, resumed ones
 * first), the CLI's `aggregate` (mean, sd, se, n per grid point and aggregated metric, docs/sweep.md "Aggregates"), both files'
 * text, how many runs were `completed` and `skipped`, whether the signal `aborted` it, and how
 * many pipeline `workers` (Web Workers) the runs were spread over.
 */
export type TissueSheetSweepResult = Pick<
  PageSweepResult,
  'header' | 'runs' | 'aggregate' | 'runsCsv' | 'aggregateCsv' | 'completed' | 'skipped' | 'aborted' | 'workers'
>;

/**
 * `cell-hover`: the cell under the pointer in the 3D view (at most one per animation frame, only
 * when it changes; `null` when the pointer leaves the sheet or starts dragging the camera).
 * `surface` is the index in the stack (0 = seeded).
 */
export type TissueSheetCellHoverDetail = { cell: number; surface: number } | null;

/** `waiting`: a run waits for the user's click to load a source from another origin. */
export interface TissueSheetWaitingDetail {
  sources: { path: string; host: string }[];
}

/**
 * `warning`: something the element did not take or could not do as asked, in words: an attribute
 * it does not know (ignored; `attribute`, and `suggestion` when one is close), or runs falling
 * back from the worker to the page (`computeSite: { where: 'page', reason }`).
 */
export interface TissueSheetWarningDetail {
  message: string;
  attribute?: string;
  suggestion?: string;
}

export interface TissueSheetEventMap {
  waiting: CustomEvent<TissueSheetWaitingDetail>;
  warning: CustomEvent<TissueSheetWarningDetail>;
  'cell-hover': CustomEvent<TissueSheetCellHoverDetail>;
  progress: CustomEvent<TissueSheetProgressDetail>;
  'sweep-progress': CustomEvent<TissueSheetSweepProgressDetail>;
  result: CustomEvent<TissueSheetResultDetail>;
  error: CustomEvent<TissueSheetErrorDetail>;
}
