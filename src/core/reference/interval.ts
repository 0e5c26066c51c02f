/**
 * Error bars of a reference point: the 95 % confidence interval of its mean, from the SD and n
 * its file gives (mean ± t(0.975, n − 1)·SD/√n, Student's t, clamped to 0–100 %), the same
 * interval the sweep chart draws around its own runs. A point without both an SD and n ≥ 2 has
 * none: an SD alone says how spread the samples were, not how well the mean is known.
 */
import { tQuantile975 } from '../analysis/realizations';
import type { ReferenceCurve, ReferencePoint } from './format';

export function referenceInterval(point: ReferencePoint): { low: number; high: number } | null {
  if (point.sd === null || point.n === null || point.n < 2) return null;
  const half = (tQuantile975(point.n - 1) * point.sd) / Math.sqrt(point.n);
  return { low: Math.max(0, point.percent - half), high: Math.min(100, point.percent + half) };
}

/** How many of a curve's points have error bars (referenceInterval), of how many. */
function curveIntervals(curve: ReferenceCurve): { withInterval: number; points: number } {
  return { withInterval: curve.points.filter((p) => referenceInterval(p) !== null).length, points: curve.points.length };
}

/** One sentence on a drawn curve's error bars, for the notes under the chart. */
export function describeIntervals(curve: ReferenceCurve): string {
  const { withInterval, points } = curveIntervals(curve);
  if (withInterval === 0) return `${curve.label}: no error bars (its file gives no SD and n ≥ 2 for its points).`;
  if (withInterval === points) return `${curve.label}: error bars are the 95 % CI of the mean, from the file's SD and n.`;
  return `${curve.label}: error bars (95 % CI of the mean, from SD and n) on ${withInterval} of ${points} points; the others have no SD and n ≥ 2 in the file.`;
}
