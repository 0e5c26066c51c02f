/**
 * The results panel: % scutoids in large type, the summary statistics (per adjacency method and
 * per surface), how the run went (iterations, energy, centroid path, timings), and the per-cell
 * table. Every number carries its full value in `data-value` for tests and copy-paste.
 */
import { describeEngine } from '../../run';
import { describeOmitted } from '../../core/analysis/headline';
import { renderCellTable } from './cellTableView';
import { tableRow } from './tableRow';
import { byConstruction, noValidCells } from '../../core/analysis/byConstruction';
import { analysisByMethod, methodCaption, type ViewStack } from '../../view/stack';

const fmt = (value: number, digits = 2) => (Number.isFinite(value) ? value.toFixed(digits) : '–');

export function renderResults(root: HTMLElement, stack: ViewStack): void {
  const { result, analysis } = stack;
  renderHeadline(root, stack, null);
  const caption = root.querySelector<HTMLElement>('#percent-scutoids-caption');
  if (caption) caption.textContent = `scutoids, from ${methodCaption(analysis)}`;
  const why = root.querySelector<HTMLElement>('#by-construction');
  if (why) {
    // A 0 that the geometry forces is said to be one, never left to read as a finding.
    const rule = byConstruction(result.config);
    const empty = analysis ? noValidCells(analysis.summary.validCells, analysis.summary.cells) : null;
    why.textContent = empty ?? rule?.message ?? '';
    why.dataset.reason = empty ? 'no-valid-cells' : (rule?.reason ?? '');
    why.hidden = !why.textContent;
  }
  const omitted = root.querySelector<HTMLElement>('#methods-note');
  if (omitted) {
    // "both" on the exact engine gives the exact method only: said, never silent.
    const line = describeOmitted(result.headline);
    omitted.textContent = line ? `${line.charAt(0).toUpperCase()}${line.slice(1)}.` : '';
    omitted.dataset.omitted = (result.headline?.omittedMethods ?? []).map((o) => o.method).join(' ');
    omitted.hidden = !line;
  }
  const summary = root.querySelector<HTMLElement>('#summary');
  if (summary) summary.replaceChildren(summaryTable(stack));
  const run = root.querySelector<HTMLElement>('#run-info');
  if (run) {
    const last = result.lloyd.iterations.length;
    const closed = result.closed;
    const mesh = closed?.mesh;
    const where = closed
      ? `${closed.kind}${mesh ? ` ${mesh.src} (${mesh.vertices} vertices, ${mesh.faces} faces, parameterization area ratio ${mesh.areaDistortion.min.toFixed(2)}..${mesh.areaDistortion.max.toFixed(2)})` : ''}, ` +
        `area ${fmt(closed.area, 0)} µm², cube map 6 x ${closed.n}² texels`
      : `${result.grid.width} x ${result.grid.height} texels`;
    const geodesic = closed?.geodesic
      ? `; geodesic Voronoi (heat method) ${fmt(closed.geodesic.msPerSite, 1)} ms per site, agrees with the GPU cells on ${fmt(100 * closed.geodesic.agreement, 1)} % of vertices`
      : '';
    run.textContent =
      `${result.cells.length} cells, ${where}, ${last} Lloyd iterations (Voronoi ${last + 1})` +
      `${result.lloyd.converged ? ' (converged)' : ''}, final energy ${result.lloyd.finalEnergy.toPrecision(6)} µm⁴, ` +
      `${describeEngine(result.engine)}, ${timings(result.timings)}${result.gpu ? ` on ${result.gpu.renderer}` : ''}${geodesic}` +
      // A mesh whose triangles faced inward was turned outward: said, never silently (issue 26).
      `${mesh?.reoriented ? `. Note: ${mesh.reoriented}` : ''}`;
    run.dataset.reoriented = mesh?.reoriented ? 'true' : 'false';
    run.dataset.voronoiK = String(last + 1);
  }
  const table = root.querySelector<HTMLElement>('#cell-table');
  // Only the rows in view are in the DOM (cellTableView.ts).
  if (table) renderCellTable(table, stack);
}

/** Where the other realizations of the headline are: running (done of n), stopped, or failed. */
export type RealizationsProgress = { state: 'running'; done: number; n: number } | { state: 'waiting' | 'cancelled' | 'failed'; n: number; message?: string };

/**
 * The headline: the mean % scutoids over the realizations with its 95 % CI and n once they are
 * computed (`result.headline.realizations` > 1), else realization 1's value, said to be one
 * realization. `#percent-scutoids` carries `data-value` (the number shown), `data-drawn` (the
 * cells shown: realization 1), `data-realizations` (n of the number shown), `data-ci-low`,
 * `data-ci-high` and `data-method`.
 */
export function renderHeadline(root: HTMLElement, stack: ViewStack, progress: RealizationsProgress | null): void {
  const { result, analysis } = stack;
  const headline = result.headline;
  const drawn = analysis?.summary.percentScutoids ?? Number.NaN;
  const n = headline?.realizations ?? 1;
  const value = n > 1 ? (headline?.percentScutoids ?? Number.NaN) : drawn;
  const seeds = headline?.realizationSeeds ?? [result.config.seed];
  const number = root.querySelector<HTMLElement>('#percent-scutoids');
  if (number) {
    number.textContent = `${fmt(value, 1)} %`;
    number.dataset.value = String(value);
    number.dataset.drawn = String(drawn);
    number.dataset.realizations = String(n);
    number.dataset.ciLow = headline?.ci95 ? String(headline.ci95[0]) : '';
    number.dataset.ciHigh = headline?.ci95 ? String(headline.ci95[1]) : '';
    number.dataset.method = analysis?.method ?? '';
  }
  const ci = root.querySelector<HTMLElement>('#headline-ci');
  if (ci) {
    ci.textContent =
      n > 1 && headline?.ci95
        ? `(mean of n = ${n} realizations, 95 % CI ${fmt(headline.ci95[0], 1)}–${fmt(headline.ci95[1], 1)} %)`
        : n > 1
          ? `(mean of n = ${n} realizations)`
          : progress?.state === 'running' || progress?.state === 'waiting'
            ? `(realization 1 of ${progress.n}; the mean and its 95 % CI follow)`
            : '(one realization, n = 1: no confidence interval)';
  }
  const words = root.querySelector<HTMLElement>('#headline-realizations');
  if (words) {
    const seed = result.config.seed;
    let text: string;
    if (n > 1) {
      text =
        `Mean of ${n} realizations, seeds ${seeds[0]}–${seeds[seeds.length - 1]}` +
        `${headline?.sd !== null && headline?.sd !== undefined ? `, SD ${fmt(headline.sd, 1)} %` : ''}. ` +
        `The cells shown are realization 1 of ${n} (seed ${seed}): ${fmt(drawn, 1)} %.`;
    } else if (progress?.state === 'running') {
      text = `Realization 1 of ${progress.n} (seed ${seed}) only: computing realizations ${progress.done + 1}–${progress.n} for the mean and its 95 % CI (${progress.done} of ${progress.n} done)…`;
    } else if (progress?.state === 'waiting') {
      text = `Realization 1 of ${progress.n} (seed ${seed}) only: the mean over ${progress.n} realizations and its 95 % CI follow once the result settles.`;
    } else if (progress?.state === 'cancelled') {
      text = `One realization (seed ${seed}): the other ${progress.n - 1} were stopped, so there is no mean or confidence interval yet.`;
    } else if (progress?.state === 'failed') {
      text = `One realization (seed ${seed}): the other realizations failed (${progress.message ?? 'unknown error'}).`;
    } else {
      text = `One realization (seed ${seed}): a single run has no confidence interval; raise Realizations for a mean with its 95 % CI.`;
    }
    words.textContent = text;
    words.dataset.state = n > 1 ? 'complete' : (progress?.state ?? 'single');
  }
}

/**
 * Timings in words. When only the sheet changed the seeded surface is reused: its setup and
 * Lloyd times are from the run that computed it, not part of this run's total, and are said so.
 */
export function timings(t: { setupMs: number; lloydMs: number; adjacencyMs: number; totalMs: number }): string {
  const parts = t.setupMs + t.lloydMs + t.adjacencyMs;
  const ms = (v: number) => `${fmt(v, 0)} ms`;
  if (parts <= t.totalMs + 1) {
    return `${ms(t.totalMs)} in all (setup ${ms(t.setupMs)}, Lloyd ${ms(t.lloydMs)}, adjacency and analysis ${ms(t.adjacencyMs)}, other ${ms(Math.max(0, t.totalMs - parts))})`;
  }
  return `${ms(t.totalMs)} in all (adjacency and analysis ${ms(t.adjacencyMs)}; the seeded surface was reused from an earlier run, where setup took ${ms(t.setupMs)} and Lloyd ${ms(t.lloydMs)})`;
}

function summaryTable(stack: ViewStack): HTMLTableElement {
  const table = document.createElement('table');
  table.className = 'summary';
  // The headline's method first: its values are the rows' data-value.
  const order = stack.analysis?.method === 'exact' ? (['exact', 'labels'] as const) : (['labels', 'exact'] as const);
  const methods = order.map((m) => analysisByMethod(stack.result, m)).filter((a) => a !== null);
  table.append(tableRow([`seed ${stack.result.config.seed} (the cells shown)`, ...methods.map((a) => a.method)], true));
  const line = (key: keyof (typeof methods)[number]['summary'], label: string, digits: number) => {
    const values = methods.map((a) => a.summary[key] as number);
    table.append(tableRow([label, ...values.map((v) => fmt(v, digits))], false, String(key), values[0]));
  };
  line('percentScutoids', '% scutoids', 2);
  line('scutoids', 'scutoids', 0);
  line('validCells', stack.closed ? 'cells counted (all: a closed surface has no border)' : 'cells counted (not touching the ends)', 0);
  line('meanTransitions', 'mean apico-basal transitions', 3);
  line('meanWon', 'mean neighbours won', 3);
  line('meanLost', 'mean neighbours lost', 3);
  line('meanNeighbours3D', 'mean 3D neighbours', 3);
  const surfaces = methods[0]?.summary.perSurface ?? [];
  surfaces.forEach((s, k) => {
    const name = stack.surfaces[k]?.name ?? s.label ?? `surface ${k}`;
    const values = methods.map((a) => a.summary.perSurface[k]?.meanSides ?? Number.NaN);
    table.append(tableRow([`mean sides, ${name}`, ...values.map((v) => fmt(v, 3))], false, `meanSides.${k}`, values[0]));
    const hex = methods.map((a) => 100 * (a.summary.perSurface[k]?.polygonDistribution[3] ?? Number.NaN));
    table.append(tableRow([`% hexagons, ${name}`, ...hex.map((v) => fmt(v, 1))], false, `hexagons.${k}`, hex[0]));
  });
  return table;
}
