/**
 * What `sweep` and `merge` share beside the layout of a spec's runs (src/run/sweepLayout.ts, also
 * the page's): the aggregate files (aggregate.csv, aggregate.json with the Flintstones fits,
 * flintstones.csv), so a merged directory is written exactly as the unsharded sweep's, runs.csv's
 * reader and the commit a sweep records.
 */
import { execFile } from 'node:child_process';
import { lstatSync, readFileSync } from 'node:fs';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';
import {
  aggregateColumns,
  aggregateRows,
  aggregateToCsv,
  aggregateToJson,
  flintstonesToCsv,
  sortRowsByRuns,
  sweepFlintstones,
  TEXT_COLUMNS,
  type FlintstonesFitter,
} from '../core/sweep';
import type { SweepLayout } from '../run/sweepLayout';
import { InputError } from './errors';
import { writeFileAtomic } from './output';

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
