/**
 * The in-page sweep: any numeric field of the configuration, or Voronoi k (Lloyd iterations + 1),
 * from a value to another in a number of points, over realizations; the spec is the CLI's
 * (docs/sweep.md) and runs through src/view/pageSweep.ts, so runs.csv and aggregate.csv have the
 * CLI's columns and the realizations' seeded surfaces are reused as in the CLI. Every grid point
 * of a realization shares its random sites (seedMode "per-realization"), as when the lab
 * evaluates the same realizations at every ratio.
 *
 * The chart grows as runs finish (mean and 95 % CI, sweepChart.ts). Cancel keeps the finished
 * runs; Resume computes the rest. Downloads: runs.csv, aggregate.csv and sweep.json (the spec);
 * loading a sweep.json (the CLI's or ours) with its runs.csv shows it and lets it be resumed.
 * Reference curves (the shipped set, or the user's file) can be laid over the chart
 * (referenceOverlay.ts); they are never part of the downloads.
 */
import type { ConfigDraft } from '../../core/config';
import { readRunsCsv, FLINTSTONES_RATIO } from '../../core/sweep';
import { computeContext, isAbort } from '../../view/pageRunner';
import { methodsOnRenderer } from '../../core/config/analysisMethods';
import { flintstonesInTurns, planSweep, resumableRows, sweepInPage, type SweepPlan } from '../../view/pageSweep';
import { FlintstonesChart } from './flintstonesChart';
import { version } from '../../version';
import { download } from './exports';
import { downloadChart } from './chartExports';
import { FIELDS } from './fields';
import { SweepForm } from './sweepForm';
import { SweepChart } from './sweepChart';
import { ReferenceOverlay } from './referenceOverlay';

export interface SweepPanelEvents {
  config(): ConfigDraft;
  onError(message: string): void;
}

export class SweepPanel {
  private controller: AbortController | null = null;
  private readonly chart: SweepChart;
  /** The Flintstones law fitted after a sweep over the surface ratio. */
  private readonly flintstones: FlintstonesChart;
  /** Reference curves over the chart. */
  private readonly reference: ReferenceOverlay;
  /** The sweep on screen: its spec (plain JSON) and its runs.csv so far. */
  private spec: unknown = null;
  private runsCsv = '';
  private aggregateCsv = '';
  private readonly form: SweepForm;

  constructor(
    private readonly root: HTMLElement,
    private readonly events: SweepPanelEvents,
  ) {
    this.chart = new SweepChart(root.querySelector<HTMLElement>('#chart-sweep') ?? root);
    const fits = document.createElement('div');
    fits.id = 'chart-flintstones';
    (root.querySelector<HTMLElement>('#chart-sweep') ?? root).after(fits);
    this.flintstones = new FlintstonesChart(fits);
    this.reference = new ReferenceOverlay(root.querySelector<HTMLElement>('#chart-sweep') ?? root, this.chart);
    this.form = new SweepForm(
      root,
      () => events.config(),
      (text) => this.status(text),
    );
    this.buildControls();
    this.button('run').addEventListener('click', () => void this.runNew());
    this.button('cancel').addEventListener('click', () => this.controller?.abort());
    this.button('resume').addEventListener('click', () => void this.resume());
    this.button('runs-csv').addEventListener('click', () => this.download('runs.csv', this.runsCsv, 'text/csv'));
    this.button('aggregate-csv').addEventListener('click', () => this.download('aggregate.csv', this.aggregateCsv, 'text/csv'));
    this.button('spec').addEventListener('click', () =>
      this.download(
        'sweep.json',
        this.spec ? `${JSON.stringify({ software: { name: 'tissue-sheet', version }, spec: this.spec }, null, 2)}\n` : '',
        'application/json',
      ),
    );
    for (const kind of ['svg', 'png'] as const) {
      this.button(`chart-${kind}`).addEventListener('click', () => void this.figure(kind, 'chart'));
      this.button(`fit-${kind}`).addEventListener('click', () => void this.figure(kind, 'fit'));
    }
    this.root.querySelector<HTMLInputElement>('[name="sweep-load"]')!.addEventListener('change', (event) => void this.load(event.target as HTMLInputElement));
    this.form.refresh();
    this.root.querySelector('.sweep-controls')?.addEventListener('focusin', () => this.form.refresh());
  }

  /** The configuration changed (a result is shown): the fields that can be varied follow it. */
  configChanged(): void {
    this.form.refresh();
  }

  /** The tidy runs.csv of the sweep on screen (the CLI's columns). */
  get csv(): string {
    return this.runsCsv;
  }

  private buildControls(): void {
    const controls = this.root.querySelector<HTMLElement>('.sweep-controls')!;
    const label = document.createElement('label');
    label.append('vary ', this.form.field);
    controls.prepend(label);
    const status = controls.querySelector('[data-sweep="status"]');
    const extra = document.createElement('span');
    extra.className = 'sweep-files';
    extra.innerHTML = `<button type="button" data-sweep="resume" disabled title="Compute the runs this sweep still lacks">Resume</button>
      <button type="button" data-sweep="runs-csv" disabled>runs.csv</button>
      <button type="button" data-sweep="aggregate-csv" disabled>aggregate.csv</button>
      <button type="button" data-sweep="spec" disabled>sweep.json</button>
      <button type="button" data-sweep="chart-svg" disabled title="The sweep chart as SVG, at the width chosen under the exports">chart SVG</button>
      <button type="button" data-sweep="chart-png" disabled title="The sweep chart as PNG, at the DPI and width chosen under the exports">chart PNG</button>
      <button type="button" data-sweep="fit-svg" disabled title="The Flintstones fit as SVG">fit SVG</button>
      <button type="button" data-sweep="fit-png" disabled title="The Flintstones fit as PNG">fit PNG</button>
      <label title="A sweep.json (this page's or the CLI's) and its runs.csv, to see them and resume">load <input name="sweep-load" type="file" multiple accept=".json,.csv,application/json,text/csv" /></label>`;
    controls.insertBefore(extra, status);
  }

  private button(name: string): HTMLButtonElement {
    return this.root.querySelector<HTMLButtonElement>(`[data-sweep="${name}"]`)!;
  }

  private status(text: string): void {
    this.root.querySelector<HTMLElement>('[data-sweep="status"]')!.textContent = text;
  }

  private chartFor(plan: SweepPlan, spec: unknown): void {
    const field = plan.fields[0] ?? '';
    const voronoi = field === 'lloyd.maxIterations';
    const label = voronoi ? 'Voronoi k' : (FIELDS.find((f) => f.path === field)?.label ?? field);
    // Only the methods the runs report on this renderer: "both" on the exact engine (auto on a
    // software renderer) gives the exact method alone, so no empty labels series is listed.
    const renderer = { softwareRenderer: safeSoftwareRenderer() };
    const reported = new Set([...plan.pointConfigs.values()].flatMap((config) => methodsOnRenderer(config, renderer)));
    const methods = ['exact', 'labels'].filter((m) => plan.summary.includes(`${m}.percentScutoids`) && reported.has(m as 'exact' | 'labels'));
    this.chart.reset({ label, field, methods, x: (cell) => (voronoi ? Number(cell) + 1 : Number(cell)) });
    this.reference.setSweep(field, (spec as { base?: unknown }).base);
  }

  private async runNew(): Promise<void> {
    let spec: unknown;
    try {
      spec = this.form.spec();
    } catch (error) {
      this.refuse(error);
      return;
    }
    await this.execute(spec, '');
  }

  /** A sweep refused before its first run (a bad spec or grid point): said, and nothing runs. */
  private refuse(error: unknown): void {
    const message = (error as Error).message;
    this.root.dataset.state = 'error';
    this.status(`Sweep not run: ${message}`);
    this.events.onError(message);
  }

  private async resume(): Promise<void> {
    if (this.spec) await this.execute(this.spec, this.runsCsv);
  }

  private async execute(spec: unknown, resumeCsv: string): Promise<void> {
    this.controller?.abort();
    const controller = new AbortController();
    this.controller = controller;
    let plan: SweepPlan;
    let resumed: Record<string, string>[];
    try {
      plan = planSweep(spec);
      resumed = resumableRows(plan, resumeCsv).rows;
    } catch (error) {
      this.refuse(error);
      return;
    }
    this.spec = spec;
    this.chartFor(plan, spec);
    this.chart.add(resumed);
    this.setBusy(true);
    delete this.root.dataset.done;
    this.root.dataset.state = 'running';
    this.root.dataset.finished = '0';
    const total = plan.runs.length;
    try {
      const result = await sweepInPage(spec, {
        signal: controller.signal,
        resumeCsv,
        onProgress: (p) => {
          if (p.row) this.chart.add([p.row]);
          this.root.dataset.finished = String(p.skipped + p.finished);
          const rate = p.finished / Math.max(1e-3, p.elapsedMs / 1000);
          this.status(`Sweep: ${p.skipped + p.finished} / ${total} runs (${rate.toFixed(2)} runs/s)${p.error ? `; failed ${p.run.key}: ${p.error}` : ''}`);
        },
      });
      this.runsCsv = result.runsCsv;
      this.aggregateCsv = result.aggregateCsv;
      // The chart and its figure hold exactly the sweep's runs (a progress event without its row
      // would otherwise leave a point short of a realization).
      this.chart.setRows(result.runs);
      // Over the surface ratio: the aggregate's Flintstones fits (one per Voronoi k), drawn. They
      // are made one per turn (no long task); a sweep started meanwhile owns the panel.
      const fits = plan.fields.includes(FLINTSTONES_RATIO) ? await flintstonesInTurns(result.runs, plan.runs, plan.fields) : [];
      if (this.controller !== controller) return;
      this.flintstones.show(fits, result.runs);
      const done = result.runs.length;
      this.root.dataset.finished = String(done);
      this.root.dataset.done = String(done);
      this.root.dataset.state = result.aborted ? 'cancelled' : 'done';
      this.root.dataset.workers = String(result.workers);
      const rejected =
        result.rejected.length > 0
          ? ` ${result.rejected.length} rows of the loaded runs.csv were not valid for this spec and were computed again (first: line ${result.rejected[0].line}, ${result.rejected[0].reason}).`
          : '';
      this.status(
        result.aborted
          ? `Sweep cancelled: ${done} of ${total} runs kept; Resume computes the other ${total - done}.${rejected}`
          : `Sweep done: ${done} runs (${result.completed} computed on ${result.workers} worker${result.workers === 1 ? '' : 's'}, ${result.skipped} loaded).${rejected}`,
      );
    } catch (error) {
      if (isAbort(error)) {
        this.root.dataset.state = 'cancelled';
        this.status('Sweep cancelled.');
      } else {
        // A failed sweep says so and stops: the panel never stays at "k / N" as if running.
        const message = (error as Error).message;
        const kept = this.root.dataset.finished ?? '0';
        this.root.dataset.state = 'error';
        this.status(`Sweep failed after ${kept} of ${total} runs: ${message}`);
        this.events.onError(`Sweep failed: ${message}`);
      }
    } finally {
      if (this.controller === controller) this.controller = null;
      this.setBusy(false);
    }
  }

  private setBusy(busy: boolean): void {
    this.button('cancel').disabled = !busy;
    this.button('run').disabled = busy;
    // Resume is offered while some run lacks a valid row (rows set aside count as lacking).
    let done = 0;
    let total = 0;
    try {
      const plan = this.spec ? planSweep(this.spec) : null;
      total = plan ? plan.runs.length : 0;
      done = plan ? resumableRows(plan, this.runsCsv).rows.length : 0;
    } catch {
      total = 0;
    }
    this.button('resume').disabled = busy || !this.spec || done >= total;
    for (const name of ['runs-csv', 'aggregate-csv', 'spec', 'chart-svg', 'chart-png']) this.button(name).disabled = busy || !this.spec;
    for (const name of ['fit-svg', 'fit-png']) this.button(name).disabled = busy || !this.flintstones.figure();
  }

  /** The sweep chart or the Flintstones fit as a figure file, with the sweep's provenance. */
  private async figure(kind: 'svg' | 'png', which: 'chart' | 'fit'): Promise<void> {
    try {
      const rows = readRunsCsv(this.runsCsv).rows;
      const paths = [...new Set(rows.map((row) => row.centroidPath).filter(Boolean))];
      const engine = paths.length === 0 ? 'unknown' : paths.map((p) => (/exact engine/.test(p) ? 'exact engine' : `GPU, centroid path ${p}`)).join(', ');
      const spec = this.spec as { base?: { seed?: number }; seed?: number } | null;
      const figure = which === 'chart' ? this.chart.figure() : this.flintstones.figure();
      const methods =
        which === 'chart'
          ? (figure?.series
              .filter((s) => s.band)
              .map((s) => s.label.split(' ')[0])
              .join(', ') ?? '')
          : 'exact wherever the runs have it (meanNeighbours3D)';
      await downloadChart(kind, which === 'chart' ? 'tissue-sheet-sweep-chart' : 'tissue-sheet-flintstones-fit', figure, {
        what: which === 'chart' ? 'tissue-sheet sweep chart (% scutoids, mean and 95 % CI per point)' : 'tissue-sheet Flintstones law fit',
        engine,
        method: methods,
        seed: spec?.seed ?? spec?.base?.seed ?? '',
        config: this.spec,
      });
    } catch (error) {
      this.events.onError((error as Error).message);
    }
  }

  /** Loads a sweep.json (a spec, or a record with `spec`) and its runs.csv. */
  private async load(input: HTMLInputElement): Promise<void> {
    const files = [...(input.files ?? [])];
    input.value = '';
    try {
      let spec: unknown = null;
      let specGiven = false;
      let csv = '';
      for (const file of files) {
        const text = await file.text();
        if (/\.csv$/i.test(file.name) || text.startsWith('key,')) csv = text;
        else {
          let data: unknown;
          try {
            data = JSON.parse(text);
          } catch {
            throw new Error(`${file.name}: not JSON; load a sweep.json and its runs.csv`);
          }
          spec = data && typeof data === 'object' && 'spec' in data ? (data as { spec: unknown }).spec : data;
          // A file that holds no spec (null, a record whose spec is null) is refused, never read
          // as "keep the sweep on screen with no rows".
          if (spec === null || typeof spec !== 'object')
            throw new Error(`${file.name}: holds no sweep spec (got ${spec === null ? 'null' : typeof spec}); load a sweep.json and its runs.csv`);
          specGiven = true;
        }
      }
      // A runs.csv alone: the rows of the sweep on screen.
      if (!specGiven) spec = this.spec;
      if (!spec) throw new Error('Load a sweep.json (the spec) together with its runs.csv.');
      const plan = planSweep(spec);
      // The rows a resume keeps, checked now: a row of another configuration is never drawn.
      const { rows, rejected } = resumableRows(plan, csv);
      this.spec = spec;
      this.runsCsv = csv;
      this.aggregateCsv = '';
      this.form.show(spec);
      this.chartFor(plan, spec);
      this.chart.add(rows);
      this.root.dataset.done = String(rows.length);
      const aside =
        rejected.length > 0
          ? ` ${rejected.length} rows do not fit this spec and are not drawn; Resume computes them again (first: line ${rejected[0].line}, ${rejected[0].reason}).`
          : '';
      this.status(`Loaded a sweep of ${plan.runs.length} runs with ${rows.length} valid rows in its runs.csv; Resume computes the rest.${aside}`);
      this.setBusy(false);
    } catch (error) {
      this.events.onError((error as Error).message);
    }
  }

  private download(name: string, text: string, type: string): void {
    if (!text) {
      this.events.onError(
        name === 'aggregate.csv' ? 'The aggregate is written when a sweep finishes or is cancelled; resume the loaded sweep first.' : 'Run a sweep first.',
      );
      return;
    }
    download(name, text, type);
  }
}

/** Whether this page's compute context is a software renderer (false when there is none). */
function safeSoftwareRenderer(): boolean {
  try {
    return computeContext().capabilities.softwareRenderer;
  } catch {
    return false;
  }
}
