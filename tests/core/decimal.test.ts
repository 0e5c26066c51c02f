import { describe, expect, it } from 'vitest';
import { readDecimal } from '../../src/core/config/decimal';

describe('readDecimal: numbers as people type them', () => {
  it('reads a decimal comma as a decimal, never as a thousands separator', () => {
    expect(readDecimal('22,5')).toEqual({ ok: true, value: 22.5 });
    expect(readDecimal('22.5')).toEqual({ ok: true, value: 22.5 });
    expect(readDecimal(' 0,25 ')).toEqual({ ok: true, value: 0.25 });
    expect(readDecimal(',5')).toEqual({ ok: true, value: 0.5 });
    expect(readDecimal('1 000')).toEqual({ ok: true, value: 1000 });
    expect(readDecimal('-3')).toEqual({ ok: true, value: -3 });
    expect(readDecimal('1e-3')).toEqual({ ok: true, value: 0.001 });
  });

  it('refuses in words what could be read two ways, or is not a number', () => {
    expect(readDecimal('1,234.5')).toMatchObject({ ok: false, message: expect.stringContaining('both a comma and a point') });
    expect(readDecimal('1,234,5')).toMatchObject({ ok: false, message: expect.stringContaining('more than one comma') });
    expect(readDecimal('abc')).toMatchObject({ ok: false, message: '"abc" is not a number' });
    expect(readDecimal('12µm')).toMatchObject({ ok: false });
    expect(readDecimal('')).toMatchObject({ ok: false, message: 'is empty: type a number' });
    expect(readDecimal('1e999')).toMatchObject({ ok: false, message: expect.stringContaining('out of range') });
  });
});
