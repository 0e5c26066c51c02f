/**
 * The page's side of a measured volume's 3D view (docs/app.md, "Measure a volume"): a canvas
 * whose drawing is handed to a worker (src/view/volumeRenderWorker.ts, an OffscreenCanvas: the
 * WebGL context, shader compilation, drawing and picking never block the page). Here only the
 * pointer: a drag turns the one camera of the basal (left) and apical (middle) views, of the
 * tissue and of the model alike (cameras linked), the wheel zooms, a click (without a drag) asks
 * the worker which cell is under it, and on which row.
 */
import type { VolumeMeasuredResult, VolumeModelDrawing } from '../../core/measure';
import type { DrawnCell, Orbit, RowName, VolumeLayout } from '../../view/volumeRenderer';
import type { FromVolumeRenderer, ToVolumeRenderer } from '../../view/volumeRenderProtocol';
import type { CellShape, DrawnSurface } from '../../view/volumeSurfaces';

export class VolumeView {
  readonly canvas: HTMLCanvasElement;
  private readonly worker: Worker;
  private orbit: Orbit | null = null;
  private picks = new Map<number, (hit: { row: RowName; cell: number; surface: number } | null) => void>();
  private pngs = new Map<number, (png: Blob) => void>();
  private request = 0;
  /** Frames the worker has drawn (data-frames on the canvas: tests wait for a new one). */
  private frames = 0;

  /** Throws when the browser cannot hand a canvas to a worker (the caller says so in the page). */
  constructor(container: HTMLElement) {
    this.canvas = document.createElement('canvas');
    this.canvas.id = 'volume-canvas';
    this.canvas.tabIndex = 0;
    this.canvas.setAttribute('role', 'img');
    this.canvas.setAttribute(
      'aria-label',
      'measured volume in 3D: basal surface (left), apical surface (middle), picked cell (right); the model of the same geometry in a row below when shown; drag to turn, wheel to zoom, click a cell to pick it',
    );
    container.append(this.canvas);
    if (typeof this.canvas.transferControlToOffscreen !== 'function') {
      this.canvas.remove();
      throw new Error('this browser cannot draw a canvas in a worker (no OffscreenCanvas)');
    }
    const offscreen = this.canvas.transferControlToOffscreen();
    this.worker = new Worker(new URL('../../view/volumeRenderWorker.ts', import.meta.url), { type: 'module' });
    this.worker.addEventListener('message', (event: MessageEvent<FromVolumeRenderer>) => this.receive(event.data));
    const { width, height } = this.size();
    this.post({ type: 'init', canvas: offscreen, width, height }, [offscreen]);
    new ResizeObserver(() => this.post({ type: 'size', ...this.size() })).observe(this.canvas);
    this.bindPointer();
  }

  /** Shows a measured volume's surfaces; the camera fits the tissue. */
  show(result: VolumeMeasuredResult, surfaces: DrawnSurface[]): void {
    const cells: DrawnCell[] = result.cells.map((c) => ({
      id: c.id,
      label: c.label,
      valid: c.valid,
      scutoid: c.scutoid,
      sides: c.sides,
      neighbours: c.neighbours,
    }));
    // Stripes about a quarter of a mean cell across on the basal surface.
    const basal = result.inputs.layers[0];
    const stripe = Math.sqrt(basal.area / Math.max(1, basal.cells)) / 4;
    this.orbit = null;
    delete this.canvas.dataset.modelCells;
    this.layout('tissue');
    this.post(
      { type: 'show', cells, surfaces, stripe },
      surfaces.flatMap((s) => [s.positions.buffer, s.cells.buffer]),
    );
  }

  /**
   * Shows the model of the same geometry in the second row, with the tissue's legend (its cells
   * numbered 1..n, neighbours by number). Its triangles are handed to the drawing worker; the
   * per-cell arrays stay with `drawing` (the page describes a picked model cell from them).
   */
  showModel(drawing: VolumeModelDrawing): void {
    const ids = (k: number, i: number) => {
      const s = drawing.surfaces[k];
      return Array.from(s.neighbours.subarray(s.offsets[i], s.offsets[i + 1]), (j) => j + 1);
    };
    const cells: DrawnCell[] = Array.from({ length: drawing.cells }, (_, i) => ({
      id: i,
      label: i + 1,
      valid: drawing.valid[i] === 1,
      scutoid: drawing.scutoid[i] === 1,
      sides: drawing.surfaces.map((s) => s.sides[i]),
      neighbours: [ids(0, i), ids(1, i)],
    }));
    const surfaces = drawing.surfaces.map((s) => ({ name: s.name, faces: s.faces, positions: s.positions, cells: s.cells, spacing: s.spacing }));
    this.post(
      { type: 'model', cells, surfaces, stripe: (5 * drawing.surfaces[0].spacing) / 4 },
      surfaces.flatMap((s) => [s.positions.buffer, s.cells.buffer]),
    );
  }

  /** Which rows to show: the tissue, the model, or both (tissue above); the canvas grows a row for both. */
  layout(layout: VolumeLayout): void {
    this.canvas.dataset.layout = layout;
    this.canvas.classList.toggle('two-rows', layout === 'both');
    this.post({ type: 'layout', layout });
  }

  setSelected(cell: number, row: RowName = 'tissue'): void {
    this.post({ type: 'select', row, cell });
  }

  setShape(shape: CellShape | null): void {
    this.post({ type: 'shape', shape }, shape ? [shape.positions.buffer, shape.indices.buffer] : []);
  }

  /** The cell (0-based id) under a point of the page (client pixels), on the tissue's row or the model's, or null. */
  pick(clientX: number, clientY: number): Promise<{ row: RowName; cell: number; surface: number } | null> {
    const rect = this.canvas.getBoundingClientRect();
    const request = ++this.request;
    const scale = this.size().width / Math.max(1, rect.width);
    return new Promise((resolve) => {
      this.picks.set(request, resolve);
      this.post({ type: 'pick', request, x: (clientX - rect.left) * scale, y: (clientY - rect.top) * scale });
    });
  }

  /** The views as shown (basal, apical, picked cell; the tissue's row, the model's, or both) as a PNG, drawn afresh in the worker. */
  png(): Promise<Blob> {
    const request = ++this.request;
    return new Promise((resolve) => {
      this.pngs.set(request, resolve);
      this.post({ type: 'png', request });
    });
  }

  private size(): { width: number; height: number } {
    return { width: Math.max(3, this.canvas.clientWidth || 900), height: Math.max(1, this.canvas.clientHeight || 320) };
  }

  private post(message: ToVolumeRenderer, transfer: Transferable[] = []): void {
    this.worker.postMessage(message, transfer);
  }

  private receive(data: FromVolumeRenderer): void {
    if (data.type === 'shown') this.orbit = data.orbit;
    else if (data.type === 'modelShown') this.canvas.dataset.modelCells = data.cells.join(',');
    else if (data.type === 'picked') {
      this.picks.get(data.request)?.(data.hit);
      this.picks.delete(data.request);
    } else if (data.type === 'png') {
      this.pngs.get(data.request)?.(data.png);
      this.pngs.delete(data.request);
    } else if (data.type === 'drawn') this.canvas.dataset.frames = String(++this.frames);
    else this.canvas.dataset.error = data.message;
  }

  /** Drag: turn (azimuth, elevation); wheel: zoom; a click without a drag is a pick (the caller's click listener). */
  private bindPointer(): void {
    let last: { x: number; y: number } | null = null;
    let moved = 0;
    this.canvas.addEventListener('pointerdown', (event) => {
      last = { x: event.clientX, y: event.clientY };
      moved = 0;
      this.canvas.setPointerCapture(event.pointerId);
    });
    this.canvas.addEventListener('pointermove', (event) => {
      if (!last || !this.orbit) return;
      const dx = event.clientX - last.x;
      const dy = event.clientY - last.y;
      moved += Math.abs(dx) + Math.abs(dy);
      last = { x: event.clientX, y: event.clientY };
      const elevation = Math.max(-1.5, Math.min(1.5, this.orbit.elevation + dy * 0.01));
      this.turn({ ...this.orbit, azimuth: this.orbit.azimuth - dx * 0.01, elevation });
    });
    this.canvas.addEventListener('pointerup', () => (last = null));
    this.canvas.addEventListener(
      'wheel',
      (event) => {
        if (!this.orbit) return;
        event.preventDefault();
        this.turn({ ...this.orbit, distance: this.orbit.distance * Math.exp(event.deltaY * 0.001) });
      },
      { passive: false },
    );
    // A drag is not a click: the page's click listener sees dataset.dragged.
    this.canvas.addEventListener('click', () => (this.canvas.dataset.dragged = moved > 4 ? 'true' : 'false'), { capture: true });
  }

  private turn(orbit: Orbit): void {
    this.orbit = orbit;
    this.post({ type: 'orbit', orbit });
  }
}
