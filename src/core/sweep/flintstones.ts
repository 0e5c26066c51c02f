/**
 * The Flintstones law (Gómez-Gálvez et al. 2022; src/core/analysis/flintstones.ts) fitted in a
 * sweep's aggregate: n3D(s) against the surface ratio s, one fit per Voronoi k
 * (= lloyd.maxIterations + 1) and per combination of the other varied fields.
 *
 * - Applies to tubes with `sheet.surfaceRatio` set, where the group has more distinct ratios
 *   than free parameters (4 with the anchor n3D(1) = 6 of the lab's fit); other groups get no fit.
 * - Data: every run's mean 3D neighbours (`exact.meanNeighbours3D`, or where a group has no exact
 *   value, `labels.meanNeighbours3D`), unweighted, so the standard errors include the scatter
 *   between realizations (fitting the per-ratio means with equal counts gives the same
 *   parameters, and standard errors that ignore that scatter).
 * - Ill-conditioned: the fit did not converge, a standard error is not finite, or a standard
 *   error exceeds its parameter's magnitude (the data do not pin it down, e.g. ratios that stop
 *   before the curve bends); the parameters are still written, flagged, with the reason.
 */
import { fitFlintstones, type FlintstonesFit, type FlintstonesParameters, type FlintstonesPoint } from '../analysis/flintstones';
import { validateConfig } from '../config';
import { formatCsv } from './csv';
import type { ConfigObject, SweepRun } from './expand';
import { getPath, valueText } from './expand';

export const FLINTSTONES_RATIO = 'sheet.surfaceRatio';
const FLINTSTONES_METRICS = ['exact.meanNeighbours3D', 'labels.meanNeighbours3D'] as const;
/** n3D(1) of the lab's fit (fittingLogFunc.m). */
const FLINTSTONES_ANCHOR = 6;
const FREE_PARAMETERS = 3;

export interface SweepFlintstonesFit {
  /** The varied fields other than the ratio (and the Voronoi k), as CSV text. */
  readonly group: Record<string, string>;
  /** lloyd.maxIterations + 1. */
  readonly voronoi: number;
  readonly metric: string;
  /** Runs fitted (points), over `ratios` distinct ratios. */
  readonly points: number;
  readonly ratios: number;
  readonly anchor: number;
  readonly parameters: FlintstonesParameters | null;
  /** Standard errors of nMax, c, d (b is fixed by the anchor: null). */
  readonly standardErrors: { nMax: number | null; c: number | null; d: number | null } | null;
  readonly rSquared: number | null;
  readonly chiSquared: number | null;
  readonly degreesOfFreedom: number | null;
  readonly converged: boolean;
  readonly illConditioned: boolean;
  /** Why it is ill-conditioned or why no fit was made; empty when well-conditioned. */
  readonly note: string;
}

const finiteOrNull = (x: number): number | null => (Number.isFinite(x) ? x : null);

/** Fits the law to one group's points (s, n3D) with the sweep's anchor; throws as fitFlintstones does. */
export type FlintstonesFitter = (points: readonly FlintstonesPoint[]) => FlintstonesFit;

/** The sweep's fit of one group's points: fitFlintstones with the lab's anchor. */
export const sweepFitter: FlintstonesFitter = (points) => fitFlintstones(points, { anchor: FLINTSTONES_ANCHOR });

/**
 * One fit per Voronoi k and combination of the other varied fields (see the module comment).
 * `rows` are runs.csv rows (key, fields, metrics as text), `runs` the expanded spec (for each
 * row's configuration). Groups are in order of first appearance in `rows`. `fit` fits a group's
 * points (sweepFitter; the CLI passes one that takes fits computed on its threads from the same
 * points, see flintstonesProblems).
 */
export function sweepFlintstones<C extends ConfigObject>(
  rows: readonly Record<string, string>[],
  runs: readonly SweepRun<C>[],
  fields: readonly string[],
  fit: FlintstonesFitter = sweepFitter,
): SweepFlintstonesFit[] {
  return flintstonesGroups(rows, runs, fields).map(({ group, voronoi, rows: members }) => fitGroup(group, voronoi, members, fit));
}

/**
 * The points each fit of sweepFlintstones(rows, runs, fields) is given, in its order, for the
 * groups that are fitted: so they can be fitted elsewhere (the CLI's threads) beforehand.
 */
export function flintstonesProblems<C extends ConfigObject>(
  rows: readonly Record<string, string>[],
  runs: readonly SweepRun<C>[],
  fields: readonly string[],
): FlintstonesPoint[][] {
  return flintstonesGroups(rows, runs, fields)
    .map(({ rows: members }) => groupPoints(members))
    .filter(({ ratios }) => ratios > FREE_PARAMETERS)
    .map(({ points }) => points);
}

type GroupRows = { group: Record<string, string>; voronoi: number; rows: { s: number; row: Record<string, string> }[] };

function flintstonesGroups<C extends ConfigObject>(
  rows: readonly Record<string, string>[],
  runs: readonly SweepRun<C>[],
  fields: readonly string[],
): GroupRows[] {
  const byKey = new Map(runs.map((r) => [r.key, r]));
  // Validated (defaults filled in: lloyd.maxIterations need not be in the spec), once per grid point.
  const configs = new Map<string, unknown>();
  const configOf = (run: SweepRun<C>) => {
    if (!configs.has(run.pointKey)) configs.set(run.pointKey, validateConfig(run.config));
    return configs.get(run.pointKey);
  };
  const groupFields = fields.filter((f) => f !== FLINTSTONES_RATIO && f !== 'lloyd.maxIterations');
  const groups = new Map<string, GroupRows>();
  for (const row of rows) {
    const run = byKey.get(row.key);
    if (!run) continue;
    const config = configOf(run);
    const surface = getPath(config, 'surface.kind');
    const s = getPath(config, FLINTSTONES_RATIO);
    const iterations = getPath(config, 'lloyd.maxIterations');
    if (surface !== 'tube' || typeof s !== 'number' || typeof iterations !== 'number') continue;
    const group: Record<string, string> = {};
    for (const f of groupFields) group[f] = valueText(run.point[f]);
    const id = JSON.stringify([iterations, groupFields.map((f) => group[f])]);
    let entry = groups.get(id);
    if (!entry) groups.set(id, (entry = { group, voronoi: iterations + 1, rows: [] }));
    entry.rows.push({ s, row });
  }
  return [...groups.values()];
}

/** A group's metric and points (runs with a finite value of it, in row order). */
function groupPoints(members: GroupRows['rows']): { metric: string; points: FlintstonesPoint[]; ratios: number } {
  const valueOf = (row: Record<string, string>, metric: string) => (row[metric] === undefined || row[metric] === '' ? NaN : Number(row[metric]));
  const metric = FLINTSTONES_METRICS.find((m) => members.some(({ row }) => Number.isFinite(valueOf(row, m)))) ?? FLINTSTONES_METRICS[0];
  const points = members.map(({ s, row }) => ({ s, n: valueOf(row, metric) })).filter((p) => Number.isFinite(p.n));
  return { metric, points, ratios: new Set(points.map((p) => p.s)).size };
}

function fitGroup(group: Record<string, string>, voronoi: number, members: GroupRows['rows'], fitter: FlintstonesFitter): SweepFlintstonesFit {
  const { metric, points, ratios } = groupPoints(members);
  const empty = {
    group,
    voronoi,
    metric,
    points: points.length,
    ratios,
    anchor: FLINTSTONES_ANCHOR,
    parameters: null,
    standardErrors: null,
    rSquared: null,
    chiSquared: null,
    degreesOfFreedom: null,
    converged: false,
    illConditioned: true,
  };
  if (ratios <= FREE_PARAMETERS) {
    return { ...empty, note: `${ratios} distinct surface ratios with values; the law needs at least ${FREE_PARAMETERS + 1}` };
  }
  let fit;
  try {
    fit = fitter(points);
  } catch (error) {
    return { ...empty, note: `no fit: ${(error as Error).message.replace(/^fitFlintstones: /, '')}` };
  }
  const p = fit.parameters;
  const se = fit.standardErrors;
  const reasons: string[] = [];
  if (!fit.converged) reasons.push('did not converge');
  for (const name of ['nMax', 'c', 'd'] as const) {
    if (!Number.isFinite(se[name])) reasons.push(`${name} standard error not finite`);
    else if (se[name] > Math.abs(p[name]))
      reasons.push(`${name} standard error ${se[name].toPrecision(3)} exceeds |${name}| ${Math.abs(p[name]).toPrecision(3)}`);
  }
  return {
    ...empty,
    parameters: { ...p },
    standardErrors: { nMax: finiteOrNull(se.nMax), c: finiteOrNull(se.c), d: finiteOrNull(se.d) },
    rSquared: finiteOrNull(fit.rSquared),
    chiSquared: finiteOrNull(fit.chiSquared),
    degreesOfFreedom: fit.degreesOfFreedom,
    converged: fit.converged,
    illConditioned: reasons.length > 0,
    note: reasons.join('; '),
  };
}

/** flintstones.csv: the group's fields, voronoi, metric, counts, parameters with SEs, fit quality, flags. */
export function flintstonesToCsv(fits: readonly SweepFlintstonesFit[], fields: readonly string[]): string {
  const groupFields = fields.filter((f) => f !== FLINTSTONES_RATIO && f !== 'lloyd.maxIterations');
  const header = [
    ...groupFields,
    'voronoi',
    'metric',
    'points',
    'ratios',
    'anchor',
    'nMax',
    'nMax.se',
    'c',
    'c.se',
    'd',
    'd.se',
    'b',
    'rSquared',
    'chiSquared',
    'degreesOfFreedom',
    'converged',
    'illConditioned',
    'note',
  ];
  const cell = (x: number | null | undefined): number | string => (x === null || x === undefined || !Number.isFinite(x) ? '' : x);
  const rows = fits.map((f) => [
    ...groupFields.map((g) => f.group[g]),
    f.voronoi,
    f.metric,
    f.points,
    f.ratios,
    f.anchor,
    cell(f.parameters?.nMax),
    cell(f.standardErrors?.nMax),
    cell(f.parameters?.c),
    cell(f.standardErrors?.c),
    cell(f.parameters?.d),
    cell(f.standardErrors?.d),
    cell(f.parameters?.b),
    cell(f.rSquared),
    cell(f.chiSquared),
    cell(f.degreesOfFreedom),
    String(f.converged),
    String(f.illConditioned),
    f.note,
  ]);
  return formatCsv(header, rows);
}
