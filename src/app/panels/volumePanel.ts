/**
 * "Measure a volume" inside the measure card (docs/app.md): one 3D label TIFF (a cyst, an
 * organoid, a gland cut by the volume) measured in a worker by the CLI's own core
 * (`tissue-sheet measure --volume --compare`: src/view/volumeWorker.ts), its basal and apical
 * surfaces drawn in 3D with the model's legend (volumeView.ts), a picked cell's neighbours on
 * both sides and its 3D shape, the model of the same geometry drawn below it (its first
 * realization, same legend, same camera; a picked model cell's neighbours on both sides) and its
 * statistics beside the measured ones (mean and 95 % CI), and the exports: per-cell CSV, figure (SVG/PNG), JSON, each with its
 * provenance. The voxel size comes from the file's metadata or from the X, Y, Z fields; never
 * assumed: without either the page asks for it.
 */
import type { VolumeComparison, VolumeMeasuredResult, VolumeModelDrawing } from '../../core/measure';
import type { VolumeLayout } from '../../view/volumeRenderer';
import { MeasureFileError } from '../../view/measureClient';
import { VolumeClient } from '../../view/volumeClient';
import type { VolumeRequestOptions } from '../../view/volumeProtocol';
import type { DrawnSurface } from '../../view/volumeSurfaces';
import { withPngText } from '../model/pngText';
import { volumeCellCsv } from '../model/volumeCsv';
import { geometryText, intervalText, volumeFigure } from '../model/volumeFigure';
import { paragraphs } from '../view/cellInfo';
import { VolumeView } from '../view/volumeView';
import { downloadChart } from './chartExports';
import { download } from './exports';
import { describeVolume, volumeWords } from './volumeText';
import { volumeTable } from './volumeStats';
import { summaryNumber } from '../../core/analysis/summaryText';

/** Everything a measured volume is, as kept in a project file (measureProject.ts). */
export interface ShownVolume {
  readonly result: VolumeMeasuredResult;
  readonly comparison: VolumeComparison | null;
  readonly note: string;
}

export class VolumePanel {
  private readonly client = new VolumeClient();
  private view: VolumeView | null = null;
  private viewError: string | null = null;
  shown: ShownVolume | null = null;
  /** The model's first realization as drawn (its per-cell arrays: a picked model cell is described from them). */
  private model: VolumeModelDrawing | null = null;
  private request = 0;

  constructor(
    private readonly root: HTMLElement,
    private readonly report: {
      status(text: string): void;
      alert(message: string): void;
      state(state: string): void;
      /** A volume is now shown (in place of measured layers, if any were). */
      shown(): void;
      /** Whether a tissue, layers or a volume, is on screen. */
      anyShown(): boolean;
    },
  ) {
    this.$('#volume-json').addEventListener('click', () => this.shown && download('measured-volume.json', this.json(), 'application/json'));
    this.$('#volume-cells-csv').addEventListener(
      'click',
      () => this.shown && download('measured-volume-cells.csv', volumeCellCsv(this.shown.result, this.shown.comparison), 'text/csv'),
    );
    for (const kind of ['svg', 'png'] as const) this.$(`#volume-figure-${kind}`).addEventListener('click', () => void this.figure(kind));
    this.$('#volume-view-png').addEventListener('click', () => void this.viewPng());
    this.$<HTMLSelectElement>('#volume-layout').addEventListener('change', (event) =>
      this.view?.layout((event.target as HTMLSelectElement).value as VolumeLayout),
    );
  }

  private $<T extends HTMLElement = HTMLElement>(selector: string): T {
    return this.root.querySelector<T>(selector)!;
  }

  /** Whether a single TIFF is to be measured as a volume (the "One 3D TIFF is" choice). */
  takesVolume(files: readonly File[]): boolean {
    return files.length === 1 && /\.tiff?$/i.test(files[0].name) && this.$<HTMLSelectElement>('#measure-tiff-as').value === 'volume';
  }

  /** The volume fields, checked; a bad one is reported naming the field. */
  options(shared: { minContact?: number; realizations: number; seed: number }): VolumeRequestOptions {
    const value = (id: string) => this.$<HTMLInputElement>(id).value.trim();
    const axes = (['x', 'y', 'z'] as const).map((a) => value(`#volume-voxel-${a}`));
    let voxelSize: VolumeRequestOptions['voxelSize'];
    if (axes.some((a) => a !== '')) {
      const numbers = axes.map(Number);
      if (axes.some((a) => a === '') || numbers.some((n) => !(n > 0 && Number.isFinite(n)))) {
        throw new MeasureFileError(
          'voxel size',
          `voxel size (µm): give all three of X, Y and Z as numbers > 0 (got ${axes.map((a) => a || 'empty').join(', ')})`,
        );
      }
      voxelSize = { x: numbers[0], y: numbers[1], z: numbers[2] };
    }
    const lumen = value('#volume-lumen-label');
    if (lumen !== '' && !(Number.isInteger(Number(lumen)) && Number(lumen) >= 1 && Number(lumen) < 2 ** 32)) {
      throw new MeasureFileError('lumen label', `lumen label: ${lumen} is not a whole number from 1 to ${2 ** 32 - 1}`);
    }
    return {
      voxelSize,
      apical: this.$<HTMLSelectElement>('#volume-apical').value === 'outside' ? 'outside' : 'lumen',
      lumenLabel: lumen === '' ? undefined : Number(lumen),
      quartetFilter: this.$<HTMLInputElement>('#volume-quartets').checked,
      minContact: shared.minContact,
      realizations: shared.realizations,
      seed: shared.seed,
    };
  }

  /** Measures one 3D TIFF; `stored`: the comparison kept in a project (not re-run). */
  async measure(file: File, options: VolumeRequestOptions, stored?: { comparison: VolumeComparison | null; note: string }): Promise<void> {
    const request = ++this.request;
    this.report.state('measuring');
    this.report.status(`Measuring ${file.name} as a label volume (in a worker)…`);
    let drawn: Promise<void> = Promise.resolve();
    try {
      // A saved comparison is not re-run; its first realization is drawn again from it.
      const asked = stored ? { ...options, realizations: 0, saved: stored.comparison ?? undefined } : options;
      let compared: Promise<void> = Promise.resolve();
      await this.client.measure(file, asked, {
        onProgress: (line) => this.report.status(volumeWords(line)),
        onMeasured: (result, surfaces) => {
          drawn = this.showMeasured(result, surfaces, request);
        },
        onCompared: (comparison, note, drawing, drawingNote) => {
          compared = drawn.then(() => {
            if (request !== this.request) return;
            if (stored) this.showComparison(stored.comparison, stored.note, true);
            else this.showComparison(comparison, note);
            this.showModel(drawing, drawingNote);
          });
        },
      });
      await drawn;
      await compared;
      if (stored && !stored.comparison && request === this.request) this.showComparison(null, stored.note, true);
    } catch (error) {
      if (error instanceof MeasureFileError && error.message.startsWith('superseded')) return;
      const message = volumeWords(error instanceof Error ? error.message : String(error));
      this.report.alert(message);
      if (/voxel size/.test(message) && !options.voxelSize) this.$<HTMLInputElement>('#volume-voxel-x').focus();
      const kept = this.report.anyShown();
      this.report.status(kept ? 'Not measured; the previous tissue is still shown.' : 'Not measured.');
      this.report.state(kept ? 'shown' : 'error');
    }
  }

  private async showMeasured(result: VolumeMeasuredResult, surfaces: DrawnSurface[], request: number): Promise<void> {
    if (request !== this.request) return;
    this.shown = { result, comparison: null, note: '' };
    this.report.shown();
    this.$('#volume-results').hidden = false;
    this.root.dataset.mode = 'volume';
    const s = result.analyses[0].summary;
    const measured = this.$('#volume-measured-percent');
    measured.textContent = `${summaryNumber(s.percentScutoids, 1)} %`;
    measured.dataset.value = String(s.percentScutoids);
    this.$('#volume-model-percent').textContent = 'comparing…';
    this.$('#volume-info').textContent = describeVolume(result);
    this.$('#volume-cell').textContent = 'Click a cell on either surface to pick it.';
    this.model = null;
    this.$('#volume-model-cell').textContent = '';
    delete this.$('#volume-model-cell').dataset.cell;
    this.$('#volume-drawing-note').textContent = '';
    const layout = this.$<HTMLSelectElement>('#volume-layout');
    layout.value = 'tissue';
    layout.disabled = true;
    await nextTask();
    if (request !== this.request) return;
    try {
      this.view ??= new VolumeView(this.$('#volume-view'));
      this.view.show(result, surfaces);
      this.view.canvas.onclick = (event) => {
        if (this.view?.canvas.dataset.dragged !== 'true') void this.pick(event.clientX, event.clientY);
      };
    } catch (error) {
      this.viewError = (error as Error).message;
      this.$('#volume-view').textContent = `The 3D view is not available here (${this.viewError}); the statistics below are complete.`;
    }
    await nextTask();
    if (request !== this.request) return;
    this.$('#volume-summary-box').replaceChildren(volumeTable(result, null, 'comparing…'));
    this.$('#volume-model').textContent = '';
    this.report.state('measured');
    this.report.status(`Measured ${result.inputs.files[0].name} in ${(result.timings.totalMs / 1000).toFixed(2)} s (in a worker).`);
  }

  private showComparison(comparison: VolumeComparison | null, note: string, fromProject = false): void {
    if (!this.shown) return;
    this.shown = { ...this.shown, comparison, note };
    const model = this.$('#volume-model-percent');
    if (comparison) {
      model.textContent = `${intervalText(comparison.model.percentScutoids, 1)} %`;
      model.dataset.value = String(comparison.model.percentScutoids.mean);
      model.dataset.bestK = String(comparison.bestK);
    } else {
      model.textContent = note || 'not asked (model realizations 0)';
      model.dataset.value = '';
    }
    this.$('#volume-summary-box').replaceChildren(volumeTable(this.shown.result, comparison, note || 'not asked (model realizations 0)'));
    this.$('#volume-model').textContent = comparison
      ? `Model of the same geometry: ${geometryText(comparison)}; Voronoi ${comparison.bestK} matches the ${comparison.geometry.seededLayer} polygon distribution best (L1 ${comparison.candidates[comparison.bestK - 1].distance.toFixed(3)}), seed ${comparison.seed}.${fromProject ? ' (As saved in the project; not re-run.)' : ''}`
      : '';
    this.report.state('compared');
    this.report.status(
      comparison
        ? `Measured and compared: the model gives ${intervalText(comparison.model.percentScutoids, 1)} % scutoids, measured ${summaryNumber(this.shown.result.analyses[0].summary.percentScutoids, 1)} %.`
        : `Measured; ${note || 'no model (model realizations 0)'}.`,
    );
  }

  /** The model's first realization drawn below the tissue (both rows shown), or why not. */
  private showModel(drawing: VolumeModelDrawing | null, note: string): void {
    this.model = drawing;
    const layout = this.$<HTMLSelectElement>('#volume-layout');
    const words = this.$('#volume-drawing-note');
    if (!drawing || !this.view) {
      words.textContent = drawing ? '' : volumeWords(note);
      return;
    }
    this.view.showModel(drawing);
    layout.disabled = false;
    layout.value = 'both';
    this.view.layout('both');
    words.textContent =
      `Model drawn: realization 1 (seed ${drawing.seed}), Voronoi ${drawing.k}, ${drawing.cells} cells, ${drawing.percentScutoids.toFixed(1)} % scutoids` +
      (drawing.matches ? '.' : '; this is not the saved first realization (the volume or its meshes differ).');
    this.$('#volume-model-cell').textContent = 'Click a cell of the model to pick it.';
  }

  private async pick(clientX: number, clientY: number): Promise<void> {
    const shown = this.shown;
    const hit = await this.view?.pick(clientX, clientY);
    if (!shown || !this.view || shown !== this.shown) return;
    if (!hit) {
      this.$('#volume-cell').textContent = 'No cell there.';
      delete this.$('#volume-cell').dataset.label;
      delete this.$('#volume-model-cell').dataset.cell;
      this.view.setSelected(-1);
      this.view.setSelected(-1, 'model');
      return;
    }
    if (hit.row === 'model') this.selectModel(hit.cell);
    else this.select(hit.cell);
  }

  /** Picks model cell `id` (0-based; numbered id + 1): drawn white, its neighbours on both surfaces listed. */
  selectModel(id: number): void {
    const model = this.model;
    if (!model || !this.view) return;
    this.view.setSelected(id, 'model');
    const box = this.$('#volume-model-cell');
    const neighbours = model.surfaces.map((s) => Array.from(s.neighbours.subarray(s.offsets[id], s.offsets[id + 1]), (j) => j + 1));
    box.dataset.cell = String(id + 1);
    model.surfaces.forEach((s, k) => (box.dataset[`neighbours${k === 0 ? 'Basal' : 'Apical'}`] = neighbours[k].join(' ')));
    const lines = [
      `Model cell ${id + 1}: ${model.valid[id] ? 'valid' : 'left out (on an open end of the tube)'}, ${model.scutoid[id] ? 'a scutoid' : 'not a scutoid'}.`,
      ...model.surfaces.map((s, k) => `Model ${s.name} (faces the ${s.faces}): ${s.sides[id]} sides, neighbours ${neighbours[k].join(', ') || 'none'}.`),
    ];
    box.replaceChildren(...paragraphs(lines));
  }

  /** Picks cell `id` (0-based): drawn white, described, its shape asked of the worker. */
  select(id: number): void {
    const shown = this.shown;
    if (!shown || !this.view) return;
    const cell = shown.result.cells[id];
    this.view.setSelected(id);
    const box = this.$('#volume-cell');
    box.dataset.label = String(cell.label);
    const lines = [
      `Cell ${cell.label}: ${cell.valid ? 'valid' : `left out (${cell.exclusion?.reason ?? 'not valid'})`}, ${cell.scutoid ? 'a scutoid' : 'not a scutoid'}; volume ${cell.volume.toFixed(1)} µm³, height ${cell.height === null ? '–' : `${cell.height.toFixed(2)} µm`}.`,
      ...shown.result.inputs.layers.map(
        (layer, k) =>
          `${layer.name} (faces the ${layer.faces}): ${cell.sides[k]} sides, ${cell.areas[k].toFixed(1)} µm², neighbours ${cell.neighbours[k].join(', ') || 'none'}.`,
      ),
      `From basal to apical: won ${cell.won}, lost ${cell.lost} (transitions ${cell.transitions}); 3D neighbours ${cell.neighbours3D}; lateral neighbours ${cell.lateralNeighbours.join(', ') || 'none'}.`,
    ];
    box.replaceChildren(...paragraphs(lines));
    const view = this.view;
    void this.client
      .cellShape(id)
      .then((shape) => {
        if (this.shown === shown && box.dataset.label === String(cell.label)) {
          // Counted before the shape's buffers are handed to the drawing worker.
          box.dataset.shape = String(shape.indices.length / 3);
          view.setShape(shape);
        }
      })
      .catch(() => undefined);
  }

  private json(): string {
    const shown = this.shown!;
    const result = { ...shown.result, comparison: shown.comparison };
    return JSON.stringify(result, null, result.cells.length > 5000 ? undefined : 2) + '\n';
  }

  /** The 3D view as a PNG, its provenance in tEXt chunks (version, file, voxel size, method, picked cell). */
  private async viewPng(): Promise<void> {
    const shown = this.shown;
    if (!shown || !this.view) {
      this.report.alert(`Nothing to save: ${this.viewError ? `the 3D view is not available here (${this.viewError})` : 'no volume is shown'}.`);
      return;
    }
    const png = new Uint8Array(await (await this.view.png()).arrayBuffer());
    const { files, voxelSize: v } = shown.result.inputs;
    const picked = this.$('#volume-cell').dataset.label;
    const pickedModel = this.$('#volume-model-cell').dataset.cell;
    const layout = this.model ? (this.$<HTMLSelectElement>('#volume-layout').value as VolumeLayout) : 'tissue';
    const m = this.model;
    const rows = {
      tissue: 'the measured tissue',
      model: 'the model of the same geometry',
      both: 'the measured tissue (top row) and the model of the same geometry (bottom row)',
    }[layout];
    const modelWords =
      m && layout !== 'tissue'
        ? `; model: realization 1 (seed ${m.seed}), Voronoi ${m.k}, ${m.cells} cells${pickedModel ? `, picked model cell ${pickedModel}` : ''}`
        : '';
    const tagged = withPngText(png, [
      ['Software', `tissue-sheet ${shown.result.software.version}`],
      [
        'Description',
        `tissue-sheet measured volume in 3D, ${rows}: basal surface (left), apical surface (middle), picked cell (right); ${files[0].name}, voxel ${v.x} x ${v.y} x ${v.z} µm (${v.source}); cells coloured by their sides on each surface, scutoids striped, cells left out faded${picked && layout !== 'model' ? `; picked cell ${picked} (white, non-neighbours darkened)` : ''}${modelWords}`,
      ],
      ['tissue-sheet:version', shown.result.software.version],
      [
        'tissue-sheet:method',
        m && layout !== 'tissue'
          ? 'measured: contact curves in µm on the voxel surfaces; model: exact Voronoi (compareVolume), its first realization drawn'
          : 'measured: contact curves in µm on the voxel surfaces',
      ],
      [
        'tissue-sheet:config',
        JSON.stringify({
          inputs: shown.result.inputs,
          ...(m && layout !== 'tissue'
            ? { model: { realization: 0, seed: m.seed, k: m.k, cells: m.cells, geometry: shown.comparison?.geometry ?? null } }
            : {}),
        }),
      ],
    ]);
    download('tissue-sheet-measured-volume-3d.png', new Blob([tagged as BlobPart], { type: 'image/png' }));
  }

  private async figure(kind: 'svg' | 'png'): Promise<void> {
    const shown = this.shown;
    if (!shown) return;
    try {
      await downloadChart(kind, 'tissue-sheet-measured-volume', volumeFigure(shown.result, shown.comparison), {
        what: 'tissue-sheet measured volume beside the model of the same geometry',
        engine: shown.comparison
          ? `measured: voxel surfaces of ${shown.result.inputs.files[0].name}; model: exact CPU Voronoi (compareVolume, ${shown.comparison.geometry.kind})`
          : `measured: voxel surfaces of ${shown.result.inputs.files[0].name}`,
        method: shown.comparison ? 'measured: contact curves in µm on the voxel surfaces; model: exact' : 'contact curves in µm on the voxel surfaces',
        seed: shown.comparison?.seed ?? '',
        config: {
          inputs: shown.result.inputs,
          model: shown.comparison
            ? { realizations: shown.comparison.realizations, seed: shown.comparison.seed, bestK: shown.comparison.bestK, geometry: shown.comparison.geometry }
            : null,
        },
      });
    } catch (error) {
      this.report.alert((error as Error).message);
    }
  }
}

const nextTask = () => new Promise<void>((resolve) => setTimeout(resolve, 0));
