/**
 * The 3D view card: the view itself, a checkbox per surface of the stack (layers included), the
 * cut slider, the scutoid highlight, a camera reset, and the picked cell (a click on a cell in
 * the 3D view or the unrolled surfaces, or its id typed in the "Cell" field: keyboard users pick
 * the same way), drawn white on every surface and described under the legend, and optionally
 * drawn as a 3D solid through the layers ("Show picked cell as a 3D solid"). Hovering the 3D view
 * shows the cell under the pointer in a tooltip (cellHover.ts: one pick per frame). Without WebGL for
 * the view, the card says so and the rest of the page still works. `viewState`/`restore` carry
 * the view in a project file.
 */
import { SheetView3D } from '../../view/sheetView3d';
import type { ViewStack } from '../../view/stack';
import type { ViewState } from '../model/project';
import { trackCellHover } from '../../view/cellHover';
import { hoverText, renderCellInfo } from '../view/cellInfo';
import type { CellSolid } from '../../view/cellSolid';
import { cellSolidPly } from '../model/ply';
import { download } from './exports';
import { drawUnrolled, pickUnrolled } from '../view/unrolled';
import { selectCellRow } from './cellTableView';

/** A pointer that moved more than this between down and up was a drag (orbit), not a click. */
const CLICK_SLOP_PX = 4;

export class ViewPanel {
  readonly view: SheetView3D | null;
  private stack: ViewStack | null = null;
  private readonly hidden = new Set<string>();
  private readonly toggles: HTMLElement;
  private readonly highlight: HTMLInputElement;
  private readonly cut: HTMLInputElement;
  private readonly cellInfo: HTMLElement;
  private readonly cellField: HTMLInputElement;
  private readonly solidBox: HTMLInputElement;
  private readonly solidPly: HTMLButtonElement;
  private readonly solidZoom: HTMLButtonElement;
  private solid: CellSolid | null = null;
  private readonly hoverTip: HTMLElement;
  private selected = -1;
  /**
   * Draws the pictures of `stack` with the stripes on or off off the main thread when it can
   * (a large opened result: model/openClient.ts), true when they are then kept for the views.
   */
  picturesElsewhere: ((stack: ViewStack, highlightScutoids: boolean) => Promise<boolean>) | null = null;

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
    this.cut = root.querySelector<HTMLInputElement>('#cut')!;
    this.cut.addEventListener('input', () => this.view?.setCut(Number(this.cut.value)));
    this.highlight.addEventListener('change', () => void this.showHighlight(this.highlight.checked));
    root.querySelector<HTMLButtonElement>('#reset-camera')!.addEventListener('click', () => this.view?.resetCamera());

    // The picked cell: a field (keyboard) and a description (announced politely).
    const picker = document.createElement('div');
    picker.className = 'cell-picker';
    const label = document.createElement('label');
    this.cellField = document.createElement('input');
    this.cellField.type = 'number';
    this.cellField.id = 'cell-id';
    this.cellField.min = '0';
    this.cellField.step = '1';
    this.cellField.placeholder = 'id';
    this.cellField.title = 'Pick a cell by its id (Enter); Escape clears';
    label.append('Cell ', this.cellField);
    this.cellInfo = document.createElement('div');
    this.cellInfo.id = 'cell-info';
    this.cellInfo.setAttribute('role', 'status');
    this.cellInfo.setAttribute('aria-live', 'polite');
    // The picked cell as a solid through the layers (the scutoid itself).
    const solidLabel = document.createElement('label');
    this.solidBox = document.createElement('input');
    this.solidBox.type = 'checkbox';
    this.solidBox.id = 'cell-solid';
    solidLabel.title =
      'Draws the picked cell as a solid through every surface of the stack, in front of the surfaces: its cross-section on each surface is its cell there (exact on planes and tubes, traced on closed surfaces)';
    solidLabel.append(this.solidBox, ' Show picked cell as a 3D solid');
    this.solidBox.addEventListener('change', () => {
      this.updateSolid();
      // Ticking the box is asking to see the scutoid: bring it into view.
      if (this.solidBox.checked) this.view?.focusOnSolid();
    });
    this.solidPly = solidButton(
      'cell-solid-ply',
      'Solid as PLY',
      'Saves the solid on screen as a closed triangle mesh (ASCII PLY, µm; each vertex with cell, surface, sides, scutoid, valid)',
      () => {
        if (!this.stack || !this.solid) return;
        const { config } = this.stack.result;
        download(
          `tissue-sheet-${config.surface.kind}-seed${config.seed}-cell${this.solid.cell}-solid.ply`,
          cellSolidPly(this.stack, this.solid),
          'application/octet-stream',
        );
      },
    );
    this.solidZoom = solidButton(
      'cell-solid-zoom',
      'Zoom to cell',
      "Turns the camera to the picked cell's solid, seen from outside the sheet (Reset camera shows the whole sheet again)",
      () => this.view?.focusOnSolid(),
    );
    picker.append(label, solidLabel, this.solidZoom, this.solidPly, this.cellInfo);
    root.querySelector('#legend')!.after(picker);
    this.cellField.addEventListener('change', () => this.select(this.cellField.value === '' ? -1 : Number(this.cellField.value)));
    this.cellField.addEventListener('keydown', (event) => {
      if (event.key === 'Escape') this.select(-1);
    });
    renderCellInfo(this.cellInfo, null, -1);

    let down: { x: number; y: number } | null = null;
    canvas.addEventListener('pointerdown', (event) => (down = { x: event.clientX, y: event.clientY }));
    canvas.addEventListener('pointerup', (event) => {
      if (!down || Math.hypot(event.clientX - down.x, event.clientY - down.y) > CLICK_SLOP_PX) return;
      down = null;
      const picked = this.view?.pickCell(event.clientX, event.clientY);
      this.select(picked ? picked.cell : -1);
    });
    canvas.addEventListener('keydown', (event) => {
      if (event.key === 'Escape') this.select(-1);
    });

    // Hover: a tooltip near the pointer with the cell under it.
    this.hoverTip = document.createElement('div');
    this.hoverTip.id = 'cell-hover';
    this.hoverTip.setAttribute('role', 'tooltip');
    this.hoverTip.hidden = true;
    this.hoverTip.style.cssText =
      'position:fixed;z-index:10;pointer-events:none;max-width:22rem;padding:2px 6px;border-radius:3px;background:rgba(20,20,20,0.85);color:#fff;font:12px/1.4 system-ui,sans-serif';
    document.body.append(this.hoverTip);
    if (view) {
      trackCellHover(canvas, view, ({ picked, clientX, clientY }) => {
        if (!picked || !this.stack) {
          this.hoverTip.hidden = true;
          delete this.hoverTip.dataset.cell;
          return;
        }
        this.hoverTip.textContent = hoverText(this.stack, picked);
        this.hoverTip.dataset.cell = String(picked.cell);
        this.hoverTip.dataset.surface = String(picked.surface);
        this.hoverTip.hidden = false;
        // Beside the pointer, turned to its other side near the window's right or bottom edge.
        const { offsetWidth: w, offsetHeight: h } = this.hoverTip;
        const left = clientX + 14 + w > window.innerWidth ? clientX - 14 - w : clientX + 14;
        const top = clientY + 14 + h > window.innerHeight ? clientY - 14 - h : clientY + 14;
        this.hoverTip.style.left = `${Math.max(0, left)}px`;
        this.hoverTip.style.top = `${Math.max(0, top)}px`;
      });
    }
  }

  /** Shows `stack`; the unrolled pictures in the next task. */
  show(stack: ViewStack): void {
    this.stack = stack;
    if (this.selected >= stack.result.cells.length) this.selected = -1;
    this.view?.setSelected(this.selected);
    this.view?.setStack(stack);
    this.view?.acceleratePicking();
    this.updateSolid();
    // In a task of its own: copying two large pictures in (a 100,000-cell result) would make one
    // task of it and the 3D view's rebuild (issue 27).
    setTimeout(() => this.stack === stack && this.drawUnrolled(), 0);
    renderCellInfo(this.cellInfo, stack, this.selected);
    this.cellField.max = String(stack.result.cells.length - 1);
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

  /** Picks cell `id` (-1: none) on every surface. */
  select(id: number): void {
    const count = this.stack?.result.cells.length ?? 0;
    const cell = Number.isInteger(id) && id >= 0 && id < count ? id : -1;
    this.selected = cell;
    this.cellField.value = cell >= 0 ? String(cell) : '';
    document.body.dataset.selectedCell = String(cell);
    this.view?.setSelected(cell);
    this.updateSolid();
    // Planes and tubes: only the picked cell's patch changes (unrolledPick.ts).
    if (this.stack && !pickUnrolled(this.unrolled, this.stack, cell)) this.drawUnrolled();
    renderCellInfo(this.cellInfo, this.stack, cell);
    const table = document.querySelector<HTMLElement>('#cell-table');
    if (table) selectCellRow(table, cell);
  }

  /**
   * The scutoid stripes on or off: a large opened result's pictures are drawn in the worker
   * holding it first (a repaint took the main thread ~0.4 s at 25,000 cells, issue 27), then
   * shown; body data-stripes says which are on screen.
   */
  private async showHighlight(on: boolean): Promise<void> {
    const stack = this.stack;
    if (stack && this.picturesElsewhere) await this.picturesElsewhere(stack, on).catch(() => false);
    if (this.stack !== stack || this.highlight.checked !== on) return; // a newer result or toggle
    this.view?.setHighlightScutoids(on);
    this.drawUnrolled();
    document.body.dataset.stripes = on ? 'on' : 'off';
  }

  /** What a project file keeps of the view. */
  viewState(): ViewState {
    return {
      camera: this.view?.cameraState() ?? null,
      visible: (this.stack?.surfaces ?? []).map((s) => !this.hidden.has(s.name)),
      cut: Number(this.cut.value),
      highlightScutoids: this.highlight.checked,
      selectedCell: this.selected >= 0 ? this.selected : null,
      cellSolid: this.solidBox.checked,
    };
  }

  /** Shows `stack` exactly as `state` describes the view. */
  restore(stack: ViewStack, state: ViewState): void {
    this.hidden.clear();
    stack.surfaces.forEach((s, k) => {
      if (state.visible[k] === false) this.hidden.add(s.name);
    });
    this.highlight.checked = state.highlightScutoids;
    this.view?.setHighlightScutoids(state.highlightScutoids);
    this.selected = state.selectedCell ?? -1;
    this.solidBox.checked = state.cellSolid === true;
    // The unrolled pictures in a task of their own, as after a run (a 100,000-cell project: the
    // 3D view's rebuild and the copies in one task held the main thread ~250 ms, issue 27).
    this.show(stack);
    this.select(this.selected);
    if (state.camera) this.view?.setCameraState(state.camera);
    this.cut.value = String(state.cut);
    this.view?.setCut(state.cut);
  }

  toBlob(): Promise<Blob> {
    if (!this.view) return Promise.reject(new Error('There is no 3D view to save: this browser does not provide WebGL.'));
    return this.view.toBlob();
  }

  /** The picked cell's solid, drawn while the box is ticked and a cell is picked. */
  private updateSolid(): void {
    if (!this.view) return;
    const solid = this.view.showCellSolid(this.solidBox.checked && this.stack ? this.selected : -1);
    this.solid = solid;
    this.solidPly.disabled = !solid;
    this.solidZoom.disabled = !solid;
    document.body.dataset.cellSolid = solid ? `${solid.cell}:${solid.sections.map((s) => s.corners).join(',')}` : '';
  }

  private drawUnrolled(): void {
    if (!this.stack) return;
    drawUnrolled(this.unrolled, this.stack, this.highlight.checked, { selected: this.selected, onPick: (_surface, cell) => this.select(cell) });
  }
}

/** A button acting on the picked cell's solid: disabled until a solid is shown. */
function solidButton(id: string, text: string, title: string, onClick: () => void): HTMLButtonElement {
  const button = document.createElement('button');
  button.type = 'button';
  button.id = id;
  button.textContent = text;
  button.title = title;
  button.disabled = true;
  button.addEventListener('click', onClick);
  return button;
}
