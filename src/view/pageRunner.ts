/**
 * Runs sheets in the page, for the app and `<tissue-sheet>` alike: one compute context (an
 * off-screen WebGL2 canvas) shared by every caller on the page, runs queued one at a time on
 * it, a newer request cancelling the one it replaces, density images decoded and mesh files
 * fetched on the way. The page stays responsive
 * because runSheet yields to the event loop between Lloyd iterations.
 *
 * Planar runs go through one SheetRunner: when only `sheet.*` changed (the live surface-ratio and
 * thickness sliders, a sweep's points) the converged seeded surface is reused and Lloyd is not
 * run again. Closed surfaces (sphere, ellipsoid, mesh) run whole through runSheet.
 */
import { isClosedConfig, type AnyConfig } from '../core/config';
import type { GrayImage } from '../core/density';
import { createCanvasContext, runSheet, SheetRunner, type GpuContext, type IterationRecord, type MeshFile, type SheetOutput } from '../run';
import { decodeGrayImage } from './densityImage';
import { meshFileFor } from './meshFiles';

let sharedContext: GpuContext | null = null;
let sharedRunner: SheetRunner | null = null;
let queue: Promise<unknown> = Promise.resolve();

/** The page's compute context; throws GpuCapabilityError (a message for people) without WebGL2. */
export function computeContext(): GpuContext {
  sharedContext ??= createCanvasContext(document.createElement('canvas'));
  return sharedContext;
}

export interface RunRequest {
  config: AnyConfig;
  signal?: AbortSignal;
  onIteration?: (record: IterationRecord, maxIterations: number) => void;
  /** A decoded density image; else an image density's `src` is fetched and decoded. */
  densityImage?: GrayImage;
  /** A mesh file for `surface.kind = "mesh"` (else an upload of that name, or `src` fetched). */
  meshFile?: MeshFile | null;
}

const decoded = new Map<string, Promise<GrayImage>>();

async function densityImageFor(config: AnyConfig, given?: GrayImage): Promise<GrayImage | undefined> {
  if (config.density.kind !== 'image') return undefined;
  if (given) return given;
  const { src } = config.density;
  if (!decoded.has(src)) {
    if (decoded.size > 8) decoded.clear();
    decoded.set(src, decodeGrayImage(src));
  }
  return decoded.get(src);
}

/** One run, queued behind any run already on the shared context. */
export function runInPage(request: RunRequest): Promise<SheetOutput> {
  const job = queue.then(async (): Promise<SheetOutput> => {
    if (request.signal?.aborted) throw new DOMException('The run was cancelled', 'AbortError');
    const context = computeContext();
    const { config, signal, onIteration } = request;
    if (isClosedConfig(config)) {
      const meshFile = await meshFileFor(config, request.meshFile);
      return runSheet(config, context, { signal, onIteration, ...(meshFile ? { meshFile } : {}) });
    }
    const densityImage = await densityImageFor(config, request.densityImage);
    sharedRunner ??= new SheetRunner(context);
    return sharedRunner.run(config, { signal, onIteration, densityImage });
  });
  queue = job.catch(() => undefined);
  return job;
}

export function isAbort(error: unknown): boolean {
  return error instanceof DOMException && error.name === 'AbortError';
}

/**
 * Keeps at most one run of one owner in flight: `start` cancels the previous run of this
 * runner. `debounced` waits `ms` of quiet first (for sliders that re-run live).
 */
export class LatestRunner {
  private controller: AbortController | null = null;
  private timer: ReturnType<typeof setTimeout> | undefined;

  get running(): boolean {
    return this.controller !== null;
  }

  cancel(): void {
    clearTimeout(this.timer);
    this.controller?.abort();
    this.controller = null;
  }

  async start(request: Omit<RunRequest, 'signal'>): Promise<SheetOutput> {
    this.cancel();
    const controller = new AbortController();
    this.controller = controller;
    try {
      return await runInPage({ ...request, signal: controller.signal });
    } finally {
      if (this.controller === controller) this.controller = null;
    }
  }

  debounced(ms: number, action: () => void): void {
    clearTimeout(this.timer);
    this.timer = setTimeout(action, ms);
  }
}
