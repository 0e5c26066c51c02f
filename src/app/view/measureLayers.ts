/**
 * The measured layers side by side, as painted by the measuring worker (measurePicture.ts: the
 * simulated surfaces' side colours, scutoids striped, excluded cells faded). A click on a cell
 * picks it: it is drawn white on every layer and described below (label, why it is left out,
 * sides, areas and neighbours per layer, neighbours won and lost from basal to apical).
 * Widths keep the layers' true proportions (an unrolled tube's apical side is wider).
 */
import type { MeasuredCellRecord, MeasuredResult } from '../../core/measure';
import { withSelected, type LayerPicture } from '../../view/measurePicture';
import { paragraphs } from './cellInfo';

const PICTURE_HEIGHT_PX = 260;

export class MeasureLayers {
  private result: MeasuredResult | null = null;
  private pictures: LayerPicture[] = [];
  private canvases: HTMLCanvasElement[] = [];
  private byLabel = new Map<number, MeasuredCellRecord>();
  selected = 0;

  constructor(
    private readonly container: HTMLElement,
    private readonly info: HTMLElement,
  ) {}

  show(result: MeasuredResult, pictures: LayerPicture[]): void {
    this.result = result;
    this.pictures = pictures;
    this.byLabel = new Map(result.cells.map((c) => [c.label, c]));
    this.selected = 0;
    this.container.replaceChildren();
    // True proportions: the same µm per screen pixel on every layer, all layers side by side
    // in the card's width (at most PICTURE_HEIGHT_PX high).
    const aspects = result.inputs.layers.map((l) => l.width / l.height);
    const room = Math.max(240, (this.container.clientWidth || 900) - 16 * aspects.length);
    const height = Math.max(80, Math.min(PICTURE_HEIGHT_PX, room / aspects.reduce((a, b) => a + b, 0)));
    this.canvases = pictures.map((picture, k) => {
      const layer = result.inputs.layers[k];
      const figure = document.createElement('figure');
      figure.className = 'unrolled';
      const canvas = document.createElement('canvas');
      canvas.width = picture.width;
      canvas.height = picture.height;
      canvas.dataset.layer = picture.name;
      canvas.setAttribute('role', 'img');
      canvas.setAttribute(
        'aria-label',
        `measured ${picture.name} layer, ${layer.width} x ${layer.height} pixels${picture.step > 1 ? `, drawn at 1/${picture.step}` : ''}; click a cell to pick it`,
      );
      canvas.style.height = `${height}px`;
      canvas.style.width = `${height * aspects[k]}px`;
      // A canvas in memory, not on the GPU: its pixels are put, never drawn (putImageData on a
      // GPU canvas cost a first 70 ms task on SwiftShader).
      canvas.getContext('2d', { willReadFrequently: true })?.putImageData(new ImageData(picture.rgba, picture.width, picture.height), 0, 0);
      canvas.addEventListener('click', (event) => this.pick(this.labelAt(k, canvas, event)));
      const caption = document.createElement('figcaption');
      caption.textContent = `${picture.name}: ${layer.file}${result.inputs.files.length === 1 ? ` page ${layer.page + 1}` : ''}, ${layer.width} x ${layer.height} px, ${layer.labels} labels`;
      figure.append(canvas, caption);
      this.container.append(figure);
      return canvas;
    });
    this.describe();
  }

  /** The raw label under a click (0: background or outside). */
  private labelAt(k: number, canvas: HTMLCanvasElement, event: MouseEvent): number {
    const picture = this.pictures[k];
    const box = canvas.getBoundingClientRect();
    const fx = (event.clientX - box.left) / box.width;
    const fy = (event.clientY - box.top) / box.height;
    if (!(fx >= 0 && fx < 1 && fy >= 0 && fy < 1)) return 0;
    return picture.labels[Math.floor(fy * picture.height) * picture.width + Math.floor(fx * picture.width)];
  }

  /** Picks the cell with raw label `label` (0: none) and redraws the layers. */
  pick(label: number): void {
    if (!this.result) return;
    this.selected = this.byLabel.has(label) ? label : 0;
    const periodicX = this.result.inputs.options.periodicX;
    this.pictures.forEach((picture, k) => {
      const rgba = withSelected(picture, this.selected, periodicX);
      this.canvases[k].getContext('2d', { willReadFrequently: true })?.putImageData(new ImageData(rgba, picture.width, picture.height), 0, 0);
    });
    this.describe();
  }

  private describe(): void {
    const info = this.info;
    info.replaceChildren();
    const cell = this.byLabel.get(this.selected);
    const result = this.result;
    if (!cell || !result) {
      info.textContent = 'Click a cell in a layer to see its neighbours.';
      delete info.dataset.label;
      return;
    }
    const names = result.inputs.layers.map((l) => l.name);
    const first = new Set(cell.neighbours[0]);
    const last = new Set(cell.neighbours[cell.neighbours.length - 1]);
    const won = [...last].filter((n) => !first.has(n));
    const lost = [...first].filter((n) => !last.has(n));
    const lines = [
      `Cell ${cell.label}: ${cell.valid ? 'valid' : `left out (${cell.exclusion?.reason ?? 'excluded'})`}, ${cell.scutoid ? 'scutoid' : 'not a scutoid'}.`,
      `Sides: ${names.map((n, k) => `${n} ${cell.sides[k]}`).join(', ')}; area: ${names.map((n, k) => `${n} ${cell.areas[k].toFixed(1)} µm²`).join(', ')}.`,
      ...names.map((n, k) => `Neighbours on ${n}: ${cell.neighbours[k].join(', ') || 'none'}.`),
      `Won from ${names[0]} to ${names[names.length - 1]}: ${won.join(', ') || 'none'}; lost: ${lost.join(', ') || 'none'}; transitions ${cell.transitions}, 3D neighbours ${cell.neighbours3D}.`,
    ];
    info.append(...paragraphs(lines));
    info.dataset.label = String(cell.label);
    info.dataset.valid = String(cell.valid);
    info.dataset.scutoid = String(cell.scutoid);
  }
}
