/**
 * The Flintstones fits of a sweep's aggregate computed on the sweep's threads: the fits are
 * independent (one per Voronoi k and group) and take the main thread about half a second or
 * more after the last run, while the threads sit idle. A thread fits a group's points with the
 * same code (sweepFitter) and sends the fit back by structured clone, which keeps every double;
 * writeAggregates then takes a fit from here only for exactly the same points (compared by
 * value, in order) and fits anything else itself, so the files cannot depend on where a fit ran.
 */
import type { FlintstonesFit, FlintstonesPoint } from '../core/analysis/flintstones';
import { sweepFitter, type FlintstonesFitter } from '../core/sweep';

/** A fit, or the message of the error fitting threw (a group the law cannot be fitted to). */
export type FitOutcome = { readonly fit: FlintstonesFit } | { readonly error: string };

/** fitFlintstones' outcome for `points` (what a thread sends back). */
export function fitOutcome(points: readonly FlintstonesPoint[]): FitOutcome {
  try {
    return { fit: sweepFitter(points) };
  } catch (error) {
    return { error: error instanceof Error ? error.message : String(error) };
  }
}

/** The points by value: each number's shortest round-trip text, so equal keys are equal points. */
export function pointsKey(points: readonly FlintstonesPoint[]): string {
  let key = '';
  for (const p of points) key += `${p.s},${p.n},${p.sigma ?? ''};`;
  return key;
}

/** A fitter that takes the outcome computed for the same points, and fits the others itself. */
export function cachedFitter(outcomes: ReadonlyMap<string, FitOutcome>): FlintstonesFitter {
  return (points) => {
    const outcome = outcomes.get(pointsKey(points));
    if (outcome === undefined) return sweepFitter(points);
    if ('error' in outcome) throw new Error(outcome.error);
    return outcome.fit;
  };
}

/** The outcomes computed for `problems` (null: not fitted there), by their points (cachedFitter's map). */
export function fitOutcomes(problems: readonly (readonly FlintstonesPoint[])[], outcomes: readonly (FitOutcome | null)[]): Map<string, FitOutcome> {
  const byPoints = new Map<string, FitOutcome>();
  problems.forEach((points, k) => {
    const outcome = outcomes[k];
    if (outcome) byPoints.set(pointsKey(points), outcome);
  });
  return byPoints;
}
