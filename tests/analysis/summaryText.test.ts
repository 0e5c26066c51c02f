/** A summary's numbers as text (src/core/analysis/summaryText.ts): no NaN shown, null read back from JSON accepted. */
import { describe, expect, it } from 'vitest';
import { scutoidsText, summaryNumber } from '../../src/core/analysis/summaryText';

describe('summary numbers as text', () => {
  it('a number with its digits; NaN, null, undefined and infinities as "n/a"', () => {
    expect(summaryNumber(12.345, 1)).toBe('12.3');
    expect(summaryNumber(0, 2)).toBe('0.00');
    for (const missing of [Number.NaN, null, undefined, Number.POSITIVE_INFINITY]) expect(summaryNumber(missing, 1)).toBe('n/a');
  });

  it('% scutoids in words, and where no cell was counted, why there is none', () => {
    expect(scutoidsText(33.333)).toBe('33.3 % scutoids');
    expect(scutoidsText(0, 2)).toBe('0.00 % scutoids');
    expect(scutoidsText(Number.NaN)).toBe('no % scutoids (no valid cell)');
    expect(scutoidsText(JSON.parse('null') as null)).toBe('no % scutoids (no valid cell)');
  });
});
