/**
 * A number as a person types it: a decimal point or a decimal comma ("22,5" is 22.5, as typed
 * in most of Europe), spaces between digit groups ignored, an exponent allowed ("1e-3"). What
 * could be read two ways is refused with words, never guessed: a comma and a point together
 * ("1,234.5"), more than one comma, or anything that is not a number. A browser's
 * `<input type="number">` reads "22,5" as 225 in an English locale, so the page's number boxes
 * are text boxes read by this function.
 */
export type DecimalReading = { ok: true; value: number } | { ok: false; message: string };

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)(e[+-]?\d+)?$/i;

export function readDecimal(text: string): DecimalReading {
  const compact = text.trim().replace(/[\s\u00a0\u202f']/g, '');
  if (compact === '') return { ok: false, message: 'is empty: type a number' };
  const commas = (compact.match(/,/g) ?? []).length;
  if (commas > 0 && compact.includes('.')) {
    return { ok: false, message: `"${text.trim()}" has both a comma and a point: type one decimal separator (22.5 or 22,5) and no thousands separator` };
  }
  if (commas > 1)
    return { ok: false, message: `"${text.trim()}" has more than one comma: type one decimal separator (22.5 or 22,5) and no thousands separator` };
  const normal = compact.replace(',', '.');
  if (!NUMBER.test(normal)) return { ok: false, message: `"${text.trim()}" is not a number` };
  const value = Number(normal);
  if (!Number.isFinite(value)) return { ok: false, message: `"${text.trim()}" is out of range` };
  return { ok: true, value };
}
