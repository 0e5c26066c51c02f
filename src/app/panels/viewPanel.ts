/**
 * The 3D view card: the view itself, a checkbox per surface of the stack (layers included), the
 * cut slider, the scutoid highlight and a camera reset. Without WebGL for the view, the card
 * says so and the rest of the page still works.
 */
import { SheetView3D } from '../../view/sheetView3d';
import type { ViewStack } from '../../view/stack';
import { drawUnrolled } from '../view/unrolled';

export class ViewPanel {
  readonly view: SheetView3D | null;
  private stack: ViewStack | null = null;
  private readonly hidden = new Set<string>();
  private readonly toggles: HTMLElement;
  private readonly highlight: HTMLInputElement;

  constructor(
    root: HTMLElement,
    private readonly unrolled: HTMLElement,
  ) {
    const canvas = root.querySelector<HTMLCanvasElement>('#view3d')!;
    let view: SheetView3D | null = null;
    try {
      view = new SheetView3D(canvas);
    } catch {
      const message = root.querySelector<HTMLElement>('#view-message')!;
      message.textContent = 'The 3D view needs WebGL, which this browser does not provide.';
      message.hidden = false;
      canvas.hidden = true;
    }
    this.view = view;
    this.toggles = root.querySelector<HTMLElement>('#surface-toggles')!;
    this.highlight = root.querySelector<HTMLInputElement>('#highlight')!;
    const cut = root.querySelector<HTMLInputElement>('#cut')!;
    cut.addEventListener('input', () => this.view?.setCut(Number(cut.value)));
    this.highlight.addEventListener('change', () => {
      this.view?.setHighlightScutoids(this.highlight.checked);
      if (this.stack) drawUnrolled(this.unrolled, this.stack, this.highlight.checked);
    });
    root.querySelector<HTMLButtonElement>('#reset-camera')!.addEventListener('click', () => this.view?.resetCamera());
  }

  show(stack: ViewStack): void {
    this.stack = stack;
    this.view?.setStack(stack);
    drawUnrolled(this.unrolled, stack, this.highlight.checked);
    this.toggles.replaceChildren();
    for (const surface of stack.surfaces) {
      const label = document.createElement('label');
      const box = document.createElement('input');
      box.type = 'checkbox';
      box.checked = !this.hidden.has(surface.name);
      box.dataset.surface = surface.name;
      box.addEventListener('change', () => {
        if (box.checked) this.hidden.delete(surface.name);
        else this.hidden.add(surface.name);
        this.view?.setSurfaceVisible(surface.index, box.checked);
      });
      this.view?.setSurfaceVisible(surface.index, box.checked);
      label.append(box, ` ${surface.name}`);
      this.toggles.append(label);
    }
  }

  toBlob(): Promise<Blob> {
    if (!this.view) return Promise.reject(new Error('There is no 3D view to save: this browser does not provide WebGL.'));
    return this.view.toBlob();
  }
}
