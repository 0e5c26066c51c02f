/**
 * An analysis summary's numbers as text for people. A summary with no valid cell holds NaN (null
 * once written to JSON and read back, e.g. a measured result opened in the app): such a number is
 * written "n/a", never "NaN", and null never throws.
 */

/** `value` with `digits` decimals, or "n/a" where there is no number (no valid cell). */
export function summaryNumber(value: number | null | undefined, digits: number): string {
  return typeof value === 'number' && Number.isFinite(value) ? value.toFixed(digits) : 'n/a';
}

/** "12.3 % scutoids", or "no % scutoids (no valid cell)". */
export function scutoidsText(percent: number | null | undefined, digits = 1): string {
  return typeof percent === 'number' && Number.isFinite(percent) ? `${percent.toFixed(digits)} % scutoids` : 'no % scutoids (no valid cell)';
}
