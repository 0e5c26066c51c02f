/**
 * How the element shows a result: the percent label (its text, and data attributes a page or a
 * test reads: `data-value` the number shown, `data-drawn` realization 1's, `data-realizations`,
 * `data-method`) and the status line. Realization 1 is shown as soon as it is drawn; the mean over
 * the realizations replaces its number once they are combined (the cells drawn stay
 * realization 1's).
 */
import type { Config } from '../core/config';
import { byConstruction } from '../core/analysis/byConstruction';
import { describeRealizations, type Headline } from '../core/analysis/headline';
import type { AnalysisRecord, SheetResult } from '../run';
import { methodCaption } from '../view/stack';

/** What the element writes on its percent label (an HTMLElement; a plain object in tests). */
export interface PercentLabel {
  textContent: string | null;
  title: string;
  readonly dataset: DOMStringMap;
}

/** Realization 1's % scutoids (NaN without an analysis), on the label at once. */
export function showDrawn(label: PercentLabel, analysis: AnalysisRecord | null): void {
  const percent = analysis?.summary.percentScutoids ?? Number.NaN;
  label.textContent = `${percent.toFixed(1)} %`;
  label.dataset.value = String(percent);
  label.dataset.method = analysis?.method ?? 'labels';
  label.title = `scutoids, from ${methodCaption(analysis)}`;
}

/**
 * The headline over realizations on the label (its mean replaces the drawn number when there
 * are several realizations and it has a value); returns the realizations in words.
 */
export function showHeadline(label: PercentLabel, analysis: AnalysisRecord | null, headline: Headline | null): string {
  if (headline && headline.realizations > 1 && headline.percentScutoids !== null) {
    label.textContent = `${headline.percentScutoids.toFixed(1)} %`;
    label.dataset.value = String(headline.percentScutoids);
  }
  label.dataset.drawn = String(analysis?.summary.percentScutoids ?? Number.NaN);
  label.dataset.realizations = String(headline?.realizations ?? 1);
  const over = headline ? describeRealizations(headline) : 'one realization';
  label.title = `scutoids, from ${methodCaption(analysis)}; ${over}`;
  return over;
}

/**
 * The status line of a finished result: why it is 0 % by construction when the geometry fixes
 * it, else what ran (`over`: the realizations in words, from showHeadline).
 */
export function resultStatus(config: Config, result: SheetResult, analysis: AnalysisRecord | null, over: string): string {
  const rule = byConstruction(config);
  if (rule) return rule.message;
  const iterations = result.lloyd.iterations.length;
  const method = analysis?.method ?? 'labels';
  return `${config.cells} cells, Voronoi ${iterations + 1} (${iterations} Lloyd iterations), ${config.surface.kind}, ${method} adjacency; ${over}`;
}
