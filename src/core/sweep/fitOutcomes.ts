/**
 * The Flintstones fits of a sweep's aggregate computed apart from it: on the CLI's threads (the
 * fits are independent, one per Voronoi k and group, and took the main thread about half a
 * second after the last run while the threads sat idle), or one per turn of a page's event loop
 * (no long task). A fit is made with the same code (sweepFitter), crosses threads by structured
 * clone, which keeps every double, and the aggregate takes it only for exactly the same points
 * (compared by value, in order), fitting anything else itself: the files cannot depend on where
 * or when a fit ran.
 */
import type { FlintstonesFit, FlintstonesPoint } from '../analysis/flintstones';
import { sweepFitter, type FlintstonesFitter } from './flintstones';

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
