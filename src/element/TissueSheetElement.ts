/**
 * `<tissue-sheet>`: a sheet computed and shown in any page. Attributes (kebab-case) configure
 * it, properties carry rich data (`config`, `densityImage`, `meshFile`), methods run and export it, and
 * `progress` / `result` / `error` events report on it. A bare element shows the app's small
 * default tube. Runs share one compute context per page and are queued.
 */
import type { AnyConfig, ConfigInput } from '../core/config';
import type { GrayImage } from '../core/density';
import { ConfigError } from '../core/config';
import type { MeshFile, SheetResult, ComputeSite } from '../run';
import { isAbort, LatestRunner, computeSite as pipelineSite, computeContext } from '../view/pageRunner';
import { sweepInPage } from '../view/pageSweep';
import type { TissueSheetSweepOptions, TissueSheetSweepProgressDetail, TissueSheetSweepResult, TissueSheetErrorDetail, TissueSheetEventMap, TissueSheetProgressDetail, TissueSheetResultDetail } from './events';
import { SheetView3D } from '../view/sheetView3d';
import { trackCellHover } from '../view/cellHover';
import { byConstruction } from '../core/analysis/byConstruction';
import { checkPageBudget } from '../view/pageBudget';
import { pendingSources, type ForeignSource } from '../view/sources';
import { methodCaption, primaryAnalysis, viewStack } from '../view/stack';
import { askToLoad } from './sourcePrompt';
import { ATTRIBUTES, OTHER_ATTRIBUTES, configFromAttributes } from './attributes';
import { TEMPLATE } from './template';

export class TissueSheetElement extends HTMLElement {
  static get observedAttributes(): string[] {
    return [...Object.keys(ATTRIBUTES), ...OTHER_ATTRIBUTES];
  }

  private base: ConfigInput | null = null;
  private image: GrayImage | null = null;
  private mesh: MeshFile | null = null;
  private last: SheetResult | null = null;
  private view: SheetView3D | null = null;
  private readonly runner = new LatestRunner();
  private scheduled = false;
  private readonly shadow: ShadowRoot;

  constructor() {
    super();
    this.shadow = this.attachShadow({ mode: 'open' });
    this.shadow.innerHTML = TEMPLATE;
  }

  /** The effective, validated configuration (throws ConfigError when the attributes are invalid). */
  get config(): AnyConfig {
    return configFromAttributes(this, this.base, this.mesh?.name);
  }

  /** A configuration (fields may be left out); attributes still override its fields. */
  set config(value: ConfigInput | null) {
    this.base = value ? structuredClone(value) : null;
    this.schedule();
  }

  /** The decoded grayscale image for `density.kind = "image"` (else the `src` URL is fetched). */
  get densityImage(): GrayImage | null {
    return this.image;
  }

  set densityImage(value: GrayImage | null) {
    this.image = value;
    this.schedule();
  }

  /**
   * A mesh file for `surface="mesh"`: `{ data: ArrayBuffer (or the text), name }`, e.g. a user's
   * File read with `await file.arrayBuffer()`. Used instead of fetching `src`; without a `src`
   * attribute the config's `surface.src` is its name.
   */
  get meshFile(): MeshFile | null {
    return this.mesh;
  }

  set meshFile(value: MeshFile | null) {
    this.mesh = value;
    this.schedule();
  }

  /** The last result, or null. */
  get result(): SheetResult | null {
    return this.last;
  }

  /** Without the `manual` attribute, the element runs when connected and when configured. */
  get manual(): boolean {
    return this.hasAttribute('manual');
  }

  connectedCallback(): void {
    if (!this.view) {
      try {
        this.view = new SheetView3D(this.shadow.querySelector('canvas')!);
        trackCellHover(this.view.canvas, this.view, ({ picked, changed }) => {
          if (changed) this.emit('cell-hover', picked ? { cell: picked.cell, surface: picked.surface } : null);
        });
      } catch {
        this.view = null; // the error event of the run says why
      }
    }
    this.schedule();
  }

  disconnectedCallback(): void {
    this.runner.cancel();
  }

  attributeChangedCallback(name: string, previous: string | null, next: string | null): void {
    if (previous !== next && name !== 'manual') this.schedule();
  }

  /** Runs the sheet now; resolves with the result (also sent as a `result` event). */
  async run(): Promise<SheetResult> {
    let config: AnyConfig;
    try {
      config = this.config;
    } catch (error) {
      this.fail(error);
      throw error;
    }
    try {
      // Untrusted attributes: the work is bounded before anything is allocated.
      checkPageBudget(config, computeContext().capabilities.maxTextureSize);
    } catch (error) {
      this.fail(error);
      throw error;
    }
    const pending = pendingSources(config, location.href);
    if (pending.length > 0) return this.waitForApproval(pending);
    this.status(`Running ${config.cells} cells…`);
    try {
      const output = await this.runner.start({
        config,
        densityImage: this.image ?? undefined,
        meshFile: config.surface.kind === 'mesh' ? this.mesh : null,
        onIteration: (record, maxIterations) => {
          this.status(`Lloyd iteration ${record.iteration} / ${maxIterations}`);
          this.emit<TissueSheetProgressDetail>('progress', { iteration: record.iteration, maxIterations, energy: record.energy, maxDisplacement: record.maxDisplacement });
        },
      });
      const stack = viewStack(output);
      try {
        this.view?.setStack(stack);
        this.view?.acceleratePicking();
      } catch (error) {
        this.status(`3D view: ${(error as Error).message}`, true);
      }
      this.last = output.result;
      const analysis = primaryAnalysis(output.result);
      const percent = analysis?.summary.percentScutoids ?? Number.NaN;
      const method = analysis?.method ?? 'labels';
      const label = this.shadow.querySelector<HTMLElement>('.percent')!;
      label.textContent = `${percent.toFixed(1)} %`;
      label.dataset.value = String(percent);
      label.dataset.method = method;
      label.title = `scutoids, from ${methodCaption(analysis)}`;
      this.shadow.querySelector<HTMLElement>('.method')!.textContent = method;
      const rule = byConstruction(output.result.config);
      const iterations = output.result.lloyd.iterations.length;
      this.status(rule ? rule.message : `${config.cells} cells, Voronoi ${iterations + 1} (${iterations} Lloyd iterations), ${config.surface.kind}, ${method} adjacency`);
      this.emit<TissueSheetResultDetail>('result', {
        result: output.result,
        headline: output.result.headline,
        percentScutoids: percent,
        method,
        ...(rule ? { byConstruction: rule.message } : {}),
      });
      return output.result;
    } catch (error) {
      if (!isAbort(error)) this.fail(error);
      throw error;
    }
  }

  /** Where runs compute: `{ where: 'worker' }`, or `{ where: 'page', reason }` after a fallback. */
  get computeSite(): ComputeSite {
    return pipelineSite();
  }

  /**
   * A parameter sweep with the CLI's spec (`{ base, vary, realizations, seed, seedMode }`,
   * docs/sweep.md), validated as the CLI does (a bad spec rejects with a SweepSpecError naming
   * the field). Resolves with the rows of the CLI's runs.csv and its aggregate (mean, sd, se, n
   * per grid point and column), plus both files' text. A `sweep-progress` event follows every
   * finished run. Aborting `signal` stops after the run in flight and resolves with the runs
   * finished so far (`aborted: true`); `resume` (a runs.csv of the same spec) skips its runs.
   */
  async sweep(spec: unknown, options: TissueSheetSweepOptions = {}): Promise<TissueSheetSweepResult> {
    const result = await sweepInPage(spec, {
      ...(options.signal ? { signal: options.signal } : {}),
      ...(options.resume ? { resumeCsv: options.resume } : {}),
      onProgress: (p) => this.emit<TissueSheetSweepProgressDetail>('sweep-progress', p),
    });
    const { runs, aggregate, runsCsv, aggregateCsv, completed, skipped, aborted, header } = result;
    return { runs, aggregate, runsCsv, aggregateCsv, completed, skipped, aborted, header };
  }

  /** The last result as the documented JSON object (a copy); throws before the first result. */
  exportResult(): SheetResult {
    if (!this.last) throw new Error('tissue-sheet: no result yet; call run() or wait for the "result" event');
    return structuredClone(this.last);
  }

  /** A PNG (or `type`) of the 3D view. */
  toBlob(options: { type?: string } = {}): Promise<Blob> {
    if (!this.view) return Promise.reject(new Error('tissue-sheet: no 3D view (WebGL is not available)'));
    return this.view.toBlob(options.type);
  }

  override addEventListener<K extends keyof TissueSheetEventMap>(type: K, listener: (this: TissueSheetElement, event: TissueSheetEventMap[K]) => unknown, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void;
  override addEventListener(type: string, listener: EventListenerOrEventListenerObject, options?: boolean | AddEventListenerOptions): void {
    super.addEventListener(type, listener, options);
  }

  /**
   * A source from another origin: the element shows "this element asks to load PATH from HOST"
   * and requests nothing until its button is clicked; then it runs.
   */
  private waitForApproval(pending: ForeignSource[]): Promise<SheetResult> {
    this.status('Waiting for permission to load a source from another site.');
    return new Promise<SheetResult>((resolve, reject) => {
      askToLoad(this.shadow, pending, () => this.run().then(resolve, reject));
    });
  }

  private schedule(): void {
    if (this.manual || !this.isConnected || this.scheduled) return;
    this.scheduled = true;
    setTimeout(() => {
      this.scheduled = false;
      if (this.isConnected) this.run().catch(() => undefined);
    }, 0);
  }

  private status(text: string, error = false): void {
    const line = this.shadow.querySelector<HTMLElement>('.status')!;
    line.textContent = text;
    line.classList.toggle('error', error);
  }

  private fail(error: unknown): void {
    const e = error instanceof Error ? error : new Error(String(error));
    const detail: TissueSheetErrorDetail = { message: e.message, name: e.name };
    if (error instanceof ConfigError) detail.field = error.field;
    this.status(e.message, true);
    this.emit('error', detail);
  }

  private emit<T>(type: keyof TissueSheetEventMap, detail: T): void {
    this.dispatchEvent(new CustomEvent(type, { detail, bubbles: true, composed: true }));
  }
}
