/**
 * The element's 3D view on its Shadow DOM canvas: opened while the element is connected, given
 * back when it is removed (a browser keeps only so many WebGL contexts, about 16, and drops the
 * oldest beyond that, blanking a live element), and the output drawn last drawn again in a new
 * view or a restored context. A context lost anyway is said through `lost` (the element's status
 * line and `error` event), never a silently blank view.
 */
import type { SheetOutput } from '../run';
import { trackCellHover } from '../view/cellHover';
import { SheetView3D } from '../view/sheetView3d';
import { viewStack } from '../view/stack';

export interface ElementViewEvents {
  /** The cell under the pointer changed (null: none). */
  hover(picked: { cell: number; surface: number } | null): void;
  /** The browser took the context away. */
  lost(): void;
  /** The browser gave it back, and the last output is drawn again. */
  restored(): void;
  /** Drawing the last output again failed. */
  failed(message: string): void;
}

export class ElementView {
  private view: SheetView3D | null = null;
  private untrackHover: (() => void) | null = null;
  /** The output in the view (drawn again when the view is made anew: reconnected, context restored). */
  private drawn: SheetOutput | null = null;

  constructor(
    private readonly root: ShadowRoot,
    private readonly events: ElementViewEvents,
  ) {}

  /** The view on the canvas, with the output drawn before (if any); no view where WebGL fails (the run's error says why). */
  connect(): void {
    if (this.view) return;
    const canvas = this.root.querySelector('canvas')!;
    try {
      this.view = new SheetView3D(canvas);
    } catch {
      this.view = null;
      return;
    }
    this.untrackHover = trackCellHover(canvas, this.view, ({ picked, changed }) => {
      if (changed) this.events.hover(picked ? { cell: picked.cell, surface: picked.surface } : null);
    });
    canvas.addEventListener('webglcontextlost', this.onContextLost);
    canvas.addEventListener('webglcontextrestored', this.onContextRestored);
    if (this.drawn) this.redraw();
  }

  /** Releases the view's GL resources and its context; a fresh canvas waits for the next connect. */
  disconnect(): void {
    const view = this.view;
    if (!view) return;
    this.view = null;
    const canvas = view.canvas;
    canvas.removeEventListener('webglcontextlost', this.onContextLost);
    canvas.removeEventListener('webglcontextrestored', this.onContextRestored);
    this.untrackHover?.();
    this.untrackHover = null;
    view.dispose();
    view.renderer.forceContextLoss();
    // A canvas keeps its context, lost now, for good: a new canvas takes its place.
    canvas.replaceWith(canvas.cloneNode(false));
  }

  /** The stack of `output` in the view (throws when the view cannot draw it); kept to draw again. */
  show(output: SheetOutput): void {
    this.drawn = output;
    this.view?.setStack(viewStack(output));
    this.view?.acceleratePicking();
  }

  /** A PNG (or `type`) of the view. */
  toBlob(type?: string): Promise<Blob> {
    if (!this.view) return Promise.reject(new Error('tissue-sheet: no 3D view (WebGL is not available)'));
    return this.view.toBlob(type);
  }

  private readonly onContextLost = (event: Event): void => {
    event.preventDefault(); // lets the browser restore it (webglcontextrestored)
    this.events.lost();
  };

  private readonly onContextRestored = (): void => {
    this.redraw();
    this.events.restored();
  };

  private redraw(): void {
    if (!this.drawn) return;
    try {
      this.show(this.drawn);
    } catch (error) {
      this.events.failed((error as Error).message);
    }
  }
}
