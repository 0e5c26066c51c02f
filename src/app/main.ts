/**
 * The biologist's page: wires the configuration panel, the runs, the views, the results, the
 * charts, the sweep and the exports. The configuration lives in the URL and in localStorage;
 * errors are shown in words and leave the previous result on screen.
 */
import { ConfigError, validateConfig, validateConfigDraft, type Config, type ConfigDraft } from '../core/config';
import { GpuCapabilityError, type SheetOutput } from '../run';
import { computeContext, isAbort, LatestRunner, onComputeSite, runInPage } from '../view/pageRunner';
import { initialConfig, readLink, saveConfig, urlWithConfig } from './model/settings';
import { checkPageBudget } from '../view/pageBudget';
import { pendingSources } from '../view/sources';
import { version } from '../version';
import { bindHelp } from './panels/help';
import { LinkAlert, SourceQuestion } from './panels/notices';
import { viewStack, type ViewStack } from '../view/stack';
import { Charts } from './panels/charts';
import { ConfigControls } from './panels/controls';
import { bindExports } from './panels/exports';
import { rerunNote, type OpenedFile, type RunOutcome } from './model/project';
import { renderHeadline, renderResults } from './panels/results';
import { cellSizeNote, explainRefusal } from './model/refusal';
import { changedFields, setMeshExtent } from './panels/fields';
import { RealizationsPanel } from './panels/realizationsPanel';
import { SweepPanel } from './panels/sweepPanel';
import { mountLloydMovie } from './panels/lloydMovie';
import { ViewPanel } from './panels/viewPanel';
import { renderLegend } from './view/legend';

const $ = <T extends HTMLElement>(selector: string) => document.querySelector<T>(selector)!;
const statusLine = $('#status');
const progress = $<HTMLProgressElement>('#progress');
const errorBox = $('#error');
const cancelButton = $<HTMLButtonElement>('#cancel');

/** Debounce of typed edits, ms. Slider drags are not debounced: they stream (LatestRunner.live). */
const EDIT_DEBOUNCE_MS = 400;

let stack: ViewStack | null = null;
/**
 * The form's config of the result on screen (a default resolution left null), which the address
 * and the saved session hold: it reproduces the result and keeps following the form's defaults.
 */
let shownDraft: ConfigDraft | null = null;
/** The draft of the latest run asked for (JSON). */
let lastDraft = '';
/** Whether the latest run asked for was a slider's live run (its pictures are drafts). */
let lastRunLive = false;
/** A slider is being dragged: its "input" events came, its "change" has not yet. */
let dragging = false;
let runs = 0;
const runner = new LatestRunner();

const realizations = new RealizationsPanel({
  input: $<HTMLInputElement>('#realizations'),
  main: $('main'),
  shown: () => stack,
  replace: (next) => (stack = next),
  onError: (message) => showError(message),
  onValid: (message) => {
    if (errorBox.querySelector('.error-main')?.textContent === message) clearError();
  },
  // The realizations' worker may report it stopped after a new run has begun (run() stops it
  // first): a run under way keeps Cancel enabled whatever the runner has reached.
  onBusy: () => (cancelButton.disabled = !runner.running && !realizations.running && document.body.dataset.state !== 'running'),
});

function setState(state: 'running' | 'done' | 'error' | 'cancelled' | 'no-webgl' | 'waiting' | 'refused'): void {
  document.body.dataset.state = state;
}

/**
 * Shows an error: a refusal in a biologist's words (model/refusal.ts), the engine's own message
 * on a details line when the main line replaced it.
 */
function showError(error: unknown, config: Config | null = null): void {
  const { message, details } =
    error instanceof ConfigError || error instanceof GpuCapabilityError || error instanceof Error
      ? explainRefusal(error, config)
      : { message: String(error), details: null };
  const main = document.createElement('span');
  main.className = 'error-main';
  main.textContent = message;
  errorBox.replaceChildren(main);
  if (details) {
    const more = document.createElement('details');
    more.className = 'error-details';
    more.append(Object.assign(document.createElement('summary'), { textContent: 'Details (for the engine)' }), ' ', details);
    errorBox.append(more);
  }
  errorBox.hidden = false;
  markStale();
}

/**
 * Marks the result on screen stale while the form describes another configuration (an edit not
 * yet run, running, or refused): `#stale-note` says which fields differ, and the body's
 * `data-stale` is "true" until a result of the form's configuration is shown.
 */
function markStale(): void {
  const note = $('#stale-note');
  const form = controls.config;
  const diffs = shownDraft ? changedFields(shownDraft, form) : [];
  const stale = stack !== null && shownDraft !== null && diffs.length > 0;
  document.body.dataset.stale = String(stale);
  note.hidden = !stale;
  if (!stale) {
    note.textContent = '';
    return;
  }
  const state = document.body.dataset.state;
  const why =
    state === 'running'
      ? 'computing the new one…'
      : state === 'error' || state === 'refused'
        ? 'the new values were not run (see the message above).'
        : 'the new values have not been run yet.';
  note.textContent = `Stale: this result is for ${diffs.map((d) => `${d.label} ${d.shown}`).join(', ')}; the form says ${diffs.map((d) => `${d.label} ${d.form}`).join(', ')}; ${why}`;
}

/**
 * True when `draft` (or its validated `config`) is the link's own configuration (its errors stay
 * until dismissed, its questions say "This link"). Both forms are compared: validation fills in
 * defaults (a mesh surface's), so a validated config never equals the link's draft as written.
 */
function isLinkConfig(draft: unknown, config?: Config): boolean {
  if (linkConfig === null) return false;
  if (JSON.stringify(draft) === JSON.stringify(linkConfig)) return true;
  return config !== undefined && linkValidated !== null && JSON.stringify(config) === linkValidated;
}

/** A configuration that cannot run: a link's refusal stays until dismissed, an edit's until the next run. */
function refuse(error: unknown, fromLink: boolean, config: Config | null = null): void {
  const message = error instanceof Error ? error.message : String(error);
  setState(fromLink ? 'refused' : 'error');
  if (fromLink) linkAlert.show(`This link's configuration was not run: ${message}`);
  else showError(error, config);
  markStale();
}

function clearError(): void {
  errorBox.hidden = true;
  errorBox.textContent = '';
}

renderLegend($('#legend'));
/** The address's configuration, read once: a link is untrusted input, validated and never stored. */
const link = readLink(location.href);
const linkConfig = link.kind === 'ok' ? link.config : null;
const openedLink = linkConfig ? { config: linkConfig, href: location.href } : null;
/** The link's configuration validated (JSON), or null when it has none or it does not validate. */
const linkValidated = ((): string | null => {
  try {
    return linkConfig ? JSON.stringify(validateConfig(validateConfigDraft(linkConfig))) : null;
  } catch {
    return null;
  }
})();
const linkAlert = new LinkAlert($('#link-alert'));
const sourceQuestion = new SourceQuestion($('#source-question'));
for (const element of document.querySelectorAll('[data-version]')) element.textContent = version;
bindHelp($('#help-open'), $<HTMLDialogElement>('#help'));
const viewPanel = new ViewPanel($('main'), $('#unrolled'));
const charts = new Charts($('#chart-polygons'), $('#chart-energy'), $('#chart-lewis'), $('#chart-aboav'));
const controls = new ConfigControls($('#controls'), initialConfig(link), {
  onEdit: (draft, live, forced) => {
    queueMicrotask(markStale);
    // A mesh file uploaded under the name the configuration already holds (a link asking for
    // the file again): the draft is the same, but the file is new, so it runs; once it has, the
    // link's "upload it again" is answered.
    if (forced) {
      void run(draft).then((outcome) => {
        if (outcome.kind === 'done') linkAlert.dismiss();
      });
      return;
    }
    // A slider's "change" after its last "input" asks for the run already under way: skip it,
    // but draw the drag's draft pictures again in full once it has settled.
    dragging = live;
    if (JSON.stringify(draft) === lastDraft) {
      if (!live && lastRunLive) {
        runner.debounced(EDIT_DEBOUNCE_MS, () => void redrawInFull());
        // The drag's last result, if already on screen, is saved now (else when it arrives).
        if (!runner.running && shownDraft) saveConfig(shownDraft, openedLink);
      }
      return;
    }
    if (live) void run(draft, true);
    else runner.debounced(EDIT_DEBOUNCE_MS, () => void run(draft));
  },
  onError: showError,
});
const sweep = new SweepPanel($('#sweep'), {
  config: () => validateConfigDraft(controls.config),
  onError: showError,
});
mountLloydMovie($('#cells-title').closest('section')!, { config: () => validateConfig(controls.config), onError: showError });
const opener = bindExports($('.exports'), {
  stack: () => stack,
  sweepCsv: () => sweep.csv,
  viewPng: () => viewPanel.toBlob(),
  onError: showError,
  view: () => viewPanel.view,
  viewState: () => viewPanel.viewState(),
  onOpen: (file, name) => openInPage(file, name),
  onOpenProgress: (line, fraction) => {
    statusLine.textContent = line;
    progress.max = 1;
    progress.value = fraction;
  },
}); // A large result's pictures with the stripes toggled: drawn in the worker holding it.
viewPanel.picturesElsewhere = (shown, on) => (opener?.holdShown(shown) ? opener.pictures(shown, on) : Promise.resolve(false));

/** Shows an opened project (exactly as saved) or result JSON (drawn from its cells, or re-run). */
async function openInPage(file: OpenedFile, name: string): Promise<void> {
  runner.cancel();
  clearError();
  const config = file.kind === 'result-rerun' ? file.result.config : file.output.result.config;
  controls.setConfig(config);
  // The file's number of realizations: the control and the address say the n of its headline.
  realizations.setFromFile((file.kind === 'result-rerun' ? file.result : file.output.result).headline?.realizations);
  if (file.kind === 'result-rerun') {
    // The note compares the file with this run's result only, never with what was on screen.
    const outcome = await run(config);
    statusLine.textContent = `Opened ${name}: ${rerunNote(file.result, outcome)}`;
    return;
  }
  // The form's rebuild and the views in tasks of their own (issue 27: no task over 50 ms).
  await nextTask();
  await show(file.output, config, false, true);
  if (file.kind === 'project' && stack) viewPanel.restore(stack, file.view);
  saveConfig(config, openedLink);
  realizations.syncParam();
  statusLine.textContent =
    file.kind === 'project'
      ? `Opened project ${name}: the result and view as saved; nothing was run.`
      : `Opened ${name}: statistics from the file; the pictures are the exact cells of its sites (nothing was run).`;
  setState('done');
}

/** Lets the browser handle input between the parts of drawing a result (no task over ~50 ms). */
const nextTask = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/** During a drag, the charts follow the results at most this often (ms), and once it pauses. */
const LIVE_CHARTS_MS = 300;
let chartsTimer: ReturnType<typeof setTimeout> | undefined;
let chartsDrawnAt = 0;

/**
 * Draws the charts of `shown`; during a drag (`live`) at most every LIVE_CHARTS_MS: four uPlot
 * canvases redrawn for every streamed result kept a software GPU busy enough to stall the main
 * thread (its 2D canvas commands wait for the GPU process) for 100-500 ms.
 */
function showCharts(shown: ViewStack, live: boolean): void {
  clearTimeout(chartsTimer);
  const wait = live ? chartsDrawnAt + LIVE_CHARTS_MS - performance.now() : 0;
  if (wait > 0) {
    chartsTimer = setTimeout(() => stack === shown && showCharts(shown, false), wait);
    return;
  }
  chartsDrawnAt = performance.now();
  charts.showStack(shown);
}

async function show(output: SheetOutput, draft: ConfigDraft, live = false, opened = false): Promise<void> {
  let shown = viewStack(output);
  // A headline over realizations already computed for this configuration and n is shown at once.
  const prepared = realizations.prepare(shown, opened);
  const { waiting, n } = prepared;
  shown = prepared.stack;
  stack = shown;
  shownDraft = draft;
  // Which pictures are on screen: a drag's drafts, or full (redrawInFull follows a drag).
  document.body.dataset.pictures = live ? 'draft' : 'full';
  try {
    viewPanel.show(shown);
  } catch (error) {
    showError(`The 3D view could not draw this result: ${(error as Error).message}`);
  }
  await nextTask();
  if (stack !== shown) return; // a newer result is being drawn
  renderResults($('main'), shown);
  const surface = shown.result.config.surface;
  if (surface.kind === 'mesh' && shown.result.closed) {
    setMeshExtent(surface.src, surface.scale, shown.result.closed.area);
    controls.refreshControls();
  }
  if (waiting) renderHeadline($('main'), shown, { state: 'waiting', n });
  if (!live) sweep.configChanged();
  await nextTask();
  if (stack !== shown) return;
  showCharts(shown, live);
}

/**
 * Validates and runs `draft`; on success the result replaces the one on screen. `live` (a slider
 * being dragged) waits for the run in flight instead of cancelling it, so pictures stream.
 */
async function run(draft: ConfigDraft, live = false): Promise<RunOutcome> {
  lastDraft = JSON.stringify(draft);
  lastRunLive = live;
  let config: Config;
  let input: ConfigDraft;
  try {
    input = validateConfigDraft(draft);
    config = validateConfig(input);
  } catch (error) {
    refuse(error, isLinkConfig(draft));
    return { kind: 'refused', message: (error as Error).message };
  }
  try {
    // The work is bounded before anything is allocated (the page cannot raise the budget).
    checkPageBudget(config, computeContext().capabilities.maxTextureSize);
  } catch (error) {
    refuse(error, isLinkConfig(draft, config), config);
    return { kind: 'refused', message: (error as Error).message };
  }
  const pending = pendingSources(config, location.href);
  if (pending.length > 0) {
    // Nothing is requested from another origin before the user's click.
    sourceQuestion.ask(pending, isLinkConfig(draft, config) ? 'This link' : 'This configuration', () => void run(config));
    statusLine.textContent = `Waiting: load ${pending[0].path} from ${pending[0].host}?`;
    setState('waiting');
    markStale();
    return { kind: 'waiting', path: pending[0].path, host: pending[0].host };
  }
  sourceQuestion.close();
  clearError();
  realizations.stop();
  setState('running');
  markStale();
  cancelButton.disabled = false;
  const sizeNote = cellSizeNote(config);
  statusLine.textContent = sizeNote ? `Running… ${sizeNote}` : 'Running…';
  progress.max = Math.max(1, config.lloyd.maxIterations);
  progress.value = 0;
  const started = performance.now();
  try {
    const output = await (live ? runner.live.bind(runner) : runner.start.bind(runner))({
      config,
      onIteration(record, total) {
        progress.max = Math.max(1, total);
        progress.value = record.iteration;
        statusLine.textContent = `Lloyd iteration ${record.iteration} / ${total}, energy ${record.energy.toPrecision(6)} µm⁴${sizeNote ? `. ${sizeNote}` : ''}`;
      },
    });
    await show(output, input, live);
    // Saved once it ran: the URL and the session hold the configuration of the result on screen
    // (during a drag only once it ends: history.replaceState took 5-30 ms per streamed result).
    if (!live || !dragging) {
      saveConfig(input, openedLink);
      realizations.syncParam();
    }
    runs += 1;
    document.body.dataset.runs = String(runs);
    const note = cellSizeNote(config, output.result.closed?.area ?? undefined);
    statusLine.textContent = `Done in ${((performance.now() - started) / 1000).toFixed(1)} s.${siteNote}${note ? ` ${note}` : ''}`;
    progress.value = progress.max;
    setState('done');
    markStale();
    if (!live) void realizations.start(output);
    return { kind: 'done', result: output.result };
  } catch (error) {
    if (isAbort(error)) {
      // A newer run replaced this one, or the user cancelled: the previous result stays.
      if (!runner.running) {
        statusLine.textContent = 'Cancelled; the previous result is still shown.';
        setState('cancelled');
        markStale();
      }
      return { kind: 'cancelled' };
    }
    // A link's input the run could not use (its density image, its mesh): said as the link's.
    if (error instanceof ConfigError && isLinkConfig(draft, config)) {
      refuse(error, true, config);
      statusLine.textContent = 'The link was not used.';
      return { kind: 'refused', message: error.message };
    }
    setState(error instanceof GpuCapabilityError ? 'no-webgl' : 'error');
    showError(error, config);
    statusLine.textContent = stack ? 'Failed; the previous result is still shown.' : 'Failed.';
    return { kind: 'failed', message: (error as Error).message };
  } finally {
    cancelButton.disabled = !runner.running;
  }
}

/**
 * A drag's results are shown with draft pictures (LatestRunner.live): once it has settled, the
 * result on screen is fetched again (the worker's cached surfaces: same numbers) with the full
 * pictures and only the views are redrawn; the run count and state are untouched.
 */
async function redrawInFull(): Promise<void> {
  const shown = stack;
  if (!shown || runner.running) return;
  try {
    const output = await runInPage({ config: shown.result.config });
    if (stack !== shown || runner.running) return;
    stack = viewStack(output);
    viewPanel.show(stack);
    document.body.dataset.pictures = 'full';
    void realizations.start(output);
  } catch {
    // The draft pictures stay: they show the same result.
  }
}

function runWith(change: (config: ConfigDraft) => ConfigDraft): void {
  const next = change(controls.config);
  controls.setConfig(next);
  void run(next);
}

// Where the pipeline runs: said in the page when it fell back from the worker to the main thread.
let siteNote = '';
onComputeSite((site) => {
  document.body.dataset.computeSite = site.where;
  siteNote = site.where === 'page' ? ` Computed on the page, not in a worker (${site.reason}): the page may pause during runs.` : '';
});

$('#run').addEventListener('click', () => void run(controls.config));
$('#step').addEventListener('click', () => runWith((c) => ({ ...c, lloyd: { ...c.lloyd, maxIterations: c.lloyd.maxIterations + 1, tolerance: 0 } })));
$('#converge').addEventListener('click', () =>
  runWith((c) => ({ ...c, lloyd: { ...c.lloyd, maxIterations: Math.max(c.lloyd.maxIterations, 500), tolerance: Math.max(c.lloyd.tolerance, 0.05) } })),
);
cancelButton.addEventListener('click', () => {
  runner.cancel();
  realizations.stop();
});
$('#share').addEventListener('click', async () => {
  try {
    // The configuration of the result on screen, not the form's draft.
    if (!stack) throw new Error('Nothing to share yet: run a sheet first.');
    // Its draft (a default resolution kept null, docs/app.md), as the address holds it.
    const shared = urlWithConfig(location.href, shownDraft ?? stack.result.config);
    $('#share').dataset.link = shared;
    await navigator.clipboard?.writeText(shared);
    statusLine.textContent = 'Link copied: it reproduces the result on screen.';
  } catch (error) {
    showError(error);
  }
});

function start(): void {
  try {
    computeContext();
  } catch (error) {
    showError(error);
    statusLine.textContent = 'No run possible in this browser.';
    for (const id of ['#run', '#step', '#converge']) $<HTMLButtonElement>(id).disabled = true;
    setState('no-webgl');
    return;
  }
  if (link.kind === 'bad') {
    // A broken link runs nothing and leaves the address as it was; the form shows what would run.
    linkAlert.show(`This link cannot be used: ${link.message} Nothing was run; fix the link, or press Run to run the settings shown.`);
    statusLine.textContent = 'The link was not used.';
    setState('refused');
    return;
  }
  void run(controls.config);
}

start();
