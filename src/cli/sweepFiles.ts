/**
 * What `sweep` and `merge` share: the layout of a spec's runs.csv (header and the columns each
 * grid point fills), the order rows are written in, and the aggregate files (aggregate.csv,
 * aggregate.json with the Flintstones fits, flintstones.csv), so a merged directory is written
 * exactly as the unsharded sweep's.
 */
import { execFile } from 'node:child_process';
import { lstatSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import { validateConfig, type Config } from '../core/config';
import {
  aggregateColumns,
  aggregateRows,
  aggregateToCsv,
  aggregateToJson,
  baseColumns,
  expandSweep,
  flintstonesToCsv,
  geometryColumns,
  geometryValues,
  orderForReuse,
  sortRowsByRuns,
  summaryColumns,
  sweepColumns,
  sweepFlintstones,
  TEXT_COLUMNS,
  variedFields,
  type FlintstonesFitter,
  type ResumeSpec,
  type SweepRun,
  type ValidSweepSpec,
} from '../core/sweep';
import { seededKey } from '../run/index';
import { InputError } from './errors';
import { writeFileAtomic } from './output';

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

/**
 * Writes aggregate.csv, aggregate.json ({ points, flintstones }) and, when some group can be
 * fitted, flintstones.csv. Rows are taken in write order first, so the aggregate does not depend
 * on the order runs finished or shards were merged in. `fit`: how a group's points are fitted
 * (default sweepFitter; the sweep passes fits its threads made, core/sweep/fitOutcomes.ts).
 */
export async function writeAggregates(
  out: string,
  rows: readonly Record<string, string>[],
  layout: SweepLayout,
  log: (line: string) => void,
  fit?: FlintstonesFitter | Promise<FlintstonesFitter | undefined>,
): Promise<{ flintstones: number }> {
  const sorted = sortRowsByRuns(rows, layout.ordered);
  const numeric = aggregateColumns(layout.summary, TEXT_COLUMNS);
  // The aggregate while the fits (a promise: the sweep's threads) are computed elsewhere.
  const aggregate = aggregateRows(sorted, layout.fields, numeric);
  for (const point of aggregate.points) {
    const partial = Object.entries(point.stats).filter(([, s]) => s.n > 0 && s.missing > 0);
    for (const [column, s] of partial.slice(0, 3)) {
      log(
        `warning: ${
          Object.entries(point.point)
            .map(([f, v]) => `${f}=${v}`)
            .join(' ') || 'all runs'
        }: ${column} has ${s.missing} of ${point.runs} values that are not finite numbers (not counted: n = ${s.n})`,
      );
    }
  }
  const aggregateCsv = aggregateToCsv(aggregate);
  const points = aggregateToJson(aggregate);
  const fits = sweepFlintstones(sorted, layout.runs, layout.fields, await fit);
  const fitted = fits.filter((f) => f.parameters !== null);
  for (const fit of fits.filter((f) => f.illConditioned).slice(0, 3)) {
    log(
      `warning: Flintstones law, Voronoi ${fit.voronoi}${Object.entries(fit.group)
        .map(([f, v]) => ` ${f}=${v}`)
        .join('')}: ${fit.parameters ? 'ill-conditioned' : 'not fitted'} (${fit.note})`,
    );
  }
  writeFileAtomic(join(out, 'aggregate.csv'), aggregateCsv);
  writeFileAtomic(join(out, 'aggregate.json'), JSON.stringify({ points, flintstones: fits }, null, 2) + '\n');
  if (fitted.length > 0) writeFileAtomic(join(out, 'flintstones.csv'), flintstonesToCsv(fits, layout.fields));
  return { flintstones: fitted.length };
}

/**
 * The text of a sweep directory's runs.csv, or null when there is none. Anything but a regular
 * file there (a directory, a device) is refused by name (exit 2), never read.
 */
export function readRunsFile(path: string): string | null {
  let stat;
  try {
    stat = lstatSync(path);
  } catch {
    return null;
  }
  if (stat.isSymbolicLink()) throw new InputError(`${path}: is a symbolic link, which is never followed; remove it`);
  if (stat.isDirectory()) throw new InputError(`${path}: is a directory, not a runs file; move it away (a sweep writes its rows to this path)`);
  if (!stat.isFile()) throw new InputError(`${path}: is not a regular file; move it away (a sweep writes its rows to this path)`);
  return readFileSync(path, 'utf8');
}

/**
 * The git commit of the checkout the CLI runs from, when it is one (null otherwise), from a `git`
 * process the caller need not wait for: a sweep starts it first and reads it when it writes
 * sweep.json, so the process runs beside the sweep's start.
 */
export function gitCommitSoon(): Promise<string | null> {
  return new Promise((resolve) => {
    try {
      execFile('git', ['rev-parse', 'HEAD'], { cwd: dirname(fileURLToPath(import.meta.url)), encoding: 'utf8', timeout: 2000 }, (error, stdout) =>
        resolve(error ? null : stdout.trim() || null),
      );
    } catch {
      resolve(null);
    }
  });
}
