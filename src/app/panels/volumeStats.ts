/**
 * A measured volume's statistics beside the model of the same geometry (docs/app.md, "Measure a
 * volume"): one table, measured (one tissue) | model (mean and 95 % CI over its realizations),
 * with n; rows the model does not give are measured only. Every number carries its full value
 * in `data-value` (the model's cells also `data-low`, `data-high`).
 */
import type { Interval, VolumeComparison, VolumeMeasuredResult } from '../../core/measure';

const fmt = (value: number | null | undefined, digits: number) =>
  value === null || value === undefined || !Number.isFinite(value) ? '–' : value.toFixed(digits);

function cell(tag: 'th' | 'td', text: string, value?: number | null): HTMLTableCellElement {
  const c = document.createElement(tag);
  c.textContent = text;
  if (value !== undefined) c.dataset.value = String(value);
  return c;
}

export function volumeTable(result: VolumeMeasuredResult, comparison: VolumeComparison | null, modelNote: string): HTMLTableElement {
  const table = document.createElement('table');
  table.className = 'summary';
  table.id = 'volume-summary';
  const head = document.createElement('tr');
  head.append(
    cell('th', ''),
    cell('th', 'measured (one tissue)'),
    cell(
      'th',
      comparison ? `model Voronoi ${comparison.bestK} (exact), mean and 95 % CI, n = ${comparison.realizations}` : `model: ${modelNote || 'not asked'}`,
    ),
  );
  table.append(head);
  const s = result.analyses[0].summary;
  const line = (key: string, label: string, measured: number | null, digits: number, model?: Interval) => {
    const tr = document.createElement('tr');
    tr.dataset.key = key;
    const th = cell('th', label);
    th.setAttribute('scope', 'row');
    const m = model ? cell('td', `${fmt(model.mean, digits)} [${fmt(model.ci95[0], digits)}, ${fmt(model.ci95[1], digits)}]`, model.mean) : cell('td', '');
    if (model) {
      m.dataset.low = String(model.ci95[0]);
      m.dataset.high = String(model.ci95[1]);
    }
    tr.append(th, cell('td', fmt(measured, digits), measured), m);
    table.append(tr);
  };
  const model = comparison?.model;
  line('percentScutoids', '% scutoids', s.percentScutoids, 2, model?.percentScutoids);
  line('meanTransitions', 'mean apico-basal transitions', s.meanTransitions, 3, model?.transitions);
  line('meanNeighbours3D', 'mean 3D neighbours', s.meanNeighbours3D, 3, model?.neighbours3D);
  line('scutoids', 'scutoids', s.scutoids, 0);
  line('validCells', 'valid cells (touch the lumen and the outside, no face of the volume)', s.validCells, 0);
  line('excludedCells', 'cells left out', s.excludedCells, 0);
  result.inputs.layers.forEach((layer, k) => {
    line(`meanSides.${k}`, `mean sides, ${layer.name} (faces the ${layer.faces})`, s.perSurface[k].meanSides, 3);
    line(`hexagons.${k}`, `% hexagons, ${layer.name}`, 100 * (s.perSurface[k].polygonDistribution[3] ?? Number.NaN), 1);
    line(`minContact.${k}`, `min contact, ${layer.name} (µm)`, layer.minContact, 3);
  });
  const heights = result.cells.filter((c) => c.valid && c.height !== null).map((c) => c.height!);
  line('meanHeight', 'mean cell height, valid cells (µm)', heights.length ? heights.reduce((a, b) => a + b, 0) / heights.length : null, 2);
  return table;
}
