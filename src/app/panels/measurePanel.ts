/**
 * "Measure a tissue" (docs/app.md): label images dropped anywhere on the page, or chosen with
 * the file picker — two or more PNG/TIFF layers (basal first; each file's layer can be
 * reassigned, layerAssign.ts), or one 3D TIFF (a label volume: volumePanel.ts; or its pages as
 * layers) — are measured in a
 * worker (src/view/measureClient.ts: decoding and counting never run on the main thread), drawn
 * with the simulated surfaces' side colours with cell picking, and their statistics shown
 * beside the best-matching Voronoi model's (the CLI's --compare). Options: pixel size, periodic
 * x, min contact, model realizations. A bad file shows a role="alert" line naming the file and
 * the problem; what is already shown stays.
 */
import type { MeasuredResult, ModelComparison, VolumeComparison } from '../../core/measure';
import { downloadChart } from './chartExports';
import { download } from './exports';
import { measuredCellCsv } from '../model/measuredCsv';
import { MeasureClient, MeasureFileError } from '../../view/measureClient';
import type { LayerPicture } from '../../view/measurePicture';
import type { MeasureRequestOptions } from '../../view/measureProtocol';
import { MeasureLayers } from '../view/measureLayers';
import { MeasureChart, renderHeadline, summaryTable } from './measureStats';
import { LayerAssign } from './layerAssign';
import { VolumePanel } from './volumePanel';
import { VOLUME_OPTIONS, VOLUME_RESULTS } from './volumeText';
import './measurePanel.css';

const TEMPLATE = `
  <h2 id="measure-title">Measure a tissue</h2>
  <p class="small">Segmented label images of one tissue at two or more depths (0 = background, the same label is the same
  cell in every layer): measured with the same definitions as a simulated sheet (docs/measure.md), beside the Voronoi model
  whose basal polygon distribution matches best.</p>
  <div id="measure-drop" class="measure-drop">
    <p>Drop label images anywhere on the page — <b>two or more PNG/TIFF layers, basal first</b>, or <b>one 3D TIFF</b> —
    or <label class="measure-pick">choose files <input id="measure-files" type="file" multiple accept=".png,.tif,.tiff,image/png,image/tiff" /></label></p>
  </div>
  <div class="measure-options">
    <label title="Edge of one square pixel in micrometres; empty: from the TIFF metadata">Pixel size (µm)
      <input id="measure-pixel-size" type="number" min="0" step="any" placeholder="from the files" /></label>
    <label title="The images are an unrolled tube: the last column touches the first"><input id="measure-periodic" type="checkbox" /> periodic x (unrolled tube)</label>
    <label title="Shortest shared boundary that makes two cells neighbours; empty: the lab's 6 px for cells 102.4 px across, scaled to this tissue">Min contact (µm)
      <input id="measure-min-contact" type="number" min="0" step="any" placeholder="default" /></label>
    <label title="Realizations of the Voronoi model (0: no comparison)">Model realizations
      <input id="measure-realizations" type="number" min="0" max="100" step="1" value="10" /></label>
    <button type="button" id="measure-again" disabled>Measure again</button>
    <button type="button" id="measure-reverse" disabled title="The first file is the basal layer">Reverse layer order</button>
    <button type="button" id="measure-json" disabled title="The measured result with its comparison, as tissue-sheet measure writes it">Result JSON</button>
    <button type="button" id="measure-cells-csv" disabled title="One row per cell: valid, scutoid, sides, areas and neighbours per layer, won, lost, transitions">Per-cell CSV</button>
    <button type="button" id="measure-figure-svg" disabled title="The measured-vs-model polygon distributions as SVG, at the width chosen under the exports">Comparison SVG</button>
    <button type="button" id="measure-figure-png" disabled title="The measured-vs-model polygon distributions as PNG, at the DPI and width chosen under the exports">Comparison PNG</button>
  </div>${VOLUME_OPTIONS}
  <p id="measure-status" class="small" role="status" aria-live="polite"></p>
  <div id="measure-alert" class="alert measure-alert" role="alert" hidden><p class="message"></p><button type="button" data-dismiss>Dismiss</button></div>${VOLUME_RESULTS}
  <div id="measure-results" hidden>
    <div id="measure-layer-files" hidden></div>
    <p class="headline"><output id="measured-percent">–</output> scutoids measured;
      model <output id="model-percent">–</output> <span id="model-caption" class="small"></span></p>
    <p id="measure-sides" role="status"></p>
    <p id="measure-info" class="small"></p>
    <div id="measure-layers" class="unrolled-row"></div>
    <div id="measure-cell" class="small"></div>
    <div class="measure-stats"><div id="measure-summary-box" class="table-box"></div><div id="measure-chart" class="chart"></div></div>
  </div>`;

/** Lets the browser handle input between the parts of drawing (no task over ~50 ms). */
const nextTask = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/** The core's messages name the CLI's options; the page names its fields. */
function inPageWords(message: string): string {
  return message
    .replace(/--pixel-size µm \(--pixel-size 1 measures in pixels\)/g, 'a pixel size (µm) above (1 measures in pixels)')
    .replace(/--pixel-size/g, 'the pixel size (µm) field')
    .replace(/--min-contact/g, 'the min contact field')
    .replace(/--periodic-x/g, 'periodic x');
}

export class MeasurePanel {
  private readonly client = new MeasureClient();
  private readonly layers: MeasureLayers;
  private readonly chart: MeasureChart;
  readonly volume: VolumePanel;
  private readonly assign: LayerAssign;
  /** The files of the latest attempt (Measure again, Reverse), basal first. */
  private files: File[] = [];
  /** The files of the tissue on screen (a failed attempt leaves them): what a project keeps. */
  private shownFiles: File[] = [];
  /** The file of the volume being measured, on screen once measured. */
  private volumeFiles: File[] = [];
  private result: MeasuredResult | null = null;
  private comparison: ModelComparison | null = null;
  private shown = 0;

  constructor(private readonly root: HTMLElement) {
    root.innerHTML = TEMPLATE;
    this.layers = new MeasureLayers(this.$('#measure-layers'), this.$('#measure-cell'));
    this.chart = new MeasureChart(this.$('#measure-chart'));
    this.volume = new VolumePanel(root, {
      status: (text) => this.status(text),
      alert: (message) => this.alert(message),
      state: (state) => (this.root.dataset.state = state),
      shown: () => {
        this.$('#measure-results').hidden = true;
        this.shownFiles = this.volumeFiles;
      },
      anyShown: () => this.anyShown(),
    });
    this.assign = new LayerAssign(this.$('#measure-layer-files'), (files) => void this.measure(files));
    const input = this.$<HTMLInputElement>('#measure-files');
    input.addEventListener('change', () => {
      if (input.files && input.files.length > 0) void this.measure([...input.files]);
      input.value = '';
    });
    this.$('#measure-again').addEventListener('click', () => void this.measure(this.files));
    this.$('#measure-reverse').addEventListener('click', () => void this.measure([...this.files].reverse()));
    this.$('#measure-json').addEventListener('click', () => this.download());
    for (const kind of ['svg', 'png'] as const) this.$(`#measure-figure-${kind}`).addEventListener('click', () => void this.figure(kind));
    this.$('#measure-cells-csv').addEventListener('click', () => this.result && download('measured-cells.csv', measuredCellCsv(this.result), 'text/csv'));
    this.$('#measure-alert [data-dismiss]').addEventListener('click', () => (this.$('#measure-alert').hidden = true));
    this.bindDrop();
  }

  private $<T extends HTMLElement = HTMLElement>(selector: string): T {
    return this.root.querySelector<T>(selector)!;
  }

  /** What is shown, for the project file (measureProject.ts): the files in layer order, the result and the comparison. */
  shownTissue(): { mode: 'layers' | 'volume'; files: File[]; result: unknown; comparison: unknown; note: string | null } | null {
    if (this.root.dataset.mode === 'volume' && this.volume.shown) {
      const v = this.volume.shown;
      return { mode: 'volume', files: this.shownFiles, result: v.result, comparison: v.comparison, note: v.note };
    }
    if (this.root.dataset.mode === 'layers' && this.result)
      return { mode: 'layers', files: this.shownFiles, result: this.result, comparison: this.comparison, note: null };
    return null;
  }

  /** The card's option fields (id -> value, or checked for checkboxes), to keep and restore. */
  fields(): HTMLInputElement[] {
    return [...this.root.querySelectorAll<HTMLInputElement>('.measure-options input:not([type=file]), .measure-options select')].filter((f) => f.id);
  }

  /** Files dropped anywhere on the page (except on another file input, which takes its own). */
  private bindDrop(): void {
    const hasFiles = (event: DragEvent) => event.dataTransfer?.types.includes('Files') ?? false;
    const ownDrop = (event: DragEvent) => !(event.target instanceof HTMLInputElement && event.target.type === 'file');
    document.addEventListener('dragover', (event) => {
      if (!hasFiles(event) || !ownDrop(event)) return;
      event.preventDefault();
      this.root.classList.add('dragging');
    });
    document.addEventListener('dragleave', (event) => {
      if (event.relatedTarget === null) this.root.classList.remove('dragging');
    });
    document.addEventListener('drop', (event) => {
      this.root.classList.remove('dragging');
      if (!hasFiles(event) || !ownDrop(event)) return;
      event.preventDefault();
      const files = [...(event.dataTransfer?.files ?? [])];
      if (files.length > 0) void this.measure(files);
    });
  }

  private alert(message: string): void {
    const box = this.$('#measure-alert');
    box.querySelector('.message')!.textContent = message;
    box.hidden = false;
  }

  private status(text: string): void {
    this.$('#measure-status').textContent = text;
  }

  /** The options fields, checked; a bad one is reported naming the field. */
  private options(): MeasureRequestOptions {
    const value = (id: string) => this.$<HTMLInputElement>(id).value.trim();
    const pixel = value('#measure-pixel-size');
    const contact = value('#measure-min-contact');
    const realizations = Number(value('#measure-realizations') || '0');
    if (pixel !== '' && !(Number(pixel) > 0 && Number.isFinite(Number(pixel))))
      throw new MeasureFileError('pixel size', `pixel size (µm): ${pixel} is not a number > 0`);
    if (contact !== '' && !(Number(contact) >= 0 && Number.isFinite(Number(contact))))
      throw new MeasureFileError('min contact', `min contact (µm): ${contact} is not a number >= 0`);
    if (!Number.isInteger(realizations) || realizations < 0 || realizations > 100) {
      throw new MeasureFileError('model realizations', `model realizations: ${value('#measure-realizations')} is not an integer 0..100`);
    }
    return {
      pixelSize: pixel === '' ? undefined : Number(pixel),
      periodicX: this.$<HTMLInputElement>('#measure-periodic').checked,
      minContact: contact === '' ? undefined : Number(contact),
      realizations,
      seed: 1,
    };
  }

  /**
   * Measures `files` (basal first). `stored`: a comparison kept in a project file, shown as
   * saved instead of running the model again (measureProject.ts).
   */
  async measure(files: File[], stored?: { comparison: unknown; note: string | null }): Promise<void> {
    if (files.length === 0) return;
    this.files = files;
    for (const id of ['#measure-again', '#measure-reverse']) this.$<HTMLButtonElement>(id).disabled = false;
    let options: MeasureRequestOptions;
    try {
      options = this.options();
    } catch (error) {
      this.alert((error as Error).message);
      return;
    }
    this.$('#measure-alert').hidden = true;
    if (this.volume.takesVolume(files)) {
      let volumeOptions;
      try {
        volumeOptions = this.volume.options({ minContact: options.minContact, realizations: options.realizations, seed: options.seed });
      } catch (error) {
        this.alert((error as Error).message);
        return;
      }
      // The layers on screen stay until the volume is measured (a bad file keeps them).
      this.$<HTMLButtonElement>('#measure-reverse').disabled = true;
      this.volumeFiles = files;
      return this.volume.measure(
        files[0],
        volumeOptions,
        stored ? { comparison: stored.comparison as VolumeComparison | null, note: stored.note ?? '' } : undefined,
      );
    }
    this.root.dataset.state = 'measuring';
    this.status(`Measuring ${files.map((f) => f.name).join(', ')} (basal first)…`);
    let measured: Promise<void> = Promise.resolve();
    try {
      await this.client.measure(files, stored ? { ...options, realizations: 0 } : options, {
        onProgress: (line) => this.status(line),
        onMeasured: (result, pictures) => {
          measured = this.showMeasured(result, pictures, files);
        },
        onCompared: (comparison, note) => {
          void measured.then(() => this.showComparison(comparison, note));
        },
      });
      await measured;
      if (stored) await this.showComparison(stored.comparison as ModelComparison | null, stored.note);
    } catch (error) {
      if (error instanceof MeasureFileError && error.message.startsWith('superseded')) return;
      this.alert(inPageWords(error instanceof Error ? error.message : String(error)));
      const kept = this.anyShown();
      this.status(kept ? 'Not measured; the previous tissue is still shown.' : 'Not measured.');
      this.root.dataset.state = kept ? 'shown' : 'error';
    }
  }

  /** Whether a measured tissue (layers or a volume) is on screen. */
  private anyShown(): boolean {
    return !this.$('#measure-results').hidden || !this.$('#volume-results').hidden;
  }

  private async showMeasured(result: MeasuredResult, pictures: LayerPicture[], files: File[]): Promise<void> {
    const shown = ++this.shown;
    this.shownFiles = files;
    // The layers take the place of a volume on screen only now that they are measured.
    this.$('#volume-results').hidden = true;
    this.root.dataset.mode = 'layers';
    this.result = result;
    this.comparison = null;
    this.$<HTMLButtonElement>('#measure-json').disabled = false;
    for (const id of ['#measure-figure-svg', '#measure-figure-png', '#measure-cells-csv']) this.$<HTMLButtonElement>(id).disabled = false;
    this.$('#measure-results').hidden = false;
    this.assign.show(files);
    renderHeadline(this.root, result, null, null);
    this.$('#measure-info').textContent = describe(result);
    this.sides(result);
    this.layers.show(result, pictures);
    await nextTask();
    if (shown !== this.shown) return;
    this.$('#measure-summary-box').replaceChildren(summaryTable(result, null));
    await nextTask();
    if (shown !== this.shown) return;
    this.chart.show(result, null);
    this.root.dataset.state = 'measured';
    this.status(`Measured in ${(result.timings.totalMs / 1000).toFixed(2)} s (in a worker); comparing with the Voronoi model…`);
  }

  private async showComparison(comparison: ModelComparison | null, note: string | null): Promise<void> {
    const result = this.result;
    if (!result) return;
    const shown = this.shown;
    this.comparison = comparison;
    renderHeadline(this.root, result, comparison, note);
    this.$('#measure-summary-box').replaceChildren(summaryTable(result, comparison));
    await nextTask();
    if (shown !== this.shown) return;
    this.chart.show(result, comparison);
    this.root.dataset.state = 'compared';
    this.status(
      comparison
        ? `Measured and compared: Voronoi ${comparison.bestK} matches best; at s = ${comparison.surfaceRatio.toFixed(3)} it gives ${comparison.meanPercentScutoids.toFixed(1)} ± ${comparison.sdPercentScutoids.toFixed(1)} % scutoids.`
        : `Measured; ${note ?? 'no comparison'}.`,
    );
  }

  /**
   * Which file is taken as which side, said in words; a surface ratio below 1 (the layer taken as
   * basal is the wider, against s = basal-to-apical widening of the model) is warned about, with
   * the button that swaps the order: never s < 1 silently.
   */
  private sides(result: MeasuredResult): void {
    const box = this.$('#measure-sides');
    const layers = result.inputs.layers;
    const first = layers[0];
    const last = layers[layers.length - 1];
    const s = result.surfaceRatio.value;
    const taken = `Taken as basal: ${first.file}${result.inputs.files.length === 1 ? ` (page ${first.page + 1})` : ''}; as apical: ${last.file}${result.inputs.files.length === 1 ? ` (page ${last.page + 1})` : ''} (the first file is basal, in the order given; the layer pickers above, or Reverse layer order, reassign them).`;
    // The file names contradict the order (a file dialog hands files over alphabetically).
    const named = (/apical/i.test(first.file) && !/basal/i.test(first.file)) || (/basal/i.test(last.file) && !/apical/i.test(last.file));
    const below = s < 1;
    const warnings: string[] = [];
    if (named)
      warnings.push(
        `the file taken as basal is named ${first.file} and the one taken as apical ${last.file}: if the names are right, press Reverse layer order.`,
      );
    if (below) {
      warnings.push(
        `the surface ratio comes out s = ${s.toFixed(3)} < 1: the layer taken as basal is the wider one. Either the files are in the wrong order (Reverse layer order), or the basal side of this tissue is the wider (as in a salivary gland), which the model's s (apical width / basal width, seeded basal) reads as s < 1.`,
      );
    }
    const warn = warnings.length > 0;
    box.textContent = warn
      ? `${taken} Warning: ${warnings.join(' Also, ')}`
      : `${taken} Surface ratio s = ${s.toFixed(3)} (from the ${result.surfaceRatio.source}).`;
    box.className = warn ? 'by-construction measure-warning' : 'small';
    box.dataset.warning = [named ? 'names' : '', below ? 'ratio-below-1' : ''].filter(Boolean).join(' ');
  }

  /** The measured-vs-model comparison as a figure file, with the measurement's provenance. */
  private async figure(kind: 'svg' | 'png'): Promise<void> {
    const result = this.result;
    if (!result) return;
    try {
      await downloadChart(kind, 'tissue-sheet-measured-vs-model', this.chart.figure(), {
        what: 'tissue-sheet measured tissue beside the Voronoi model',
        engine: this.comparison ? 'measured: label images; model: exact CPU Voronoi (compareMeasured)' : 'measured: label images',
        method: this.comparison ? 'measured: pixel-based adjacency; model: exact' : 'pixel-based adjacency',
        seed: this.comparison?.seed ?? '',
        config: {
          inputs: result.inputs,
          model: this.comparison
            ? {
                cells: this.comparison.cells,
                realizations: this.comparison.realizations,
                seed: this.comparison.seed,
                bestK: this.comparison.bestK,
                surfaceRatio: this.comparison.surfaceRatio,
              }
            : null,
        },
      });
    } catch (error) {
      this.alert((error as Error).message);
    }
  }

  /** The result JSON of the tissue shown, in the CLI's shape (comparison included once made). */
  private download(): void {
    if (!this.result) return;
    const result = { ...this.result, comparison: this.comparison };
    const text = JSON.stringify(result, null, result.cells.length > 5000 ? undefined : 2) + '\n';
    const link = document.createElement('a');
    link.href = URL.createObjectURL(new Blob([text], { type: 'application/json' }));
    link.download = 'measured.json';
    link.click();
    setTimeout(() => URL.revokeObjectURL(link.href), 10_000);
  }
}

function describe(result: MeasuredResult): string {
  const s = result.analyses[0].summary;
  const p = result.inputs.pixelSize;
  const layers = result.inputs.layers.map((l) => `${l.name} ${l.file}${result.inputs.files.length === 1 ? ` page ${l.page + 1}` : ''}`).join(', ');
  const warnings = result.warnings.length ? ` Warnings: ${result.warnings.map(inPageWords).join('; ')}.` : '';
  return (
    `${s.cells} cells, ${s.validCells} valid (${result.exclusions.touchesBorder} touch an open border, ${result.exclusions.missing} missing from a layer), ` +
    `${s.surfaces} layers (${layers}); pixel size ${p.value} µm (${p.source === 'option' ? 'given' : `${p.detail}, ${p.file}`}), ` +
    `min contact ${result.analyses[0].minContactLength.toPrecision(3)} µm (${result.inputs.options.minContactSource}), ` +
    `surface ratio ${result.surfaceRatio.value.toFixed(3)} (from the ${result.surfaceRatio.source}), ${result.inputs.options.periodicX ? 'periodic x' : 'not periodic'}; ` +
    `pixel-based adjacency.${warnings}`
  );
}

/** Mounts the panel as a card at the end of `main`. */
export function mountMeasurePanel(main: HTMLElement): MeasurePanel {
  const section = document.createElement('section');
  section.className = 'card wide measure';
  section.id = 'measure';
  section.setAttribute('aria-labelledby', 'measure-title');
  main.append(section);
  return new MeasurePanel(section);
}
