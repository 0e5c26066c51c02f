/**
 * Lloyd converging, as a movie: frame k shows the seeded surface's cells and sites of Voronoi k
 * (k - 1 Lloyd iterations, no early stop), k = 1 .. the configuration's iterations + 1. Each
 * frame is a run of the pipeline (in a worker of the movie's own) with that many iterations:
 * the same seed gives the same sites, so frame k is exactly the state after k - 1 iterations of
 * the run on screen. Frames appear as they are computed, then loop; "WebM" records the loop from
 * the canvas with MediaRecorder. Planes and tubes only (closed surfaces have no flat picture).
 */
import type { Config } from '../../core/config';
import { surfaceLayout } from '../../core/config/surfaceLayout';
import type { SheetOutput } from '../../run';
import { acquirePipelineRunner, isAbort, releasePipelineRunner, runInputs } from '../../view/pageRunner';
import { flipRows, paintSurface } from '../../view/sideColors';
import { viewStack } from '../../view/stack';
import { download } from './exports';

/** Most frames a movie computes (each is a run: the cost grows with the square of the frames). */
const MAX_FRAMES = 25;
const FRAME_MS = 400;

export interface LloydMovieEvents {
  config(): Config;
  onError(message: string): void;
}

export class LloydMovie {
  private readonly canvas = document.createElement('canvas');
  private readonly status = document.createElement('span');
  private frames: ImageData[] = [];
  private timer: ReturnType<typeof setInterval> | undefined;
  private controller: AbortController | null = null;

  constructor(
    private readonly root: HTMLElement,
    private readonly events: LloydMovieEvents,
  ) {
    root.classList.add('lloyd-movie');
    const play = button('Show Lloyd converging', 'play');
    const record = button('WebM', 'webm');
    record.disabled = true;
    record.title = 'Record the frames as a WebM movie';
    this.status.className = 'small';
    this.status.setAttribute('role', 'status');
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute('aria-label', 'the seeded surface, unrolled, at each Lloyd iteration');
    this.canvas.style.maxWidth = '100%';
    root.append(play, record, this.status, document.createElement('br'), this.canvas);
    play.addEventListener('click', () => void this.compute().then(() => (record.disabled = this.frames.length === 0)));
    record.addEventListener('click', () => void this.record());
  }

  /** Computes every frame, showing each as it arrives, then loops them. */
  async compute(): Promise<void> {
    this.controller?.abort();
    const controller = new AbortController();
    this.controller = controller;
    clearInterval(this.timer);
    this.frames = [];
    const runner = acquirePipelineRunner();
    try {
      const config = this.events.config();
      if (!surfaceLayout(config).flatPicture) throw new Error('The Lloyd movie shows planes and tubes; a closed surface has no flat picture.');
      const count = Math.min(MAX_FRAMES, config.lloyd.maxIterations + 1);
      const inputs = await runInputs(config);
      for (let k = 1; k <= count; k++) {
        this.status.textContent = `Computing Voronoi ${k} of ${count}…`;
        const frameConfig: Config = { ...config, lloyd: { ...config.lloyd, maxIterations: k - 1, tolerance: 0 } };
        const output = await runner.run(frameConfig, { signal: controller.signal, ...inputs });
        this.frames.push(frameImage(output));
        this.draw(this.frames.length - 1);
        await new Promise((resolve) => setTimeout(resolve, 0));
      }
      this.root.dataset.frames = String(this.frames.length);
      this.status.textContent = `Voronoi 1 to ${count}: the sites (dots) move to their cells' centroids.`;
      let frame = 0;
      this.timer = setInterval(() => this.draw((frame = (frame + 1) % this.frames.length)), FRAME_MS);
    } catch (error) {
      if (!isAbort(error)) this.events.onError((error as Error).message);
    } finally {
      releasePipelineRunner(runner);
      if (this.controller === controller) this.controller = null;
    }
  }

  /** Records one pass over the frames from the canvas (MediaRecorder) and downloads it. */
  async record(): Promise<void> {
    try {
      const blob = await recordWebm(this.canvas, this.frames.length, (k) => this.draw(k));
      this.root.dataset.webmBytes = String(blob.size);
      download('tissue-sheet-lloyd.webm', blob);
    } catch (error) {
      this.events.onError((error as Error).message);
    }
  }

  private draw(k: number): void {
    const image = this.frames[k];
    if (!image) return;
    if (this.canvas.width !== image.width || this.canvas.height !== image.height) {
      this.canvas.width = image.width;
      this.canvas.height = image.height;
    }
    this.canvas.getContext('2d')!.putImageData(image, 0, 0);
    this.canvas.dataset.frame = String(k + 1);
  }
}

function button(text: string, name: string): HTMLButtonElement {
  const element = document.createElement('button');
  element.type = 'button';
  element.textContent = text;
  element.dataset.movie = name;
  return element;
}

/** The seeded surface's cells (coloured by sides) with its sites as dark dots, as ImageData. */
function frameImage(output: SheetOutput): ImageData {
  const stack = viewStack(output);
  const surface = stack.surfaces[0];
  const { width, height, texelX, texelY } = surface.image.grid;
  const rgba = flipRows(paintSurface(surface, { highlightScutoids: false, valid: stack.valid }), width, height);
  const radius = Math.max(1, Math.round(Math.min(width, height) / 150));
  for (const cell of stack.result.cells) {
    const cx = Math.floor(cell.surface[0] / texelX);
    const cy = height - 1 - Math.floor(cell.surface[1] / texelY);
    for (let dy = -radius; dy <= radius; dy++) {
      for (let dx = -radius; dx <= radius; dx++) {
        const x = cx + dx;
        const y = cy + dy;
        if (x < 0 || y < 0 || x >= width || y >= height || dx * dx + dy * dy > radius * radius) continue;
        rgba.set([15, 15, 15, 255], (y * width + x) * 4);
      }
    }
  }
  return new ImageData(rgba, width, height);
}

/** A WebM of `frames` frames drawn by `draw(k)` on `canvas`, FRAME_MS each. */
function recordWebm(canvas: HTMLCanvasElement, frames: number, draw: (k: number) => void): Promise<Blob> {
  if (frames === 0) return Promise.reject(new Error('Compute the Lloyd frames first ("Show Lloyd converging").'));
  if (typeof MediaRecorder === 'undefined' || !canvas.captureStream) return Promise.reject(new Error('This browser cannot record video (no MediaRecorder).'));
  const type = ['video/webm;codecs=vp9', 'video/webm;codecs=vp8', 'video/webm'].find((t) => MediaRecorder.isTypeSupported(t));
  if (!type) return Promise.reject(new Error('This browser cannot record WebM video.'));
  const stream = canvas.captureStream(Math.ceil(1000 / FRAME_MS));
  const recorder = new MediaRecorder(stream, { mimeType: type });
  const chunks: Blob[] = [];
  recorder.ondataavailable = (event) => event.data.size > 0 && chunks.push(event.data);
  return new Promise<Blob>((resolve, reject) => {
    recorder.onstop = () => {
      stream.getTracks().forEach((track) => track.stop());
      resolve(new Blob(chunks, { type: 'video/webm' }));
    };
    recorder.onerror = () => reject(new Error('Recording the movie failed.'));
    recorder.start();
    let k = 0;
    draw(0);
    const timer = setInterval(() => {
      k += 1;
      if (k >= frames) {
        clearInterval(timer);
        recorder.stop();
        return;
      }
      draw(k);
    }, FRAME_MS);
  });
}

/** A card holding the movie, placed before `before` (the page has no slot for it in its HTML). */
export function mountLloydMovie(before: Element, events: LloydMovieEvents): LloydMovie {
  const card = document.createElement('section');
  card.className = 'card wide';
  card.setAttribute('aria-labelledby', 'lloyd-title');
  const title = Object.assign(document.createElement('h2'), { id: 'lloyd-title', textContent: 'Lloyd iterations' });
  const root = Object.assign(document.createElement('div'), { id: 'lloyd-movie' });
  card.append(title, root);
  before.before(card);
  return new LloydMovie(root, events);
}
