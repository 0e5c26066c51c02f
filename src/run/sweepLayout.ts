/**
 * The layout of a sweep spec's runs, shared by `tissue-sheet sweep`, `merge` and the page's
 * sweeps (src/view/pageSweep.ts), so they expand, check, order and write a spec alike: every grid
 * point's config (validated once per point), runs.csv's header and the columns each point fills,
 * the order rows are written in (runs sharing a seeded surface together) and what a resume reads.
 */
import { validateConfig, type Config } from '../core/config';
import {
  baseColumns,
  expandSweep,
  geometryColumns,
  geometryValues,
  orderForReuse,
  summaryColumns,
  sweepColumns,
  TEXT_COLUMNS,
  variedFields,
  type ResumeSpec,
  type SweepRun,
  type ValidSweepSpec,
} from '../core/sweep';
import { seededKey } from './runSheet';

export type Run = SweepRun<Config & Record<string, unknown>>;

export interface SweepLayout {
  readonly fields: string[];
  /** Every run of the spec, in grid order. */
  readonly runs: Run[];
  /** Every run in the order rows are written (runs sharing a seeded surface together). */
  readonly ordered: Run[];
  /** Summary columns of runs.csv (the union over the grid): what a run measured. */
  readonly summary: string[];
  /** The base geometry columns (config paths that are not varied: units.ts), before the summary. */
  readonly geometry: string[];
  /** A run's geometry values (by plain column name), added to its summary. */
  readonly geometryOf: (run: Run) => Record<string, string | number | boolean>;
  readonly header: string[];
  /** Runs with the same group share a relaxed seeded surface (SheetRunner reuses it). */
  readonly reuseGroup: (run: Run) => string;
  /** A run's grid point's config as `pointConfig` validated it (the same for all its runs but for `seed`). */
  readonly pointConfigOf: (run: Run) => Config;
  /** Every grid point's config, by point key, in grid order. */
  readonly pointConfigs: ReadonlyMap<string, Config>;
  readonly resume: ResumeSpec<Config & Record<string, unknown>>;
}

/**
 * The layout of a spec's sweep. `pointConfig` validates (and may check) one grid point's config;
 * it is called once per grid point, in grid order.
 */
export function sweepLayout(spec: ValidSweepSpec, pointConfig: (run: Run) => Config = (run) => validateConfig(run.config)): SweepLayout {
  const fields = variedFields(spec);
  const runs = expandSweep(spec) as Run[];
  const configs = new Map<string, Config>();
  for (const run of runs) if (!configs.has(run.pointKey)) configs.set(run.pointKey, pointConfig(run));
  // Every column a point may fill (the engine, and so the methods, can depend on the renderer).
  const summary = sweepColumns(configs.values());
  const geometry = geometryColumns(configs.values(), fields);
  const header = [...baseColumns(fields), ...geometry.columns, ...summary];
  const values = new Map([...configs].map(([key, config]) => [key, geometryValues(config, fields)]));
  const filled = new Map([...configs].map(([key, config]) => [key, new Set([...Object.keys(values.get(key)!), ...summaryColumns(config)])]));
  const reuseGroup = seedGroups((run) => configs.get(run.pointKey)!, seededKey);
  const ordered = orderForReuse(runs, reuseGroup);
  return {
    fields,
    runs,
    ordered,
    summary,
    geometry: geometry.columns,
    geometryOf: (run) => values.get(run.pointKey)!,
    header,
    reuseGroup,
    pointConfigOf: (run) => configs.get(run.pointKey)!,
    pointConfigs: configs,
    resume: {
      header,
      fields,
      runs,
      filledColumns: (run) => filled.get(run.pointKey)!,
      textColumns: new Set([...TEXT_COLUMNS, ...geometry.text]),
      pointValues: (run) => values.get(run.pointKey)!,
    },
  };
}

/**
 * A grouping of runs by `keyOf` of their configs (seededKey, chainKey: JSON texts of most of a
 * config): two runs get the same key exactly when `keyOf` gives the same text for them. A grid
 * point's runs differ in their seed only, so `keyOf` is computed once per grid point, with seed
 * 0, and a run's key is that text's number and the run's seed (a text of a kilobyte per run was
 * made and hashed 2,400 times per key at the published grid's start).
 */
export function seedGroups(pointConfigOf: (run: Run) => Config, keyOf: (config: Config) => string): (run: Run) => string {
  const byPoint = new Map<string, number>();
  const byText = new Map<string, number>();
  return (run) => {
    let id = byPoint.get(run.pointKey);
    if (id === undefined) {
      const text = keyOf({ ...pointConfigOf(run), seed: 0 });
      id = byText.get(text);
      if (id === undefined) byText.set(text, (id = byText.size));
      byPoint.set(run.pointKey, id);
    }
    return `${id}#${run.seed}`;
  };
}
