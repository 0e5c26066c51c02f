/**
 * `<tissue-sheet>`: a sheet computed and shown in any page. Attributes (kebab-case) configure
 * it, properties carry rich data (`config`, `densityImage`, `meshFile`), methods run, sweep and
 * export it, and events report on it (events.ts: `progress`, `result`, `error`, `warning`,
 * `waiting`, `cell-hover`, `sweep-progress`). A bare element shows the schema's default sheet
 * (the published tube), as the CLI runs it. Runs go to the page's one pipeline worker
 * (src/view/pageRunner.ts; the page itself after a fallback, which `computeSite` says); a newer
 * run cancels the previous one, or, on the slider path, replaces the one waiting (LatestRunner).
 * Each feature beside the run has a file of its own here (listed in docs/architecture.md,
 * "Consumers").
 */
import type { Config, ConfigInput } from '../core/config';
import type { GrayImage } from '../core/density';
import { ConfigError, validateConfig } from '../core/config';
import type { IterationRecord, MeshFile, SheetOutput, SheetResult, ComputeSite } from '../run';
import { isAbort, LatestRunner, computeSite as pipelineSite, computeContext } from '../view/pageRunner';
import { sweepInPage } from '../view/pageSweep';
import type {
  TissueSheetSweepOptions,
  TissueSheetSweepProgressDetail,
  TissueSheetSweepResult,
  TissueSheetErrorDetail,
  TissueSheetEventMap,
  TissueSheetProgressDetail,
  TissueSheetResultDetail,
  TissueSheetWaitingDetail,
  TissueSheetWarningDetail,
} from './events';
import { byConstruction } from '../core/analysis/byConstruction';
import { checkPageBudget } from '../view/pageBudget';
import { pendingSources, type ForeignSource } from '../view/sources';
import { primaryAnalysis } from '../view/stack';
import { askToLoad } from './sourcePrompt';
import { ATTRIBUTES, OTHER_ATTRIBUTES, configFromAttributes } from './attributes';
import { TEMPLATE } from './template';
import { unknownAttributes } from './unknownAttributes';
import { ElementRealizations, realizationStatus, realizationsOf } from './realizations';
import { LivePath } from './livePath';
import { ElementView } from './elementView';
import { StatusLine } from './statusLine';
import { resultStatus, showDrawn, showHeadline } from './resultDisplay';

export class TissueSheetElement extends HTMLElement {
  static get observedAttributes(): string[] {
    return [...Object.keys(ATTRIBUTES), ...OTHER_ATTRIBUTES];
  }

  private base: ConfigInput | null = null;
  private image: GrayImage | null = null;
  private mesh: MeshFile | null = null;
  private last: SheetResult | null = null;
  /** The 3D view, open while connected (elementView.ts). */
  private readonly view: ElementView;
  private readonly runner = new LatestRunner();
  /** The slider path: a change of `sheet.*` only redraws the result on screen from its seeded surface. */
  private readonly livePath = new LivePath(this.runner, (full) => this.drawStack(full));
  /** The other realizations of the latest run's headline, in the element's own worker. */
  private readonly realizationRuns = new ElementRealizations();
  private scheduled = false;
  private readonly shadow: ShadowRoot;
  /** What the element is doing, with its standing warnings. */
  private readonly statusLine: StatusLine;

  constructor() {
    super();
    this.shadow = this.attachShadow({ mode: 'open' });
    this.shadow.innerHTML = TEMPLATE;
    this.statusLine = new StatusLine(this.shadow.querySelector<HTMLElement>('.status')!);
    this.view = new ElementView(this.shadow, {
      hover: (picked) => this.emit('cell-hover', picked),
      lost: () =>
        this.fail(
          new WebGLContextLostError(
            'tissue-sheet: the 3D view lost its WebGL context (the browser drops the oldest one when a page holds too many, or the GPU was reset); it stays blank until the browser restores it or the element is connected again.',
          ),
        ),
      restored: () => this.status('The 3D view was restored.'),
      failed: (message) => this.status(`3D view: ${message}`, true),
    });
  }

  /**
   * The effective configuration. While an attribute is invalid it does not throw (issue 26): it
   * gives the last valid configuration read (else the last result's, else the defaults with the
   * `config` property), and `configError` says what is wrong; `run()` and the `error` event
   * report it.
   */
  get config(): Config {
    try {
      const config = this.readConfig();
      this.lastValid = config;
      return config;
    } catch {
      return this.lastValid ?? this.last?.config ?? validateConfig(this.base ?? {});
    }
  }

  /** What makes the attributes invalid, in words, or null when they are valid. */
  get configError(): string | null {
    try {
      this.readConfig();
      return null;
    } catch (error) {
      return (error as Error).message;
    }
  }

  private lastValid: Config | null = null;

  private readConfig(): Config {
    return configFromAttributes(this, this.base, this.mesh?.name);
  }

  /**
   * A configuration (fields may be left out); attributes still override its fields. Anything but
   * an object or null (`el.config = 5`, a JSON string) is refused: the setter throws a ConfigError
   * on `config`, also sent as an `error` event, and the configuration stays as it was.
   */
  set config(value: ConfigInput | null) {
    const given = value as unknown;
    if (given !== null && given !== undefined && (typeof given !== 'object' || Array.isArray(given))) {
      const what = Array.isArray(given) ? 'an array' : `a ${typeof given}`;
      const error = new ConfigError(
        'config',
        `config: expected a configuration object (or null), got ${what}; set fields as an object, e.g. el.config = { cells: 100 }`,
      );
      this.fail(error);
      throw error;
    }
    this.base = given ? structuredClone(value) : null;
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

  /**
   * Realizations the headline is over (the `realizations` attribute, 1 to 100; default 5): the
   * result event's headline is their mean with its 95 % CI; the cells shown are realization 1.
   */
  get realizations(): number {
    return realizationsOf(this.getAttribute('realizations'));
  }

  /** Without the `manual` attribute, the element runs when connected and when configured. */
  get manual(): boolean {
    return this.hasAttribute('manual');
  }

  connectedCallback(): void {
    this.warned.clear();
    this.checkAttributes();
    // Attributes set later that the element does not observe (a typo such as `cels`) are said too.
    this.attributeWatch.observe(this, { attributes: true });
    this.view.connect();
    this.schedule();
  }

  disconnectedCallback(): void {
    this.attributeWatch.disconnect();
    this.runner.cancel();
    this.realizationRuns.stop();
    // A browser keeps only so many WebGL contexts (about 16) and drops the oldest beyond that:
    // a removed element gives its context back at once (connecting it again makes a new one).
    this.view.disconnect();
  }

  /** The unknown attributes already warned about while connected (each is said once). */
  private readonly warned = new Set<string>();

  /** Changes of attributes the element does not observe (attributeChangedCallback sees the others). */
  private readonly attributeWatch = new MutationObserver((records) => {
    const observed = TissueSheetElement.observedAttributes;
    if (records.some((record) => record.attributeName !== null && !observed.includes(record.attributeName))) {
      this.checkAttributes();
      this.statusLine.refresh();
    }
  });

  /** Attributes the element does not know are said (a warning event each, and in the status). */
  private checkAttributes(): void {
    const unknown = unknownAttributes(this.getAttributeNames(), TissueSheetElement.observedAttributes);
    this.statusLine.setUnknownAttributes(unknown.map((warning) => warning.message));
    const fresh = unknown.filter((warning) => !this.warned.has(warning.attribute));
    this.warned.clear();
    for (const warning of unknown) this.warned.add(warning.attribute);
    for (const warning of fresh) this.emit<TissueSheetWarningDetail>('warning', warning);
  }

  /** Once: runs fell back from the worker to the page; said in the status and as a warning event. */
  private noteFallback(): void {
    const message = this.statusLine.noteFallback(pipelineSite());
    if (message) this.emit<TissueSheetWarningDetail>('warning', { message });
  }

  attributeChangedCallback(name: string, previous: string | null, next: string | null): void {
    if (previous !== next && name !== 'manual') this.schedule();
  }

  /** Runs the sheet now; resolves with the result (also sent as a `result` event). */
  async run(): Promise<SheetResult> {
    let config: Config;
    let n: number;
    try {
      config = this.readConfig();
      this.lastValid = config;
      n = this.realizations;
      // Untrusted attributes: the work is bounded before anything is allocated.
      checkPageBudget(config, computeContext().capabilities.maxTextureSize);
    } catch (error) {
      this.fail(error);
      throw error;
    }
    const pending = pendingSources(config, location.href);
    if (pending.length > 0) return this.waitForApproval(pending);
    // A question about an earlier configuration's source does not stay beside an unrelated run.
    this.shadow.querySelector<HTMLElement>('.ask')!.hidden = true;
    this.status(`Running ${config.cells} cells…`);
    // A change of `sheet.*` only (surface-ratio, thickness) on the result shown takes the app's
    // slider path (issue 27, livePath.ts): the result event follows in tens of milliseconds.
    const live = this.livePath.applies(config, this.image, this.mesh);
    const inputs = { densityImage: this.image ?? undefined, meshFile: config.surface.kind === 'mesh' ? this.mesh : null };
    try {
      const request = {
        config,
        ...inputs,
        onIteration: (record: IterationRecord, maxIterations: number) => {
          this.status(`Lloyd iteration ${record.iteration} / ${maxIterations}`);
          this.emit<TissueSheetProgressDetail>('progress', {
            iteration: record.iteration,
            maxIterations,
            energy: record.energy,
            maxDisplacement: record.maxDisplacement,
          });
        },
      };
      // The other realizations of the headline start at once in their own worker (issue 27).
      const realizations = this.realizationRuns.start(config, n, inputs);
      const output = await (live ? this.runner.live(request) : this.runner.start(request));
      this.livePath.show({ config, image: this.image, mesh: this.mesh, output }, live);
      this.noteFallback();
      try {
        this.drawStack(output);
      } catch (error) {
        this.status(`3D view: ${(error as Error).message}`, true);
      }
      const analysis = primaryAnalysis(output.result);
      const label = this.shadow.querySelector<HTMLElement>('.percent')!;
      showDrawn(label, analysis);
      const method = analysis?.method ?? 'labels';
      this.shadow.querySelector<HTMLElement>('.method')!.textContent = method;
      // The headline over realizations (realization 1 is on screen): the result event carries it.
      const headline = await realizations.combine(output, (done, total) => done < total && this.status(realizationStatus(config, done, total)));
      const result = { ...output.result, headline };
      this.last = result;
      const over = showHeadline(label, analysis, headline);
      this.status(resultStatus(config, output.result, analysis, over));
      const rule = byConstruction(config);
      this.emit<TissueSheetResultDetail>('result', {
        result,
        headline,
        percentScutoids: analysis?.summary.percentScutoids ?? Number.NaN,
        method,
        ...(rule ? { byConstruction: rule.message } : {}),
      });
      return result;
    } catch (error) {
      if (!isAbort(error)) this.fail(error);
      throw error;
    }
  }

  /** The stack of `output` in the 3D view (throws when the view cannot draw it). */
  private drawStack(output: SheetOutput): void {
    this.view.show(output);
  }

  /** Where runs compute: `{ where: 'worker' }`, or `{ where: 'page', reason }` after a fallback. */
  get computeSite(): ComputeSite {
    return pipelineSite();
  }

  /**
   * A parameter sweep with the CLI's spec (`{ base, vary, realizations, seed, seedMode }`,
   * docs/sweep.md), validated as the CLI does (a bad spec rejects with a SweepSpecError naming
   * the field). Resolves with the rows of the CLI's runs.csv and its aggregate (mean, sd, se, n
   * per grid point and aggregated metric), plus both files' text. A `sweep-progress` event follows every
   * finished run. The runs are spread over a pool of Web Workers (`workers`, default the
   * browser's cores less one, at least 1, at most 8), each continuing one realization's Lloyd run through its Voronoi k and ratios, as
   * the CLI does. Aborting `signal` stops after the runs in flight and resolves with the runs
   * finished so far (`aborted: true`); `resume` (a runs.csv of the same spec) skips its runs.
   */
  async sweep(spec: unknown, options: TissueSheetSweepOptions = {}): Promise<TissueSheetSweepResult> {
    const result = await sweepInPage(spec, {
      ...(options.signal ? { signal: options.signal } : {}),
      ...(options.resume ? { resumeCsv: options.resume } : {}),
      ...(options.workers !== undefined ? { workers: options.workers } : {}),
      onProgress: (p) => this.emit<TissueSheetSweepProgressDetail>('sweep-progress', p),
    });
    const { runs, aggregate, runsCsv, aggregateCsv, completed, skipped, aborted, header, workers } = result;
    return { runs, aggregate, runsCsv, aggregateCsv, completed, skipped, aborted, header, workers };
  }

  /** The last result as the documented JSON object (a copy); throws before the first result. */
  exportResult(): SheetResult {
    if (!this.last) throw new Error('tissue-sheet: no result yet; call run() or wait for the "result" event');
    return structuredClone(this.last);
  }

  /** A PNG (or `type`) of the 3D view. */
  toBlob(options: { type?: string } = {}): Promise<Blob> {
    return this.view.toBlob(options.type);
  }

  override addEventListener<K extends keyof TissueSheetEventMap>(
    type: K,
    listener: (this: TissueSheetElement, event: TissueSheetEventMap[K]) => unknown,
    options?: boolean | AddEventListenerOptions,
  ): void;
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
    this.emit<TissueSheetWaitingDetail>('waiting', { sources: pending.map((p) => ({ path: p.path, host: p.host })) });
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
    this.statusLine.show(text, error);
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

/** The `error` event's name when the browser took the 3D view's WebGL context away. */
class WebGLContextLostError extends Error {
  override name = 'WebGLContextLostError';
}
