/**
 * The Flintstones law in the page: after a sweep over the surface ratio, each fit of the
 * aggregate (src/core/sweep/flintstones.ts; one per Voronoi k) drawn as its data, the mean 3D
 * neighbours n3D per ratio, and the fitted curve n3D(s) = Nmax (b + e^{s/c}) / (d + e^{s/c})
 * (Gómez-Gálvez et al. 2022), with the parameters, their standard errors and R² in words, and
 * the reason where a fit is ill-conditioned or missing.
 */
import uPlot from 'uplot';
import { flintstonesLaw } from '../../core/analysis/flintstones';
import { FLINTSTONES_RATIO, type SweepFlintstonesFit } from '../../core/sweep';
import type { ChartSeries, ChartSpec } from '../model/chartSvg';

const COLORS = ['#1f5fa8', '#c0392b', '#2e8b57', '#8e44ad', '#d35400', '#16a085'];
const CURVE_POINTS = 60;

export class FlintstonesChart {
  private plot: uPlot | null = null;
  private readonly chart: HTMLElement;
  private readonly caption: HTMLElement;

  constructor(private readonly root: HTMLElement) {
    root.hidden = true;
    root.innerHTML = '<h3>Flintstones law: 3D neighbours against the surface ratio</h3><div class="flintstones-chart"></div><ul class="flintstones-fits"></ul>';
    this.chart = root.querySelector<HTMLElement>('.flintstones-chart')!;
    this.caption = root.querySelector<HTMLElement>('.flintstones-fits')!;
  }

  private last: { fits: readonly SweepFlintstonesFit[]; rows: readonly Record<string, string>[] } | null = null;

  /** The fits as a figure (chartSvg.ts): mean n3D per ratio, the fitted curves, the parameters in the notes. */
  figure(): Pick<ChartSpec, 'title' | 'xLabel' | 'yLabel' | 'series' | 'notes'> | null {
    if (!this.last || this.last.fits.length === 0) return null;
    const { fits, rows } = this.last;
    const ratios = [...new Set(rows.map((row) => Number(row[FLINTSTONES_RATIO])).filter(Number.isFinite))].sort((a, b) => a - b);
    const lo = ratios[0];
    const hi = ratios[ratios.length - 1];
    const series: ChartSeries[] = [];
    fits.forEach((fit, k) => {
      const color = COLORS[k % COLORS.length];
      const means = meanPerRatio(rows, fit);
      series.push({
        label: `Voronoi ${fit.voronoi}: mean 3D neighbours of the runs`,
        color,
        style: 'points',
        labels: 2,
        points: [...means].sort((a, b) => a[0] - b[0]).map(([x, y]) => ({ x, y })),
      });
      const p = fit.parameters;
      if (p) {
        const curve = Array.from({ length: CURVE_POINTS }, (_, j) => lo + ((hi - lo) * j) / (CURVE_POINTS - 1)).map((x) => ({ x, y: flintstonesLaw(x, p) }));
        series.push({
          label: `Voronoi ${fit.voronoi}: fit n3D(s) = Nmax (b + e^(s/c)) / (d + e^(s/c))`,
          color,
          style: 'curve',
          dashed: fit.illConditioned,
          points: curve,
        });
      }
    });
    return {
      title: 'Flintstones law: 3D neighbours against the surface ratio',
      xLabel: 'surface ratio s = R_outer / R_inner',
      yLabel: 'mean 3D neighbours n3D (cells)',
      series,
      notes: fits.map((fit) => fitLine(fit).textContent ?? ''),
    };
  }

  /** Draws the fits of a finished sweep (`rows`: its runs.csv rows); hides itself without any. */
  show(fits: readonly SweepFlintstonesFit[], rows: readonly Record<string, string>[]): void {
    this.last = { fits, rows };
    this.plot?.destroy();
    this.plot = null;
    this.root.hidden = fits.length === 0;
    this.root.dataset.fits = String(fits.length);
    if (fits.length === 0) return;
    const ratios = [...new Set(rows.map((row) => Number(row[FLINTSTONES_RATIO])).filter(Number.isFinite))].sort((a, b) => a - b);
    const lo = ratios[0];
    const hi = ratios[ratios.length - 1];
    const xs = Array.from({ length: CURVE_POINTS }, (_, k) => lo + ((hi - lo) * k) / (CURVE_POINTS - 1));
    // One x axis for data and curves: the ratios and the curve's samples, merged.
    const x = [...new Set([...ratios, ...xs])].sort((a, b) => a - b);
    const data: (number | null)[][] = [x];
    const series: uPlot.Series[] = [{ label: 's' }];
    fits.forEach((fit, k) => {
      const color = COLORS[k % COLORS.length];
      const means = meanPerRatio(rows, fit);
      data.push(x.map((s) => means.get(s) ?? null));
      series.push({ label: `Voronoi ${fit.voronoi} (runs)`, stroke: color, width: 0, points: { show: true, size: 7, stroke: color, fill: color } });
      const p = fit.parameters;
      data.push(x.map((s) => (p && s >= lo && s <= hi ? flintstonesLaw(s, p) : null)));
      series.push({ label: `Voronoi ${fit.voronoi} (fit)`, stroke: color, width: 2, dash: fit.illConditioned ? [5, 5] : undefined, spanGaps: true });
    });
    const width = Math.max(280, this.chart.clientWidth || 420);
    this.plot = new uPlot(
      { width, height: 240, series, axes: [{ label: 'surface ratio s' }, { label: 'mean 3D neighbours n3D' }], scales: { x: { time: false } } },
      data as uPlot.AlignedData,
      this.chart,
    );
    this.caption.replaceChildren(...fits.map((fit) => fitLine(fit)));
  }
}

/** Mean of the fit's metric per ratio over the rows of its group. */
function meanPerRatio(rows: readonly Record<string, string>[], fit: SweepFlintstonesFit): Map<number, number> {
  const sums = new Map<number, { total: number; n: number }>();
  for (const row of rows) {
    if (Object.entries(fit.group).some(([field, value]) => row[field] !== value)) continue;
    if (voronoiOf(row) !== null && voronoiOf(row) !== fit.voronoi) continue;
    const s = Number(row[FLINTSTONES_RATIO]);
    const v = Number(row[fit.metric]);
    if (!Number.isFinite(s) || !Number.isFinite(v) || row[fit.metric] === '') continue;
    const entry = sums.get(s) ?? { total: 0, n: 0 };
    entry.total += v;
    entry.n += 1;
    sums.set(s, entry);
  }
  return new Map([...sums].map(([s, { total, n }]) => [s, total / n]));
}

/** Voronoi k of a row whose sweep varies lloyd.maxIterations (else null: one k for all rows). */
function voronoiOf(row: Record<string, string>): number | null {
  const iterations = row['lloyd.maxIterations'];
  return iterations === undefined || iterations === '' ? null : Number(iterations) + 1;
}

function fitLine(fit: SweepFlintstonesFit): HTMLElement {
  const item = document.createElement('li');
  const p = fit.parameters;
  const se = fit.standardErrors;
  const pm = (value: number, error: number | null | undefined) =>
    `${value.toPrecision(4)}${error !== null && error !== undefined ? ` ± ${error.toPrecision(2)}` : ''}`;
  item.textContent = p
    ? `Voronoi ${fit.voronoi}: Nmax ${pm(p.nMax, se?.nMax)}, c ${pm(p.c, se?.c)}, d ${pm(p.d, se?.d)}, b ${p.b.toPrecision(4)}` +
      `${fit.rSquared !== null ? `, R² ${fit.rSquared.toFixed(3)}` : ''} (${fit.points} runs, ${fit.ratios} ratios, ${fit.metric})` +
      `${fit.illConditioned ? ` — ill-conditioned: ${fit.note}` : ''}`
    : `Voronoi ${fit.voronoi}: no fit (${fit.note})`;
  if (fit.illConditioned || !p) item.dataset.illConditioned = 'true';
  return item;
}
