/**
 * The sweep's live chart: % scutoids against the swept value, one line per adjacency method
 * (mean over the realizations finished so far) with its 95 % confidence band (t interval of the
 * mean, clamped to 0-100 %). Rows are added one at a time as runs finish; the chart is redrawn
 * at most once per animation frame, by updating its data, not rebuilding it.
 *
 * Reference curves (src/core/reference, chosen by referenceOverlay.ts) are drawn over it dashed,
 * each with its own legend entry (label and kind); the legend value of a reference point is its
 * percent, SD and n when given, and the number of its source in the Sources list under the chart.
 * A reference point whose file gives an SD and n ≥ 2 gets an error bar: the 95 % CI of its mean
 * (referenceInterval, the runs' own interval), drawn as a whisker on the live chart and in the
 * figure; `data-reference-error-bars` counts the whiskers drawn.
 * They share the x axis and nothing else: every export holds the runs only.
 */
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { meanInterval } from '../../view/pageSweep';
import { referenceInterval, type ReferenceCurve, type ReferencePoint } from '../../core/reference';
import type { ChartSeries, ChartSpec } from '../model/chartSvg';

const COLORS: Record<string, string> = { exact: '#1f5fa8', labels: '#c0392b' };
const REFERENCE_COLORS = ['#2e8b57', '#8e44ad', '#d35400', '#16a085', '#7f8c8d', '#b7950b', '#5d6d7e', '#a04000'];

/** A reference curve as drawn: the curve and the number of each of its points' sources. */
export interface ReferenceSeries {
  curve: ReferenceCurve;
  sourceNumber: (point: ReferencePoint) => number;
}

export interface SweepChartSetup {
  /** Axis label of the swept value. */
  label: string;
  /** runs.csv column of the swept value. */
  field: string;
  /** Maps a cell of that column to the x plotted (e.g. Lloyd iterations -> Voronoi k). */
  x: (cell: string) => number;
  /** Adjacency methods with a `<method>.percentScutoids` column. */
  methods: string[];
}

export class SweepChart {
  private plot: uPlot | null = null;
  private setup: SweepChartSetup | null = null;
  /** x -> method -> % scutoids of each finished run. */
  private readonly values = new Map<number, Map<string, number[]>>();
  private frame = 0;
  private reference: readonly ReferenceSeries[] = [];
  /** Series labels of the plot on screen: a new set rebuilds it. */
  private shape = '';
  /** The x values on screen (legend values read them: setData keeps the series' closures). */
  private xs: number[] = [];
  /** Reference error bars on screen (the draw hook reads them: setData keeps the hook). */
  private whiskers: { x: number; low: number; high: number; color: string }[] = [];

  constructor(private readonly root: HTMLElement) {}

  /** Reference curves drawn over the sweep (none: `[]`); redrawn at the next frame. */
  setReference(reference: readonly ReferenceSeries[]): void {
    this.reference = reference;
    this.root.dataset.referenceCurves = String(reference.length);
    if (!this.frame) this.frame = requestAnimationFrame(() => this.draw());
  }

  /** Starts an empty chart for a sweep. */
  reset(setup: SweepChartSetup): void {
    this.setup = setup;
    this.values.clear();
    this.plot?.destroy();
    this.plot = null;
    this.root.dataset.points = '0';
  }

  /** The chart of exactly these runs (a finished sweep's rows: every run once). */
  setRows(rows: readonly Record<string, string>[]): void {
    this.values.clear();
    this.add(rows);
  }

  /** Adds finished runs (runs.csv rows) and schedules a redraw. */
  add(rows: readonly Record<string, string>[]): void {
    const setup = this.setup;
    if (!setup) return;
    for (const row of rows) {
      const x = setup.x(row[setup.field]);
      let byMethod = this.values.get(x);
      if (!byMethod) this.values.set(x, (byMethod = new Map(setup.methods.map((m) => [m, []]))));
      for (const method of setup.methods) {
        const cell = row[`${method}.percentScutoids`];
        if (cell !== undefined && cell !== '') byMethod.get(method)!.push(Number(cell));
      }
    }
    if (!this.frame) this.frame = requestAnimationFrame(() => this.draw());
  }

  /**
   * The chart as a figure (chartSvg.ts): per method the mean % scutoids per x with its 95 % CI
   * as a band and the means written beside the points; reference curves dashed, their points
   * with ± SD error bars where the source gives an SD; notes with n per point and the sources.
   */
  figure(): Pick<ChartSpec, 'title' | 'xLabel' | 'yLabel' | 'series' | 'notes' | 'yRange'> | null {
    const setup = this.setup;
    if (!setup || this.values.size === 0) return null;
    const xs = [...this.values.keys()].sort((a, b) => a - b);
    const series: ChartSeries[] = [];
    const ns: number[] = [];
    for (const method of setup.methods) {
      const points = xs.map((x) => ({ x, ...meanInterval(this.values.get(x)?.get(method) ?? []) })).filter((p) => p.n > 0);
      if (points.length === 0) continue;
      ns.push(...points.map((p) => p.n));
      series.push({
        label: `${method} method: mean % scutoids, 95 % CI band`,
        color: COLORS[method] ?? '#555',
        style: 'line',
        band: true,
        labels: 1,
        points: points.map((p) => ({ x: p.x, y: p.mean, low: p.n > 1 ? p.low : null, high: p.n > 1 ? p.high : null })),
      });
    }
    const sources: string[] = [];
    this.reference.forEach(({ curve, sourceNumber }, k) => {
      series.push({
        label: `${curve.label} (${curve.kind})`,
        color: REFERENCE_COLORS[k % REFERENCE_COLORS.length],
        style: curve.kind === 'data' ? 'points' : 'line',
        dashed: true,
        points: curve.points.map((p) => {
          const interval = referenceInterval(p);
          return { x: p.x, y: p.percent, low: interval?.low ?? null, high: interval?.high ?? null };
        }),
      });
      for (const point of curve.points) {
        const line = `[${sourceNumber(point)}] ${point.source}`;
        if (!sources.includes(line)) sources.push(line);
      }
    });
    const nLo = Math.min(...ns);
    const nHi = Math.max(...ns);
    const max = Math.max(...series.flatMap((s) => s.points.map((p) => p.high ?? p.y)));
    return {
      title: `% scutoids vs ${setup.label}`,
      xLabel: setup.label,
      yLabel: '% scutoids (of valid cells)',
      yRange: [0, Math.min(100, Math.max(10, Math.ceil(max * 1.1)))],
      series,
      notes: [
        `n = ${nLo === nHi ? nLo : `${nLo}–${nHi}`} realizations per point; line: the mean; band: 95 % confidence interval of the mean (Student's t), clamped to 0–100 %.`,
        ...(this.reference.length
          ? [
              "Dashed: reference curves; their error bars are the 95 % confidence interval of the mean (Student's t from the source's SD and n), where the source gives both; points without are drawn without.",
              ...sources.map((line) => `Source ${line}`),
            ]
          : []),
      ],
    };
  }

  private xRange(min: number, max: number): [number, number] {
    const runs = [...this.values.keys()];
    const lo = runs.length > 0 ? Math.min(...runs) : min;
    const hi = runs.length > 0 ? Math.max(...runs) : max;
    if (hi > lo) return [lo, hi];
    const pad = Math.max(0.5, Math.abs(lo) * 0.1);
    return [lo - pad, hi + pad];
  }

  /** Reference error bars: a vertical line from the CI's low to its high, with caps. */
  private drawWhiskers(u: uPlot): void {
    const ctx = u.ctx;
    const cap = 4 * uPlot.pxRatio;
    ctx.save();
    ctx.lineWidth = uPlot.pxRatio;
    for (const w of this.whiskers) {
      const x = u.valToPos(w.x, 'x', true);
      if (x < u.bbox.left || x > u.bbox.left + u.bbox.width) continue;
      const top = u.valToPos(w.high, 'y', true);
      const bottom = u.valToPos(w.low, 'y', true);
      ctx.strokeStyle = w.color;
      ctx.beginPath();
      ctx.moveTo(x, top);
      ctx.lineTo(x, bottom);
      ctx.moveTo(x - cap, top);
      ctx.lineTo(x + cap, top);
      ctx.moveTo(x - cap, bottom);
      ctx.lineTo(x + cap, bottom);
      ctx.stroke();
    }
    ctx.restore();
  }

  private draw(): void {
    this.frame = 0;
    const setup = this.setup;
    if (!setup) return;
    const runXs = [...this.values.keys()].sort((a, b) => a - b);
    // One x axis for runs and reference curves: their x values, merged.
    const xs = [...new Set([...runXs, ...this.reference.flatMap((r) => r.curve.points.map((p) => p.x))])].sort((a, b) => a - b);
    this.xs = xs;
    const data: (number | null)[][] = [xs];
    const series: uPlot.Series[] = [{ label: setup.label }];
    const bands: uPlot.Band[] = [];
    for (const method of setup.methods) {
      const color = COLORS[method] ?? '#555';
      const stats = xs.map((x) => meanInterval(this.values.get(x)?.get(method) ?? []));
      const at = data.length;
      data.push(stats.map((s) => (Number.isFinite(s.mean) ? s.mean : null)));
      data.push(stats.map((s) => (Number.isFinite(s.high) ? s.high : null)));
      data.push(stats.map((s) => (Number.isFinite(s.low) ? s.low : null)));
      const value = (_u: uPlot, v: number | null) => (v === null ? '' : `${v.toFixed(1)} %`);
      series.push(
        { label: `${method}: mean % scutoids`, stroke: color, width: 2, points: { show: true, size: 6 }, value, spanGaps: true },
        { label: `${method}: 95 % CI high`, stroke: `${color}55`, width: 1, points: { show: false }, value, spanGaps: true },
        { label: `${method}: 95 % CI low`, stroke: `${color}55`, width: 1, points: { show: false }, value, spanGaps: true },
      );
      bands.push({ series: [at + 1, at + 2], fill: `${color}22` });
    }
    const whiskers: typeof this.whiskers = [];
    this.reference.forEach(({ curve, sourceNumber }, k) => {
      const color = REFERENCE_COLORS[k % REFERENCE_COLORS.length];
      const byX = new Map(curve.points.map((p) => [p.x, p]));
      data.push(xs.map((x) => byX.get(x)?.percent ?? null));
      for (const point of curve.points) {
        const interval = referenceInterval(point);
        if (interval) whiskers.push({ x: point.x, ...interval, color });
      }
      const value = (_u: uPlot, _v: number | null, _series: number, index: number | null) => {
        const point = index === null ? undefined : byX.get(this.xs[index]);
        if (!point) return '';
        const interval = referenceInterval(point);
        const spread = [
          point.sd !== null ? `SD ${point.sd.toFixed(1)}` : '',
          point.n !== null ? `n ${point.n}` : '',
          interval ? `95 % CI ${interval.low.toFixed(1)}–${interval.high.toFixed(1)}` : 'no CI',
        ]
          .filter(Boolean)
          .join(', ');
        return `${point.percent.toFixed(1)} % (${spread}) [source ${sourceNumber(point)}]`;
      };
      series.push({
        label: `${curve.label} (${curve.kind})`,
        stroke: color,
        width: 1.5,
        dash: curve.kind === 'model' ? [8, 4] : [3, 3],
        points: { show: curve.kind === 'data', size: 5 },
        spanGaps: true,
        value,
      });
    });
    this.whiskers = whiskers;
    this.root.dataset.referenceErrorBars = String(whiskers.length);
    this.root.dataset.points = String(runXs.length);
    const shape = series.map((s) => s.label).join('\n');
    if (this.plot && this.shape === shape) {
      this.plot.setData(data as uPlot.AlignedData);
      return;
    }
    this.shape = shape;
    this.plot?.destroy();
    const width = Math.max(240, Math.floor(this.root.clientWidth || 320));
    this.plot = new uPlot(
      {
        title: `% scutoids vs ${setup.label} (mean, 95 % CI)${this.reference.length > 0 ? '; dashed: reference curves' : ''}`,
        width,
        height: 200,
        // The runs' range when there are runs: reference points beyond it stay off screen.
        scales: {
          x: { time: false, range: (_u, min, max) => this.xRange(min, max) },
          y: { range: (_u, _min, max) => [0, Math.min(100, Math.max(10, Math.ceil(max * 1.1)))] },
        },
        series,
        bands,
        hooks: { draw: [(u) => this.drawWhiskers(u)] },
      },
      data as uPlot.AlignedData,
      this.root,
    );
  }
}
