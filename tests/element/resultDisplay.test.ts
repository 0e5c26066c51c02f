import { describe, expect, it } from 'vitest';
import { resultStatus, showDrawn, showHeadline, type PercentLabel } from '../../src/element/resultDisplay';
import { StatusLine } from '../../src/element/statusLine';
import { realizationsOf, realizationStatus } from '../../src/element/realizations';
import { validateConfig } from '../../src/core/config';
import type { Headline } from '../../src/core/analysis/headline';
import type { AnalysisRecord, SheetResult } from '../../src/run';

/**
 * What the element shows of a result, without a page: the percent label (realization 1 first,
 * then the mean over realizations, with realization 1 kept in data-drawn), the status line with
 * its standing warnings, and the realizations attribute.
 */

const label = (): PercentLabel => ({ textContent: null, title: '', dataset: {} });
const analysis = (percentScutoids: number, method: 'labels' | 'exact' = 'exact') =>
  ({ method, protocol: 'default', summary: { percentScutoids } }) as unknown as AnalysisRecord;
const headline = (realizations: number, percentScutoids: number | null, drawn: number) =>
  ({
    realizations,
    percentScutoids,
    ci95: realizations > 1 ? [percentScutoids! - 1, percentScutoids! + 1] : null,
    realizationSeeds: Array.from({ length: realizations }, (_, i) => 7 + i),
    realizationValues: [drawn, ...Array.from({ length: realizations - 1 }, () => percentScutoids)],
  }) as unknown as Headline;

describe('the percent label', () => {
  it('shows realization 1 at once, then the mean over realizations with realization 1 in data-drawn', () => {
    const l = label();
    showDrawn(l, analysis(31.25));
    expect([l.textContent, l.dataset.value, l.dataset.method]).toEqual(['31.3 %', '31.25', 'exact']);
    const over = showHeadline(l, analysis(31.25), headline(5, 40.5, 31.25));
    expect([l.textContent, l.dataset.value, l.dataset.drawn, l.dataset.realizations]).toEqual(['40.5 %', '40.5', '31.25', '5']);
    expect(over).toMatch(/^mean of 5 realizations \(seeds 7–11\)/);
    expect(l.title).toContain(over);
  });

  it('keeps realization 1 when there is one realization, or no headline, or no mean', () => {
    for (const h of [headline(1, 12, 12), null, headline(3, null, 12)]) {
      const l = label();
      showDrawn(l, analysis(12, 'labels'));
      const over = showHeadline(l, analysis(12, 'labels'), h);
      expect([l.textContent, l.dataset.value, l.dataset.drawn]).toEqual(['12.0 %', '12', '12']);
      expect(l.dataset.realizations).toBe(String(h?.realizations ?? 1));
      if (!h) expect(over).toBe('one realization');
    }
  });

  it('shows NaN, not a number, without an analysis', () => {
    const l = label();
    showDrawn(l, null);
    expect([l.textContent, l.dataset.method]).toEqual(['NaN %', 'labels']);
  });
});

describe('the status line', () => {
  it('says what ran, or why the geometry fixes 0 %', () => {
    const result = { lloyd: { iterations: [{}, {}, {}] } } as unknown as SheetResult;
    const tube = validateConfig({ cells: 40, sheet: { surfaceRatio: 2 } });
    expect(resultStatus(tube, result, analysis(10), 'one realization')).toBe(
      `40 cells, Voronoi 4 (3 Lloyd iterations), ${tube.surface.kind}, exact adjacency; one realization`,
    );
    const flat = validateConfig({ cells: 40, surface: { kind: 'plane', width: 100, height: 100 }, sheet: { thickness: 5 } });
    expect(resultStatus(flat, result, analysis(0), 'one realization')).not.toContain('Lloyd');
  });

  it('keeps unknown-attribute and fallback warnings after every status, the fallback said once', () => {
    const line = { textContent: null as string | null, classes: new Set<string>() };
    const status = new StatusLine({
      get textContent() {
        return line.textContent;
      },
      set textContent(text) {
        line.textContent = text;
      },
      classList: { toggle: (token: string, force?: boolean) => (force ? line.classes.add(token) : line.classes.delete(token), !!force) },
    });
    status.show('Running');
    expect(line.textContent).toBe('Running');
    status.setUnknownAttributes(['unknown attribute "x" ignored']);
    expect(status.noteFallback({ where: 'worker' })).toBeNull();
    const fallback = status.noteFallback({ where: 'page', reason: 'no OffscreenCanvas' });
    expect(fallback).toContain('no OffscreenCanvas');
    expect(status.noteFallback({ where: 'page', reason: 'no OffscreenCanvas' })).toBeNull();
    status.show('bad cells', true);
    expect(line.textContent).toBe(`bad cells — unknown attribute "x" ignored; ${fallback}.`);
    expect(line.classes.has('error')).toBe(true);
    status.show('ok');
    expect(line.classes.has('error')).toBe(false);
  });
});

describe('the realizations attribute', () => {
  it('defaults, checks and names itself', () => {
    expect(realizationsOf('3')).toBe(3);
    expect(realizationsOf(null)).toBeGreaterThanOrEqual(1);
    for (const bad of ['0', '1.5', '101', 'many']) expect(() => realizationsOf(bad)).toThrow(/^realizations: /);
    expect(realizationStatus(validateConfig({ seed: 4294967295 }), 1, 5)).toBe('Realization 2 of 5 (seed 0) for the mean % scutoids…');
  });
});
