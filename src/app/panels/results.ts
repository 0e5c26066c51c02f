/**
 * The results panel: % scutoids in large type, the summary statistics (per adjacency method and
 * per surface), how the run went (iterations, energy, centroid path, timings), and the per-cell
 * table. Every number carries its full value in `data-value` for tests and copy-paste.
 */
import { describeEngine } from '../../run';
import { cellTable } from '../model/cellRows';
import { byConstruction, noValidCells } from '../../core/analysis/byConstruction';
import { analysisByMethod, methodCaption, type ViewStack } from '../../view/stack';

const fmt = (value: number, digits = 2) => (Number.isFinite(value) ? value.toFixed(digits) : '–');

export function renderResults(root: HTMLElement, stack: ViewStack): void {
  const { result, analysis } = stack;
  const headline = root.querySelector<HTMLElement>('#percent-scutoids');
  if (headline) {
    const value = analysis?.summary.percentScutoids ?? Number.NaN;
    headline.textContent = `${fmt(value, 1)} %`;
    headline.dataset.value = String(value);
    headline.dataset.method = analysis?.method ?? '';
  }
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
      `${describeEngine(result.engine)}, ${timings(result.timings)}${result.gpu ? ` on ${result.gpu.renderer}` : ''}${geodesic}`;
    run.dataset.voronoiK = String(last + 1);
  }
  const table = root.querySelector<HTMLElement>('#cell-table');
  if (table) table.replaceChildren(cellTableElement(stack));
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

function row(cells: (string | number)[], header = false, key?: string, value?: number): HTMLTableRowElement {
  const tr = document.createElement('tr');
  cells.forEach((text, k) => {
    const cell = document.createElement(header || k === 0 ? 'th' : 'td');
    cell.textContent = String(text);
    if (!header && k === 0) cell.setAttribute('scope', 'row');
    tr.append(cell);
  });
  if (key) tr.dataset.key = key;
  if (value !== undefined) tr.dataset.value = String(value);
  return tr;
}

function summaryTable(stack: ViewStack): HTMLTableElement {
  const table = document.createElement('table');
  table.className = 'summary';
  // The headline's method first: its values are the rows' data-value.
  const order = stack.analysis?.method === 'exact' ? (['exact', 'labels'] as const) : (['labels', 'exact'] as const);
  const methods = order.map((m) => analysisByMethod(stack.result, m)).filter((a) => a !== null);
  table.append(row(['', ...methods.map((a) => a.method)], true));
  const line = (key: keyof (typeof methods)[number]['summary'], label: string, digits: number) => {
    const values = methods.map((a) => a.summary[key] as number);
    table.append(row([label, ...values.map((v) => fmt(v, digits))], false, String(key), values[0]));
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
    table.append(row([`mean sides, ${name}`, ...values.map((v) => fmt(v, 3))], false, `meanSides.${k}`, values[0]));
    const hex = methods.map((a) => 100 * (a.summary.perSurface[k]?.polygonDistribution[3] ?? Number.NaN));
    table.append(row([`% hexagons, ${name}`, ...hex.map((v) => fmt(v, 1))], false, `hexagons.${k}`, hex[0]));
  });
  return table;
}

function cellTableElement(stack: ViewStack): HTMLTableElement {
  const { header, rows } = cellTable(stack);
  const table = document.createElement('table');
  table.className = 'cells';
  const head = document.createElement('thead');
  head.append(row(header, true));
  const body = document.createElement('tbody');
  for (const cells of rows) {
    const tr = row(cells);
    if (cells[2] === 1) tr.className = 'scutoid';
    else if (cells[1] === 0) tr.className = 'border';
    body.append(tr);
  }
  table.append(head, body);
  return table;
}
