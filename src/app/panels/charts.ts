/**
 * uPlot charts: the polygon distribution on each surface (seeded and other side by side as bars,
 * layers as lines), the CVT energy per Lloyd iteration, and Lewis's and Aboav-Weaire's laws. The
 * sweep's chart is sweepChart.ts.
 */
import uPlot from 'uplot';
import 'uplot/dist/uPlot.min.css';
import { SIDE_LABELS } from '../../view/sideColors';
import type { ViewStack } from '../../view/stack';

const SURFACE_COLORS = ['#1f5fa8', '#c0392b', '#7f8c8d', '#16a085', '#8e44ad', '#d35400'];

const HEIGHT = 200;

/** One uPlot chart that follows its box's width (a window resize, a narrower layout). */
class Chart {
  private plot: uPlot | null = null;
  constructor(private readonly root: HTMLElement) {
    new ResizeObserver(() => this.plot?.setSize({ width: this.width(), height: HEIGHT })).observe(root);
  }

  private width(): number {
    return Math.max(200, Math.floor(this.root.clientWidth || 320));
  }

  /** What the chart's layout depends on: a chart of the same shape only takes new data. */
  private shape = '';

  /**
   * Draws `data`; a chart of the same title and series keeps its plot and only takes the data
   * (building a uPlot, its DOM and its legend costs several ms per chart and a layout; four
   * charts follow every result of a slider drag).
   */
  show(options: Omit<uPlot.Options, 'width' | 'height'>, data: uPlot.AlignedData): void {
    const shape = JSON.stringify([options.title, options.series.map((s) => [s.label, s.stroke, s.width, s.dash])]);
    if (this.plot && shape === this.shape) {
      this.plot.setData(data);
      return;
    }
    this.plot?.destroy();
    this.shape = shape;
    this.plot = new uPlot({ ...options, width: this.width(), height: HEIGHT }, data, this.root);
  }
}

const sideTicks = (_u: uPlot, ticks: number[]) => ticks.map((t) => (t >= 10 ? '10+' : Number.isInteger(t) ? String(t) : ''));

export class Charts {
  private readonly polygons: Chart;
  private readonly energy: Chart;
  private readonly lewis: Chart;
  private readonly aboav: Chart;

  constructor(polygons: HTMLElement, energy: HTMLElement, lewis: HTMLElement, aboav: HTMLElement) {
    this.polygons = new Chart(polygons);
    this.energy = new Chart(energy);
    this.lewis = new Chart(lewis);
    this.aboav = new Chart(aboav);
  }

  showStack(stack: ViewStack): void {
    const perSurface = stack.analysis?.summary.perSurface ?? [];
    const last = perSurface.length - 1;
    const x = SIDE_LABELS.map((_, k) => k + 3);
    const series: uPlot.Series[] = [{ label: 'sides', value: (_u, v) => (v === null ? '' : v >= 10 ? '10+' : String(v)) }];
    const data: number[][] = [x];
    perSurface.forEach((surface, k) => {
      const color = SURFACE_COLORS[k === 0 ? 0 : k === last ? 1 : 2 + ((k - 1) % 4)];
      const ends = k === 0 || k === last;
      series.push({
        label: stack.surfaces[k]?.name ?? `surface ${k}`,
        stroke: color,
        fill: ends ? `${color}99` : undefined,
        width: ends ? 1 : 2,
        paths: ends ? uPlot.paths.bars!({ size: [0.4, 60], align: k === 0 ? -1 : 1 }) : undefined,
        points: { show: !ends },
        value: (_u, v) => (v === null ? '' : `${v.toFixed(1)} %`),
      });
      data.push(surface.polygonDistribution.map((f) => 100 * f));
    });
    this.polygons.show(
      {
        title: 'Polygon distribution (%)',
        scales: { x: { time: false, range: [2.5, 10.5] } },
        axes: [{ values: (_u, ticks) => ticks.map((t) => (t >= 10 ? '10+' : String(t))) }, {}],
        series,
      },
      data as uPlot.AlignedData,
    );

    this.showLaws(stack);

    const iterations = stack.result.lloyd.iterations;
    this.energy.show(
      {
        title: 'CVT energy per iteration (µm⁴)',
        scales: { x: { time: false } },
        axes: [{}, { size: 72, values: (_u, ticks) => ticks.map((t) => t.toPrecision(3)) }],
        series: [
          { label: 'iteration' },
          { label: 'energy', stroke: '#1f5fa8', width: 2, points: { show: true }, value: (_u, v) => (v === null ? '' : v.toPrecision(6)) },
        ],
      },
      [iterations.map((r) => r.iteration), iterations.map((r) => r.energy)],
    );
  }

  /**
   * Lewis's law (mean area of n-sided cells over the mean area, against n, with (n - 2)/4) and
   * Aboav-Weaire (mean sides of the neighbours of n-sided cells, against n, with Aboav's
   * 5 + 8/n), one line per surface, from the analysis shown (valid cells).
   */
  private showLaws(stack: ViewStack): void {
    const perSurface = stack.analysis?.summary.perSurface ?? [];
    const last = perSurface.length - 1;
    const x = SIDE_LABELS.map((_, k) => k + 3);
    const color = (k: number) => SURFACE_COLORS[k === 0 ? 0 : k === last ? 1 : 2 + ((k - 1) % 4)];
    const line = (name: string, k: number): uPlot.Series => ({
      label: name,
      stroke: color(k),
      width: 2,
      points: { show: true, size: 6 },
      spanGaps: false,
      value: (_u, v) => (v === null ? '' : v.toFixed(2)),
    });
    const finite = (v: number) => (Number.isFinite(v) ? v : null);
    const names = perSurface.map((s, k) => stack.surfaces[k]?.name ?? s.label ?? `surface ${k}`);
    const method = stack.analysis?.method ?? '';
    this.lewis.show(
      {
        title: `Lewis's law: area of n-sided cells / mean area (${method})`,
        scales: { x: { time: false, range: [2.5, 10.5] } },
        axes: [{ values: sideTicks }, {}],
        series: [{ label: 'sides n' }, ...names.map(line), { label: '(n − 2) / 4', stroke: '#555', dash: [4, 4], width: 1, points: { show: false } }],
      },
      [x, ...perSurface.map((s) => s.lewis.map((e) => finite(e.normalizedArea))), x.map((n) => (n - 2) / 4)] as uPlot.AlignedData,
    );
    this.aboav.show(
      {
        title: `Aboav-Weaire: mean sides of the neighbours m(n) (${method})`,
        scales: { x: { time: false, range: [2.5, 10.5] } },
        axes: [{ values: sideTicks }, {}],
        series: [{ label: 'sides n' }, ...names.map(line), { label: '5 + 8/n (Aboav)', stroke: '#555', dash: [4, 4], width: 1, points: { show: false } }],
      },
      [x, ...perSurface.map((s) => s.aboavWeaire.map((e) => finite(e.meanNeighbourSides))), x.map((n) => 5 + 8 / n)] as uPlot.AlignedData,
    );
  }
}
