/**
 * A result's headline: the one % scutoids that the page shows in large type, the element
 * reports and `tissue-sheet run` prints, with the method and protocol that made it, how many
 * cells it counts, the regularity (Voronoi k) and, where the geometry fixes it, why. Machine
 * readers take `result.headline` instead of guessing which of `analyses[]` is the headline.
 *
 * One realization: `realizations` is 1 and `ci95` null (a single run has no spread); a headline
 * over realizations (realizations.ts: combineHeadlines, headlineOverRealizations) carries their
 * mean, n, SD and 95 % confidence interval in the same fields, and every realization's % and
 * seed, the first being the realization drawn (the configuration's own seed).
 */
import { headlineMethod, type AdjacencyMethod } from '../config/analysisMethods';
import type { Config } from '../config/types';
import { byConstruction, noValidCells, type ByConstruction } from './byConstruction';
import type { AnalysisRecord } from './record';

export interface Headline {
  /** The analysis it comes from: exact wherever the exact method ran, else labels. */
  readonly method: AdjacencyMethod;
  readonly protocol: 'default' | 'lab';
  /** % of valid cells that are scutoids; null when no cell was valid (nothing to count). */
  readonly percentScutoids: number | null;
  readonly scutoids: number;
  readonly validCells: number;
  readonly cells: number;
  /** Mean apico-basal transitions and 3D neighbours of the valid cells (null: none valid). */
  readonly meanTransitions: number | null;
  readonly meanNeighbours3D: number | null;
  /** Regularity: Voronoi k = Lloyd iterations run + 1 (Voronoi 1 = random sites). */
  readonly voronoiK: number;
  /** Realizations the number is over (1: this run alone). */
  readonly realizations: number;
  /** 95 % confidence interval of the mean over realizations (Student's t); null for one realization. */
  readonly ci95: readonly [number, number] | null;
  /** Standard deviation of % scutoids over the realizations; null for one realization. */
  readonly sd: number | null;
  /** The realizations' seeds, the first being the one drawn (the configuration's own seed). */
  readonly realizationSeeds: readonly number[];
  /** Each realization's % scutoids, in the order of realizationSeeds (null: no valid cell). */
  readonly realizationValues: readonly (number | null)[];
  /** Set when the geometry fixes % scutoids at 0 whatever the sites, with why. */
  readonly byConstruction: ByConstruction | null;
  /** Set when no cell was counted (every cell touches an open end), with what to change. */
  readonly noValidCells: string | null;
  /**
   * Methods `sheet.adjacency` asked for that the run does not report, with why (the exact engine
   * makes no label images: "both" on the exact engine gives the exact method only). Empty when
   * every method asked for is in `analyses`.
   */
  readonly omittedMethods: readonly OmittedMethod[];
}

export interface OmittedMethod {
  readonly method: AdjacencyMethod;
  readonly reason: string;
}

/** The methods `config` asked for that `reported` lacks, and why (see Headline.omittedMethods). */
export function omittedMethods(config: Config, reported: readonly AdjacencyMethod[]): OmittedMethod[] {
  const adjacency = config.sheet.adjacency;
  const asked: AdjacencyMethod[] = adjacency === 'both' ? ['labels', 'exact'] : [adjacency];
  const why =
    config.engine === 'exact'
      ? 'engine "exact" ran Lloyd on the exact Voronoi diagram on the CPU, which makes no label images'
      : 'engine "auto" took the exact engine (Lloyd on the exact Voronoi diagram on the CPU) because the renderer here is software, not a GPU, and that engine makes no label images';
  return asked
    .filter((method) => !reported.includes(method))
    .map((method) => ({
      method,
      reason: method === 'labels' ? `${why}; set engine "gpu" (in the page: Engine, under Advanced) for the labels method` : 'not computed by this run',
    }));
}

/** The omitted methods in one line ("labels method left out: ..."), or null when none was. */
export function describeOmitted(headline: Pick<Headline, 'omittedMethods'> | null): string | null {
  const omitted = headline?.omittedMethods ?? [];
  return omitted.length ? omitted.map((o) => `${o.method} method left out: ${o.reason}`).join('; ') : null;
}

const finiteOrNull = (value: number): number | null => (Number.isFinite(value) ? value : null);

/**
 * The headline of one run: its headline method's summary (see headlineMethod), or null when the
 * run reports no analysis.
 */
export function runHeadline(config: Config, analyses: readonly AnalysisRecord[], lloydIterations: number): Headline | null {
  const method = headlineMethod(analyses.map((a) => a.method));
  const analysis = analyses.find((a) => a.method === method);
  if (!method || !analysis) return null;
  const s = analysis.summary;
  const counted = s.validCells > 0;
  return {
    method,
    protocol: analysis.protocol,
    percentScutoids: counted ? finiteOrNull(s.percentScutoids) : null,
    scutoids: s.scutoids,
    validCells: s.validCells,
    cells: s.cells,
    meanTransitions: counted ? finiteOrNull(s.meanTransitions) : null,
    meanNeighbours3D: counted ? finiteOrNull(s.meanNeighbours3D) : null,
    voronoiK: lloydIterations + 1,
    realizations: 1,
    ci95: null,
    sd: null,
    realizationSeeds: [config.seed],
    realizationValues: [counted ? finiteOrNull(s.percentScutoids) : null],
    byConstruction: byConstruction(config),
    noValidCells: noValidCells(s.validCells, s.cells),
    omittedMethods: omittedMethods(
      config,
      analyses.map((a) => a.method),
    ),
  };
}

/** % with one decimal ("–" when there is none). */
const pct = (value: number | null | undefined): string => (typeof value === 'number' && Number.isFinite(value) ? value.toFixed(1) : '–');

/**
 * How many realizations a headline is over, in words: "one realization (seed 1)", or "mean of 5
 * realizations (seeds 1–5), 95 % CI 91.2–94.6 %; realization 1 (seed 1, drawn): 97.8 %".
 */
export function describeRealizations(headline: Headline): string {
  const seeds = headline.realizationSeeds ?? [];
  if (headline.realizations <= 1) return seeds.length ? `one realization (seed ${seeds[0]})` : 'one realization';
  const first = seeds[0];
  const last = seeds[seeds.length - 1];
  const range = seeds.length > 1 ? ` (seeds ${first}–${last})` : '';
  const ci = headline.ci95 ? `, 95 % CI ${pct(headline.ci95[0])}–${pct(headline.ci95[1])} %` : '';
  const drawn = seeds.length ? `; realization 1 (seed ${first}, drawn): ${pct(headline.realizationValues?.[0])} %` : '';
  return `mean of ${headline.realizations} realizations${range}${ci}${drawn}`;
}

/**
 * The headline in one line of words, for logs and exports:
 * "92.9 % scutoids (exact method, 200 of 200 cells counted; mean of 10 realizations (seeds 1–10),
 * 95 % CI 91.2–94.6 %; realization 1 (seed 1, drawn): 97.8 %), Voronoi 51".
 */
export function describeHeadline(headline: Headline | null): string {
  if (!headline) return 'no analysis';
  const value = headline.percentScutoids === null ? 'no % scutoids' : `${headline.percentScutoids.toFixed(1)} % scutoids`;
  const protocol = headline.protocol === 'lab' ? ", the lab's protocol" : '';
  const why = headline.noValidCells ?? headline.byConstruction?.message ?? null;
  const counted =
    headline.realizations > 1
      ? `${headline.validCells} of ${headline.cells} cells counted in realization 1`
      : `${headline.validCells} of ${headline.cells} cells counted`;
  const omitted = describeOmitted(headline);
  const sentences = [why, omitted && `${omitted.charAt(0).toUpperCase()}${omitted.slice(1)}`]
    .filter((x): x is string => Boolean(x))
    .map((x) => x.replace(/\.$/, ''));
  return `${value} (${headline.method} method${protocol}, ${counted}; ${describeRealizations(headline)}), Voronoi ${headline.voronoiK}${sentences.map((x) => `. ${x}`).join('')}`;
}
