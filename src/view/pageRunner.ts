/**
 * Runs sheets for the page, for the app and `<tissue-sheet>` alike, with the pipeline in a Web
 * Worker (WorkerSheetRunner: an OffscreenCanvas WebGL2 context there), so the main thread only
 * draws. Where the browser cannot give the worker a WebGL2 context, runs fall back to the page
 * and `computeSite()` says so and why (the app and the element show it).
 *
 * One shared runner serves every caller on the page (its runs are taken in order in the
 * worker); it keeps the converged seeded surface, so a change of `sheet.*` only (the live
 * surface-ratio and thickness sliders) recomputes the other side and the analysis. The worker
 * (viewWorker.ts) also draws the views' pictures of each result (workerPictures.ts), so the main
 * thread only uploads them. Sweeps and the Lloyd movie take their own runner
 * (`acquirePipelineRunner`), so they and the live view never evict each other's seeded surface;
 * an idle one is kept for the next (terminating a worker that holds a WebGL context costs the
 * main thread one task of 50-160 ms on a software renderer).
 *
 * Mesh uploads: the seeded surface is keyed by the config, which names an uploaded mesh by its
 * file name only. When other bytes arrive under a name already run, the runner is replaced, so
 * a surface relaxed on the old file is never reused for the new one.
 */
import type { Config } from '../core/config';
import type { GrayImage } from '../core/density';
import {
  createCanvasContext,
  seededKey,
  WorkerSheetRunner,
  type ComputeSite,
  type GpuContext,
  type IterationRecord,
  type MeshFile,
  type SheetOutput,
} from '../run';
import { abortError, type WorkerRunOptions } from '../run/worker/workerRunner';
import { decodeGrayImage } from './densityImage';
import { meshFileFor } from './meshFiles';
import { rememberPictures, type PictureRequest } from './workerPictures';

let sharedContext: GpuContext | null = null;
let sharedRunner: WorkerSheetRunner | null = null;
/** The bytes last run under each mesh name, to notice a different file under the same name. */
const meshBytes = new Map<string, MeshFile['data']>();
const siteListeners = new Set<(site: ComputeSite) => void>();

/**
 * The page's own compute context, used only when runs fall back to the page; throws
 * GpuCapabilityError (a message for people) without WebGL2.
 */
export function computeContext(): GpuContext {
  sharedContext ??= createCanvasContext(document.createElement('canvas'));
  return sharedContext;
}

/** A new pipeline runner in its own worker (the view's worker: it can draw the views' pictures). */
function createPipelineRunner(): WorkerSheetRunner {
  return new WorkerSheetRunner(computeContext, () => new Worker(new URL('./viewWorker.ts', import.meta.url), { type: 'module' }));
}

/** Idle runners of sweeps and movies, kept for the next one (see the module's comment). */
const idleRunners: WorkerSheetRunner[] = [];
/**
 * As many as a sweep's pool takes by default (pageSweep.ts: the cores less one, at most 8), so
 * that the end of a sweep terminates no worker (each termination costs the main thread a task).
 */
const MAX_IDLE_RUNNERS = Math.max(1, Math.min(8, ((typeof navigator !== 'undefined' && navigator.hardwareConcurrency) || 2) - 1));

/** A pipeline runner of its own for a sweep or a movie; give it back with releasePipelineRunner. */
export function acquirePipelineRunner(): WorkerSheetRunner {
  return idleRunners.pop() ?? createPipelineRunner();
}

/** Gives back a runner from acquirePipelineRunner: kept for the next caller, or disposed. */
export function releasePipelineRunner(runner: WorkerSheetRunner): void {
  if (idleRunners.length < MAX_IDLE_RUNNERS && runner.site.where === 'worker' && !idleRunners.includes(runner)) idleRunners.push(runner);
  else if (!idleRunners.includes(runner)) runner.dispose();
}

function pipeline(): WorkerSheetRunner {
  sharedRunner ??= createPipelineRunner();
  return sharedRunner;
}

/** Where the page's runs compute: in the worker, or on the page and why. */
export function computeSite(): ComputeSite {
  return pipeline().site;
}

/** Calls `listener` after every run with where it computed (to show a fallback to the page). */
export function onComputeSite(listener: (site: ComputeSite) => void): () => void {
  siteListeners.add(listener);
  return () => siteListeners.delete(listener);
}

export interface RunRequest {
  config: Config;
  signal?: AbortSignal;
  onIteration?: (record: IterationRecord, maxIterations: number) => void;
  /** A decoded density image; else an image density's `src` is fetched and decoded. */
  densityImage?: GrayImage;
  /** A mesh file for `surface.kind = "mesh"` (else an upload of that name, or `src` fetched). */
  meshFile?: MeshFile | null;
  /**
   * How the worker draws the views' pictures (workerPictures.ts); default: scutoids highlighted,
   * no picked cell, as the views show a result first. false: none drawn there.
   */
  pictures?: PictureRequest | false;
}

/**
 * How long after the last live change (a slider's drag, an element's `sheet.*` attribute) the
 * result on screen is drawn again with its full pictures.
 */
export const FULL_PICTURES_DELAY_MS = 400;

/**
 * True when `next` differs from `previous` in `sheet.*` only (and differs): the worker's
 * converged seeded surface serves it, the change the live path (LatestRunner.live) is for.
 */
export function sheetOnlyChange(previous: Config, next: Config): boolean {
  return seededKey(previous) === seededKey(next) && JSON.stringify(previous.sheet) !== JSON.stringify(next.sheet);
}

const decoded = new Map<string, Promise<GrayImage>>();

async function densityImageFor(config: Config, given?: GrayImage): Promise<GrayImage | undefined> {
  if (config.density.kind !== 'image') return undefined;
  if (given) return given;
  const { src } = config.density;
  if (!decoded.has(src)) {
    if (decoded.size > 8) decoded.clear();
    const job = decodeGrayImage(src);
    job.catch(() => decoded.delete(src));
    decoded.set(src, job);
  }
  return decoded.get(src);
}

/** The inputs a run needs besides its config: the decoded density image and the mesh file. */
export async function runInputs(
  config: Config,
  request: Pick<RunRequest, 'densityImage' | 'meshFile'> = {},
): Promise<{ densityImage?: GrayImage; meshFile?: MeshFile }> {
  const meshFile = await meshFileFor(config, request.meshFile);
  const densityImage = await densityImageFor(config, request.densityImage);
  return { ...(densityImage ? { densityImage } : {}), ...(meshFile ? { meshFile } : {}) };
}

/** True when `file` differs from the bytes last run under its name (remembers it). */
function meshChanged(file: MeshFile): boolean {
  const name = file.name ?? '';
  const before = meshBytes.get(name);
  meshBytes.set(name, file.data);
  return before !== undefined && before !== file.data;
}

/** One run on the page's shared pipeline runner (in arrival order in the worker). */
export async function runInPage(request: RunRequest): Promise<SheetOutput> {
  if (request.signal?.aborted) throw abortError();
  const { config, signal, onIteration } = request;
  const inputs = await runInputs(config, request);
  if (signal?.aborted) throw abortError();
  if (inputs.meshFile && meshChanged(inputs.meshFile) && sharedRunner) {
    sharedRunner.dispose();
    sharedRunner = null;
  }
  const runner = pipeline();
  let presented: unknown;
  const pictures = request.pictures ?? { highlightScutoids: true, selected: -1 };
  const callbacks: WorkerRunOptions = { signal, onIteration, ...inputs, ...(pictures ? { present: pictures, onPresented: (p) => (presented = p) } : {}) };
  try {
    const output = await runner.run(config, callbacks);
    rememberPictures(output, presented);
    return output;
  } finally {
    for (const listener of siteListeners) listener(runner.site);
  }
}

export function isAbort(error: unknown): boolean {
  return error instanceof DOMException && error.name === 'AbortError';
}

interface Waiting {
  readonly request: Omit<RunRequest, 'signal'>;
  readonly resolve: (output: SheetOutput) => void;
  readonly reject: (error: unknown) => void;
}

/**
 * Keeps at most one run of one owner in flight, the latest request winning:
 * - `start` cancels the run in flight (and any waiting one) and starts at once;
 * - `live` (a slider being dragged) starts at once when nothing is in flight, else waits for
 *   the run in flight and replaces any request already waiting, so pictures stream at the pace
 *   of the pipeline, each from the newest value, and nothing queues up behind a drag;
 * - `debounced` waits `ms` of quiet first (for typed edits).
 * A superseded request rejects with an AbortError.
 */
export class LatestRunner {
  private controller: AbortController | null = null;
  private waiting: Waiting | null = null;
  private timer: ReturnType<typeof setTimeout> | undefined;

  get running(): boolean {
    return this.controller !== null || this.waiting !== null;
  }

  cancel(): void {
    clearTimeout(this.timer);
    this.controller?.abort();
    this.controller = null;
    this.dropWaiting();
  }

  async start(request: Omit<RunRequest, 'signal'>): Promise<SheetOutput> {
    this.cancel();
    return this.launch(request);
  }

  /** (Results of `live` runs get draft pictures from the worker: workerPictures.ts.) */
  live(live: Omit<RunRequest, 'signal'>): Promise<SheetOutput> {
    const request = { ...live, pictures: live.pictures ?? { highlightScutoids: true, selected: -1, draft: true } };
    clearTimeout(this.timer);
    if (!this.controller) return this.launch(request);
    this.dropWaiting();
    return new Promise<SheetOutput>((resolve, reject) => {
      this.waiting = { request, resolve, reject };
    });
  }

  debounced(ms: number, action: () => void): void {
    clearTimeout(this.timer);
    this.timer = setTimeout(action, ms);
  }

  private dropWaiting(): void {
    const waiting = this.waiting;
    this.waiting = null;
    waiting?.reject(abortError());
  }

  private async launch(request: Omit<RunRequest, 'signal'>): Promise<SheetOutput> {
    const controller = new AbortController();
    this.controller = controller;
    try {
      return await runInPage({ ...request, signal: controller.signal });
    } finally {
      if (this.controller === controller) {
        this.controller = null;
        const next = this.waiting;
        this.waiting = null;
        if (next) this.launch(next.request).then(next.resolve, next.reject);
      }
    }
  }
}
