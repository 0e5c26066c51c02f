/**
 * A measured tissue's statistics beside its best-matching Voronoi model's: the headline
 * percentages, the summary table (the rows of the results panel's table, read from
 * `analyses[0].summary` of the measured result and from the comparison's model summary), and the
 * polygon distribution chart (measured layers as bars, the model's basal distribution as a line).
 * Every number carries its full value in `data-value`.
 */
import uPlot from 'uplot';
import type { ChartSeries, ChartSpec } from '../model/chartSvg';
import 'uplot/dist/uPlot.min.css';
import type { ScutoidSummary } from '../../core/analysis';
import type { MeasuredResult, ModelComparison } from '../../core/measure';
import { SIDE_LABELS } from '../../view/sideColors';
import { scutoidsText } from '../../core/analysis/summaryText';

const fmt = (value: number, digits = 2) => (Number.isFinite(value) ? value.toFixed(digits) : '–');

/** Model summaries put NaN where the JSON has null; a measured result read back may hold null. */
const num = (value: number | null | undefined) => (value === null || value === undefined ? Number.NaN : value);

function row(cells: string[], header: boolean, key?: string, values?: number[]): HTMLTableRowElement {
  const tr = document.createElement('tr');
  cells.forEach((text, k) => {
    const cell = document.createElement(header || k === 0 ? 'th' : 'td');
    cell.textContent = text;
    if (!header && k === 0) cell.setAttribute('scope', 'row');
    if (!header && k > 0 && values) cell.dataset.value = String(values[k - 1]);
    tr.append(cell);
  });
  if (key) tr.dataset.key = key;
  if (values) tr.dataset.value = String(values[0]);
  return tr;
}

/** Headline: measured % scutoids, and the model's mean ± SD at the measured ratio when compared. */
export function renderHeadline(root: HTMLElement, result: MeasuredResult, comparison: ModelComparison | null, note: string | null): void {
  const summary = result.analyses[0].summary;
  const measured = root.querySelector<HTMLElement>('#measured-percent')!;
  measured.textContent = `${fmt(num(summary.percentScutoids), 1)} %`;
  measured.dataset.value = String(summary.percentScutoids);
  const model = root.querySelector<HTMLElement>('#model-percent')!;
  if (comparison) {
    model.textContent = `${fmt(comparison.meanPercentScutoids, 1)} ± ${fmt(comparison.sdPercentScutoids, 1)} %`;
    model.dataset.value = String(comparison.meanPercentScutoids);
    model.dataset.bestK = String(comparison.bestK);
    model.dataset.sd = String(comparison.sdPercentScutoids);
  } else {
    model.textContent = note ?? 'comparing…';
    model.dataset.value = '';
    model.dataset.bestK = '';
  }
  const caption = root.querySelector<HTMLElement>('#model-caption')!;
  caption.textContent = comparison
    ? `the best-matching model, Voronoi ${comparison.bestK} (L1 distance ${fmt(comparison.candidates[comparison.bestK - 1].distance, 3)} between basal polygon distributions), simulated at the measured ratio s = ${fmt(comparison.surfaceRatio, 3)} over ${comparison.realizations} realizations (exact adjacency)`
    : '';
}

export function summaryTable(result: MeasuredResult, comparison: ModelComparison | null): HTMLTableElement {
  const table = document.createElement('table');
  table.className = 'summary';
  table.id = 'measure-summary';
  const columns: { name: string; summary: ScutoidSummary }[] = [
    { name: `measured (labels, min contact ${fmt(result.analyses[0].minContactLength, 3)} µm)`, summary: result.analyses[0].summary },
  ];
  if (comparison) columns.push({ name: `model Voronoi ${comparison.bestK} (exact; realization 1, % scutoids: mean)`, summary: comparison.summary });
  table.append(row(['', ...columns.map((c) => c.name)], true));
  const line = (key: keyof ScutoidSummary, label: string, digits: number, values = columns.map((c) => num(c.summary[key] as number))) =>
    table.append(row([label, ...values.map((v) => fmt(v, digits))], false, String(key), values));
  // The model's % scutoids is its mean over realizations (the first realization's summary gives the rest).
  const percents = [num(columns[0].summary.percentScutoids), ...(comparison ? [comparison.meanPercentScutoids] : [])];
  line('percentScutoids', comparison ? '% scutoids (model: mean over realizations)' : '% scutoids', 2, percents);
  line('scutoids', 'scutoids', 0);
  line('validCells', 'cells counted (not touching an open border, on every layer)', 0);
  line('excludedCells', 'cells left out', 0);
  line('meanTransitions', 'mean apico-basal transitions', 3);
  line('meanWon', 'mean neighbours won', 3);
  line('meanLost', 'mean neighbours lost', 3);
  line('meanNeighbours3D', 'mean 3D neighbours', 3);
  result.inputs.layers.forEach((layer, k) => {
    const sides = columns.map((c) => num(c.summary.perSurface[k]?.meanSides));
    table.append(row([`mean sides, ${layer.name}`, ...sides.map((v) => fmt(v, 3))], false, `meanSides.${k}`, sides));
    const hex = columns.map((c) => 100 * num(c.summary.perSurface[k]?.polygonDistribution[3]));
    table.append(row([`% hexagons, ${layer.name}`, ...hex.map((v) => fmt(v, 1))], false, `hexagons.${k}`, hex));
  });
  return table;
}

const COLORS = ['#1f5fa8', '#c0392b', '#7f8c8d', '#16a085'];

/** The polygon distribution chart: measured layers (bars at the ends), the model's basal mean (line). */
export class MeasureChart {
  private plot: uPlot | null = null;
  private last: { result: MeasuredResult; comparison: ModelComparison | null } | null = null;
  constructor(private readonly root: HTMLElement) {}

  /**
   * The measured-vs-model comparison as a figure (chartSvg.ts): the measured first and last
   * layers' polygon distributions as bars, the best model's mean basal distribution as a line,
   * the measured and model % scutoids (mean ± SD over the model's realizations) in the notes.
   */
  figure(): Pick<ChartSpec, 'title' | 'xLabel' | 'yLabel' | 'series' | 'notes' | 'xTicks' | 'yRange'> | null {
    if (!this.last) return null;
    const { result, comparison } = this.last;
    const perSurface = result.analyses[0].summary.perSurface;
    const last = perSurface.length - 1;
    const series: ChartSeries[] = [0, last].map((k, j) => ({
      label: `measured ${result.inputs.layers[k].name} (${result.inputs.layers[k].file})`,
      color: COLORS[j],
      style: 'bars' as const,
      labels: 1,
      points: perSurface[k].polygonDistribution.map((f, c) => ({ x: c + 3, y: f === null || !Number.isFinite(f) ? Number.NaN : 100 * f })),
    }));
    if (comparison) {
      series.push({
        label: `model Voronoi ${comparison.bestK}, basal, mean of ${comparison.realizations} realizations`,
        color: '#111',
        style: 'line',
        dashed: true,
        points: comparison.candidates[comparison.bestK - 1].polygonDistribution.map((f, c) => ({ x: c + 3, y: 100 * f })),
      });
    }
    const s = result.analyses[0].summary;
    const max = Math.max(...series.flatMap((x) => x.points.map((p) => p.y)).filter(Number.isFinite));
    return {
      title: 'Polygon distribution, measured and model',
      xLabel: 'sides (cells with n sides)',
      yLabel: '% of valid cells',
      xTicks: SIDE_LABELS.map((label, k) => ({ x: k + 3, label })),
      yRange: [0, Math.min(100, Math.ceil(max * 1.15))],
      series,
      notes: [
        `Measured: ${scutoidsText(s.percentScutoids)} (${s.scutoids} of ${s.validCells} valid cells, one tissue), surface ratio ${result.surfaceRatio.value.toFixed(3)}, pixel-based adjacency.`,
        comparison
          ? `Model (Voronoi ${comparison.bestK}, the best match by ${comparison.distance}; exact method): ${comparison.meanPercentScutoids.toFixed(1)} ± ${comparison.sdPercentScutoids.toFixed(1)} % scutoids (mean ± SD over n = ${comparison.realizations} realizations) at s = ${comparison.surfaceRatio.toFixed(3)}.`
          : 'No model comparison.',
      ],
    };
  }

  show(result: MeasuredResult, comparison: ModelComparison | null): void {
    this.last = { result, comparison };
    const perSurface = result.analyses[0].summary.perSurface;
    const last = perSurface.length - 1;
    const x = SIDE_LABELS.map((_, k) => k + 3);
    const series: uPlot.Series[] = [{ label: 'sides', value: (_u, v) => (v === null ? '' : v >= 10 ? '10+' : String(v)) }];
    const data: (number | null)[][] = [x];
    const percent = (_u: uPlot, v: number | null) => (v === null ? '' : `${v.toFixed(1)} %`);
    perSurface.forEach((surface, k) => {
      const ends = k === 0 || k === last;
      const color = COLORS[k === 0 ? 0 : k === last ? 1 : 2];
      series.push({
        label: `measured ${result.inputs.layers[k].name}`,
        stroke: color,
        fill: ends ? `${color}99` : undefined,
        width: ends ? 1 : 2,
        paths: ends ? uPlot.paths.bars!({ size: [0.4, 60], align: k === 0 ? -1 : 1 }) : undefined,
        points: { show: !ends },
        value: percent,
      });
      data.push(surface.polygonDistribution.map((f) => (f === null || !Number.isFinite(f) ? null : 100 * f)));
    });
    if (comparison) {
      series.push({
        label: `model Voronoi ${comparison.bestK} basal (mean)`,
        stroke: '#111',
        width: 2,
        dash: [5, 3],
        points: { show: true, size: 6 },
        value: percent,
      });
      data.push(comparison.candidates[comparison.bestK - 1].polygonDistribution.map((f) => 100 * f));
    }
    this.plot?.destroy();
    const width = Math.max(280, Math.floor(this.root.clientWidth || 420));
    this.plot = new uPlot(
      {
        title: 'Polygon distribution (%), measured and model',
        width,
        height: 220,
        scales: { x: { time: false, range: [2.5, 10.5] } },
        axes: [{ values: (_u, ticks) => ticks.map((t) => (t >= 10 ? '10+' : String(t))) }, {}],
        series,
      },
      data as uPlot.AlignedData,
      this.root,
    );
  }
}
