/**
 * The sweep panel's reference curves (docs/reference-curves.md): a checkbox for the shipped set
 * (tissue-sheet's own reproduction of the lab's Voronoi tube, offered when the sweep varies the
 * surface ratio or Voronoi k; loaded on first use, a chunk of its own) and "Load reference
 * curves…" for the user's JSON or CSV (e.g. numbers digitised from a paper, each with its
 * source). Only curves whose x is the swept quantity are drawn (match.ts); the others, and where
 * the sweep's configuration differs from the one the shipped set was computed with, are said in
 * words. Under the chart, a numbered Sources list names every drawn curve's sources; the chart's
 * legend values carry those numbers. A bad file shows its one-line error in a role="alert" box
 * and leaves the curves already shown as they were.
 */
import {
  configDifferences,
  describeIntervals,
  overlayFor,
  quantityOfField,
  readReferenceFile,
  REFERENCE_LIMITS,
  validateReferenceDocument,
  type ReferenceCurve,
  type ReferenceDocument,
  type ReferencePoint,
} from '../../core/reference';
import type { ReferenceSeries, SweepChart } from './sweepChart';

/** A loaded set: where it came from and its document. */
interface LoadedSet {
  name: string;
  doc: ReferenceDocument;
}

/** Quantities the shipped set has curves for. */
const SHIPPED_QUANTITIES = new Set(['surfaceRatio', 'voronoiK']);
const SHIPPED_NAME = 'tissue-sheet reference (published tube, lab protocol, exact engine)';

export class ReferenceOverlay {
  private readonly root: HTMLElement;
  private readonly shippedBox: HTMLInputElement;
  private shipped: ReferenceDocument | null = null;
  private loaded: LoadedSet[] = [];
  private sweep: { field: string; base: unknown } | null = null;

  constructor(
    after: HTMLElement,
    private readonly chart: SweepChart,
  ) {
    this.root = document.createElement('div');
    this.root.className = 'reference-curves';
    this.root.id = 'reference-curves';
    this.root.innerHTML = `<div class="sweep-controls">
        <label title="tissue-sheet's own computation of the lab's Voronoi tubular model (200 cells, protocol lab, exact engine): a reproduction, not numbers from the paper; for sweeps over the surface ratio or Voronoi k"><input type="checkbox" name="reference-shipped" disabled /> tissue-sheet reference curves</label>
        <label title="A JSON or CSV file of % scutoids against the swept quantity, every point with its source (docs/reference-curves.md)">Load reference curves… <input name="reference-load" type="file" accept=".json,.csv,application/json,text/csv" /></label>
        <button type="button" data-reference="clear" disabled>Clear loaded</button>
      </div>
      <div class="alert reference-alert" role="alert" hidden><p class="message"></p><button type="button" data-dismiss>Dismiss</button></div>
      <p class="small" data-reference="notes"></p>
      <div data-reference="sources" hidden><h3>Sources</h3><ol></ol></div>`;
    after.after(this.root);
    this.shippedBox = this.root.querySelector<HTMLInputElement>('[name="reference-shipped"]')!;
    this.shippedBox.addEventListener('change', () => void this.toggleShipped());
    this.root
      .querySelector<HTMLInputElement>('[name="reference-load"]')!
      .addEventListener('change', (event) => void this.load(event.target as HTMLInputElement));
    this.root.querySelector('[data-reference="clear"]')!.addEventListener('click', () => {
      this.loaded = [];
      this.update();
    });
    this.root.querySelector('[data-dismiss]')!.addEventListener('click', () => (this.alertBox.hidden = true));
  }

  /** The sweep on the chart: its swept field (runs.csv column) and base configuration. */
  setSweep(field: string, base: unknown): void {
    this.sweep = { field, base };
    const offered = SHIPPED_QUANTITIES.has(quantityOfField(field));
    this.shippedBox.disabled = !offered;
    this.update();
  }

  private get alertBox(): HTMLElement {
    return this.root.querySelector<HTMLElement>('.reference-alert')!;
  }

  private alert(message: string): void {
    this.alertBox.querySelector('.message')!.textContent = message;
    this.alertBox.hidden = false;
  }

  private async toggleShipped(): Promise<void> {
    if (this.shippedBox.checked && !this.shipped) {
      try {
        this.shipped = validateReferenceDocument((await import('../../core/reference/tissueSheetVoronoiTube.json')).default);
      } catch (error) {
        this.shippedBox.checked = false;
        this.alert(`The shipped reference curves could not be read: ${(error as Error).message}`);
      }
    }
    this.update();
  }

  private async load(input: HTMLInputElement): Promise<void> {
    const file = input.files?.[0];
    input.value = '';
    if (!file) return;
    try {
      if (file.size > REFERENCE_LIMITS.maxChars) throw new Error(`${file.name}: file: ${file.size} bytes, larger than ${REFERENCE_LIMITS.maxChars} bytes`);
      const doc = readReferenceFile(file.name, await file.text());
      this.loaded = [...this.loaded.filter((set) => set.name !== file.name), { name: file.name, doc }];
      this.alertBox.hidden = true;
      this.update();
    } catch (error) {
      // What is shown stays as it was.
      this.alert((error as Error).message);
    }
  }

  /** Recomputes what is drawn, the notes and the Sources list. */
  private update(): void {
    const sets: LoadedSet[] = [
      ...(this.shippedBox.checked && this.shipped && !this.shippedBox.disabled ? [{ name: SHIPPED_NAME, doc: this.shipped }] : []),
      ...this.loaded,
    ];
    (this.root.querySelector('[data-reference="clear"]') as HTMLButtonElement).disabled = this.loaded.length === 0;
    const notes: string[] = [];
    const drawn: { set: LoadedSet; curve: ReferenceCurve }[] = [];
    for (const set of sets) {
      if (!this.sweep) {
        notes.push(`${set.name}: run a sweep to lay its ${set.doc.curves.length} curve(s) over it.`);
        continue;
      }
      const overlay = overlayFor(set.doc.curves, this.sweep.field, this.sweep.base);
      drawn.push(...overlay.drawn.map((curve) => ({ set, curve })));
      const reasons = new Map<string, number>();
      for (const { reason } of overlay.skipped) reasons.set(reason, (reasons.get(reason) ?? 0) + 1);
      const why = [...reasons].map(([reason, count]) => `${reason} (${count})`).join('; ');
      const total = set.doc.curves.length;
      if (overlay.drawn.length === 0) notes.push(`${set.name}: no curve drawn (${why}).`);
      else if (reasons.size > 0) notes.push(`${set.name}: ${overlay.drawn.length} of ${total} curves drawn; not drawn: ${why}.`);
      const differences = configDifferences(set.doc, this.sweep.base);
      if (overlay.drawn.length > 0 && differences.length > 0) {
        const pairs = differences.map((d) => `${d.field} ${shown(d.reference)} there, ${shown(d.sweep)} here`);
        notes.push(`${set.name} was computed with another configuration (${pairs.join('; ')}): compare the trend, not the values.`);
      }
    }
    // Sources, numbered in order of first use.
    const numbers = new Map<string, number>();
    const numberOf = (point: ReferencePoint) => {
      let n = numbers.get(point.source);
      if (n === undefined) numbers.set(point.source, (n = numbers.size + 1));
      return n;
    };
    const series: ReferenceSeries[] = drawn.map(({ curve }) => {
      curve.points.forEach(numberOf);
      return { curve, sourceNumber: numberOf };
    });
    // Each drawn curve: whether it has error bars, and why not.
    for (const { curve } of drawn) notes.push(describeIntervals(curve));
    this.chart.setReference(series);
    this.root.querySelector<HTMLElement>('[data-reference="notes"]')!.textContent = notes.join(' ');
    const sources = this.root.querySelector<HTMLElement>('[data-reference="sources"]')!;
    sources.hidden = drawn.length === 0;
    this.root.dataset.drawn = String(drawn.length);
    sources.querySelector('ol')!.replaceChildren(
      ...[...numbers].map(([source]) => {
        const item = document.createElement('li');
        const users = drawn.filter(({ curve }) => curve.points.some((p) => p.source === source)).map(({ curve }) => `${curve.label} (${curve.kind})`);
        item.textContent = `${source} — ${users.join('; ')}`;
        return item;
      }),
    );
  }
}

/** A config value in a note: numbers to 4 significant digits. */
function shown(value: unknown): string {
  if (typeof value === 'number') return String(Number(value.toPrecision(4)));
  return value === undefined ? 'unset' : JSON.stringify(value);
}
