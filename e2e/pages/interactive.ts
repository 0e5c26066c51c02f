// Test page: <tissue-sheet>.sweep() with its sweep-progress events and cancellation, and the
// page's long tasks while it runs; the pictures the pipeline's worker draws against the page's.
import '../../src/element/index';
import { validateConfig } from '../../src/core/config';
import type { TissueSheetSweepProgressDetail } from '../../src/element/events';
import { drawExactCells } from '../../src/view/exactCells';
import { runInPage } from '../../src/view/pageRunner';
import { flipRows, paintSurface } from '../../src/view/sideColors';
import { viewStack, type ViewStack } from '../../src/view/stack';
import { PICTURE_LAYOUT, workerPicture, type PictureKind } from '../../src/view/workerPictures';
import { observeLongTasks } from './longTasks';

const element = document.querySelector('tissue-sheet')!;
const longTasks = observeLongTasks();

/** Runs `spec`; with `abortAfter`, aborts once that many runs have finished. */
async function sweep(input: { spec: unknown; abortAfter?: number; resume?: string; workers?: number }) {
  const controller = new AbortController();
  const progress: TissueSheetSweepProgressDetail[] = [];
  const listener = (event: Event) => {
    const detail = (event as CustomEvent<TissueSheetSweepProgressDetail>).detail;
    progress.push(detail);
    if (input.abortAfter !== undefined && progress.length >= input.abortAfter) controller.abort();
  };
  element.addEventListener('sweep-progress', listener);
  longTasks.length = 0;
  const started = performance.now();
  try {
    const result = await element.sweep(input.spec, {
      signal: controller.signal,
      ...(input.resume ? { resume: input.resume } : {}),
      ...(input.workers ? { workers: input.workers } : {}),
    });
    return {
      ...result,
      ms: performance.now() - started,
      longTasks: [...longTasks],
      progress: progress.map((p) => ({ finished: p.finished, total: p.total, key: p.run.key, hasRow: p.row !== undefined })),
      site: element.computeSite,
    };
  } finally {
    element.removeEventListener('sweep-progress', listener);
  }
}

/** A bad spec: the error's name and message. */
async function badSweep(spec: unknown) {
  try {
    await element.sweep(spec);
    return { name: 'none', message: '' };
  } catch (error) {
    return { name: (error as Error).name, message: (error as Error).message };
  }
}

/** RGBA of a picture, read back from a software canvas. */
function pixels(picture: ImageBitmap | ImageData | ((canvas: HTMLCanvasElement) => void), width = 0, height = 0): Uint8ClampedArray {
  const canvas = document.createElement('canvas');
  canvas.width = picture instanceof ImageBitmap || picture instanceof ImageData ? picture.width : width;
  canvas.height = picture instanceof ImageBitmap || picture instanceof ImageData ? picture.height : height;
  const context = canvas.getContext('2d', { willReadFrequently: true })!;
  if (picture instanceof ImageData) context.putImageData(picture, 0, 0);
  else if (picture instanceof ImageBitmap) context.drawImage(picture, 0, 0);
  else picture(canvas);
  return context.getImageData(0, 0, canvas.width, canvas.height).data;
}

/** Fraction of pixels whose colour differs by more than 2 levels in a channel. */
function differing(a: Uint8ClampedArray, b: Uint8ClampedArray): number {
  if (a.length !== b.length) return 1;
  let count = 0;
  for (let i = 0; i < a.length; i += 4) {
    if (Math.abs(a[i] - b[i]) > 2 || Math.abs(a[i + 1] - b[i + 1]) > 2 || Math.abs(a[i + 2] - b[i + 2]) > 2) count++;
  }
  return count / (a.length / 4);
}

/**
 * One config run twice on the page's runner: full pictures and drafts from the worker, each
 * compared with what the views draw on the page without them (drawExactCells, paintSurface).
 */
async function pictures(config: unknown) {
  const valid = validateConfig(config);
  const options = (stack: ViewStack) => ({ highlightScutoids: true, selected: -1, valid: stack.valid, scutoid: stack.scutoid });
  const full = viewStack(await runInPage({ config: valid }));
  const draft = viewStack(await runInPage({ config: valid, pictures: { highlightScutoids: true, selected: -1, draft: true } }));
  const rows: {
    surface: string;
    kind: PictureKind;
    grid: number[];
    scale: number;
    full: string;
    fullSize: number[];
    fullDiffering: number;
    draftSize: number[];
    draftDiffering: number;
  }[] = [];
  for (const kind of ['texture', 'unrolled'] as const) {
    full.surfaces.forEach((surface, k) => {
      const picture = workerPicture(surface, kind, { highlightScutoids: true, selected: -1 });
      const layout = PICTURE_LAYOUT[kind](surface);
      const { width, height } = surface.image.grid;
      const onPage = pixels(
        (canvas) => drawExactCells(canvas, surface, { ...options(full), ...layout }),
        Math.round(width * layout.scale),
        Math.round(height * layout.scale),
      );
      const draftSurface = draft.surfaces[k];
      const draftPicture = workerPicture(draftSurface, kind, { highlightScutoids: true, selected: -1 });
      const painted = paintSurface(draftSurface, options(draft));
      const draftOnPage = new ImageData(kind === 'unrolled' ? flipRows(painted, width, height) : new Uint8ClampedArray(painted), width, height);
      rows.push({
        surface: surface.name,
        kind,
        grid: [width, height],
        scale: layout.scale,
        full: picture ? picture.constructor.name : 'none',
        fullSize: picture ? [picture.width, picture.height] : [],
        fullDiffering: picture ? differing(pixels(picture), onPage) : 1,
        draftSize: draftPicture ? [draftPicture.width, draftPicture.height] : [],
        draftDiffering: draftPicture ? differing(pixels(draftPicture), pixels(draftOnPage)) : 1,
      });
    });
  }
  return rows;
}

(window as unknown as Record<string, unknown>).tissueSheetInteractive = { sweep, badSweep, pictures };
document.title = 'ready';
