/**
 * The in-page sweep: % scutoids against the surface ratio (tube) or the thickness (plane, closed surfaces), over
 * a few realizations, run with src/core/sweep (expandSweep + runSweep) and runSheet as the
 * runner. Every grid point of a realization shares its random sites (seedMode
 * "per-realization"), as when the lab evaluates the same realizations at every ratio. The tidy
 * CSV is kept for download; the chart shows mean ± sd.
 */
import { validateAnyConfig, type AnyConfig as Config } from '../../core/config';
import { aggregateRows, expandSweep, runSweep } from '../../core/sweep';
import { isAbort, runInPage } from '../../view/pageRunner';
import { primaryAnalysis } from '../../view/stack';

export interface SweepPanelEvents {
  config(): Config;
  onPoints(label: string, points: { x: number; mean: number; sd: number }[]): void;
  onError(message: string): void;
}

export class SweepPanel {
  private controller: AbortController | null = null;
  /** The tidy CSV of the last sweep (header + one row per run). */
  csv = '';

  constructor(
    private readonly root: HTMLElement,
    private readonly events: SweepPanelEvents,
  ) {
    this.button('run').addEventListener('click', () => void this.run());
    this.button('cancel').addEventListener('click', () => this.controller?.abort());
  }

  private button(name: string): HTMLButtonElement {
    return this.root.querySelector<HTMLButtonElement>(`[data-sweep="${name}"]`)!;
  }

  private input(name: string): HTMLInputElement {
    return this.root.querySelector<HTMLInputElement>(`[name="sweep-${name}"]`)!;
  }

  private status(text: string): void {
    this.root.querySelector<HTMLElement>('[data-sweep="status"]')!.textContent = text;
  }

  /** The swept field and its values for the current surface. */
  private plan(config: Config): { field: string; label: string; values: number[] } {
    const from = Number(this.input('from').value);
    const to = Number(this.input('to').value);
    const steps = Math.max(2, Math.min(50, Math.round(Number(this.input('steps').value))));
    if (!Number.isFinite(from) || !Number.isFinite(to)) throw new Error('Sweep: give numbers for "from" and "to".');
    const values = Array.from({ length: steps }, (_, k) => Number((from + ((to - from) * k) / (steps - 1)).toPrecision(6)));
    if (config.surface.kind === 'tube') return { field: 'sheet.surfaceRatio', label: 'surface ratio', values };
    return { field: 'sheet.thickness', label: 'thickness (µm)', values };
  }

  async run(): Promise<void> {
    this.controller?.abort();
    const controller = new AbortController();
    this.controller = controller;
    this.button('cancel').disabled = false;
    try {
      const base = structuredClone(this.events.config());
      if (base.surface.kind === 'tube') base.sheet = { ...base.sheet, thickness: 0 };
      else base.sheet = { ...base.sheet, surfaceRatio: null };
      const { field, label, values } = this.plan(base);
      const realizations = Math.max(1, Math.min(20, Math.round(Number(this.input('realizations').value) || 1)));
      const runs = expandSweep({ base: base as unknown as Record<string, unknown>, vary: { [field]: values }, realizations, seedMode: 'per-realization' });
      let csv = '';
      const result = await runSweep({
        runs,
        fields: [field],
        signal: controller.signal,
        append: (text) => {
          csv += text;
        },
        runner: async (config) => {
          const output = await runInPage({ config: validateAnyConfig(config), signal: controller.signal });
          const analysis = primaryAnalysis(output.result);
          const summary = analysis?.summary;
          return {
            method: analysis?.method ?? '',
            percentScutoids: summary?.percentScutoids ?? Number.NaN,
            percentScutoidsEnds: summary?.percentScutoidsEnds ?? Number.NaN,
            meanTransitions: summary?.meanTransitions ?? Number.NaN,
            validCells: summary?.validCells ?? 0,
            finalEnergy: output.result.lloyd.finalEnergy,
          };
        },
        onProgress: (p) => this.status(`Sweep: ${p.finished} / ${p.total} runs (${(p.elapsedMs / 1000).toFixed(1)} s)`),
      });
      this.csv = csv;
      const aggregate = aggregateRows(result.rows, [field], ['percentScutoids']);
      const points = aggregate.points.map((p) => ({ x: Number(p.point[field]), mean: p.stats.percentScutoids.mean, sd: Number.isFinite(p.stats.percentScutoids.sd) ? p.stats.percentScutoids.sd : 0 }));
      this.events.onPoints(label, points);
      this.status(result.aborted ? `Sweep cancelled after ${result.completed} runs.` : `Sweep done: ${result.completed} runs.`);
      this.root.dataset.done = String(result.completed);
    } catch (error) {
      if (isAbort(error)) this.status('Sweep cancelled.');
      else this.events.onError((error as Error).message);
    } finally {
      if (this.controller === controller) this.controller = null;
      this.button('cancel').disabled = true;
    }
  }
}
