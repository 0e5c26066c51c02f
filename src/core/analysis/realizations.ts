/**
 * The headline over several realizations: the same configuration run with n seeds, the mean %
 * scutoids with its 95 % confidence interval (Student's t interval of the mean), n, and the
 * realization that is drawn (the configuration's own seed) named as one of them.
 *
 * Seeds: realization r (1..n) runs with seed `config.seed + r - 1` (mod 2^32), so realization 1
 * is the configuration itself (the one drawn) and every realization is reproducible by a link
 * or a config file with its seed. The page, the element and `tissue-sheet run --realizations N`
 * all use these functions, so they report the same number for the same configuration and n.
 */
import type { Headline } from './headline';

/** Realizations the headline is over unless asked otherwise: quick enough for a first result. */
export const DEFAULT_REALIZATIONS = 5;
/** The most realizations one headline is computed over (the page's control, the CLI, the element). */
export const MAX_REALIZATIONS = 100;

/** The seed of realization `r` (1-based) of a configuration seeded with `seed`. */
export function realizationSeed(seed: number, r: number): number {
  return (seed + r - 1) % 4294967296;
}

/** The seeds of realizations 1..n (the first is `seed` itself). */
export function realizationSeeds(seed: number, n: number): number[] {
  return Array.from({ length: n }, (_, k) => realizationSeed(seed, k + 1));
}

/** Checks a number of realizations (an integer from 1 to MAX_REALIZATIONS); returns it or throws with words. */
export function checkRealizations(n: unknown, name = 'realizations'): number {
  const value = typeof n === 'string' && n.trim() !== '' ? Number(n) : n;
  if (typeof value !== 'number' || !Number.isInteger(value) || value < 1 || value > MAX_REALIZATIONS) {
    throw new RangeError(`${name}: must be a whole number of realizations from 1 to ${MAX_REALIZATIONS} (got ${JSON.stringify(n)})`);
  }
  return value;
}

/** t(0.975, df) for df = 1 .. 30 (the aggregate asks for it per column and grid point). */
const T975 = [
  12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228, 2.201, 2.179, 2.16, 2.145, 2.131, 2.12, 2.11, 2.101, 2.093, 2.086, 2.08, 2.074, 2.069,
  2.064, 2.06, 2.056, 2.052, 2.048, 2.045, 2.042,
];

/** Two-sided 97.5 % quantile of Student's t with `df` degrees of freedom (for 95 % intervals). */
export function tQuantile975(df: number): number {
  if (!(df >= 1)) return Number.NaN;
  if (df <= T975.length) return T975[Math.floor(df) - 1];
  // Cornish-Fisher expansion around the normal quantile: within 1e-3 for df > 30.
  const z = 1.959964;
  return z + (z ** 3 + z) / (4 * df) + (5 * z ** 5 + 16 * z ** 3 + 3 * z) / (96 * df ** 2);
}

export interface MeanInterval {
  readonly n: number;
  readonly mean: number;
  /** Sample standard deviation (n - 1); NaN for n < 2. */
  readonly sd: number;
  /** 95 % confidence interval of the mean (t distribution), clamped to [min, max]; null for n < 2. */
  readonly ci95: readonly [number, number] | null;
}

/** Mean, SD and 95 % CI of the mean of `values`, the interval clamped to [min, max]. */
export function meanInterval(values: readonly number[], min = 0, max = 100): MeanInterval {
  const n = values.length;
  if (n === 0) return { n, mean: Number.NaN, sd: Number.NaN, ci95: null };
  const mean = values.reduce((a, b) => a + b, 0) / n;
  if (n < 2) return { n, mean, sd: Number.NaN, ci95: null };
  const sd = Math.sqrt(values.reduce((a, v) => a + (v - mean) ** 2, 0) / (n - 1));
  const half = tQuantile975(n - 1) * (sd / Math.sqrt(n));
  const clamp = (x: number) => Math.min(max, Math.max(min, x));
  return { n, mean, sd, ci95: [clamp(mean - half), clamp(mean + half)] };
}

const mean = (values: readonly number[]): number | null => (values.length ? values.reduce((a, b) => a + b, 0) / values.length : null);

/**
 * One headline over realizations: `headlines[0]` is the realization drawn (the configuration's
 * own seed), `seeds[k]` the seed of `headlines[k]`. % scutoids, mean transitions and mean 3D
 * neighbours are the means over the realizations that counted cells (a realization with no
 * valid cell has no %); `ci95` is the t interval of the mean % (null below two such
 * realizations); `scutoids`, `validCells` and `cells` are the drawn realization's counts;
 * `realizationValues` lists every realization's % in seed order. Throws when the realizations
 * were not made by one method and protocol (they are the same configuration but for the seed).
 */
export function combineHeadlines(headlines: readonly Headline[], seeds: readonly number[]): Headline {
  if (headlines.length === 0) throw new Error('combineHeadlines: no realization');
  if (seeds.length !== headlines.length) throw new Error('combineHeadlines: one seed per realization');
  const drawn = headlines[0];
  for (const h of headlines) {
    if (h.method !== drawn.method || h.protocol !== drawn.protocol) {
      throw new Error(`combineHeadlines: realizations made by different methods (${drawn.method}/${drawn.protocol}, ${h.method}/${h.protocol})`);
    }
  }
  const values = headlines.map((h) => h.percentScutoids);
  const counted = values.filter((v): v is number => v !== null);
  const interval = meanInterval(counted);
  const pick = (key: 'meanTransitions' | 'meanNeighbours3D') => mean(headlines.map((h) => h[key]).filter((v): v is number => v !== null));
  return {
    ...drawn,
    percentScutoids: counted.length ? interval.mean : null,
    meanTransitions: pick('meanTransitions'),
    meanNeighbours3D: pick('meanNeighbours3D'),
    realizations: headlines.length,
    ci95: interval.ci95,
    sd: Number.isFinite(interval.sd) ? interval.sd : null,
    realizationSeeds: [...seeds],
    realizationValues: values,
    noValidCells: counted.length ? null : drawn.noValidCells,
  };
}

/**
 * The headline of a configuration over `n` realizations: `drawn` is realization 1's (the run
 * already made with the configuration's seed), `runOne(seed)` runs the configuration with
 * another seed and gives its headline. Runs one after another (realization 2, 3, ...), calling
 * `onProgress(done, n)` after each; returns `drawn` unchanged when n is 1 or it has no headline.
 * A realization without a headline (no analysis) throws: the configurations differ only in seed.
 */
export async function headlineOverRealizations(
  seed: number,
  n: number,
  drawn: Headline | null,
  runOne: (seed: number) => Promise<Headline | null>,
  onProgress?: (done: number, n: number) => void,
): Promise<Headline | null> {
  if (!drawn || n <= 1) return drawn;
  const seeds = realizationSeeds(seed, n);
  const headlines: Headline[] = [drawn];
  onProgress?.(1, n);
  for (let k = 1; k < n; k++) {
    const headline = await runOne(seeds[k]);
    if (!headline) throw new Error(`realization ${k + 1} (seed ${seeds[k]}) gave no analysis`);
    headlines.push(headline);
    onProgress?.(k + 1, n);
  }
  return combineHeadlines(headlines, seeds);
}
