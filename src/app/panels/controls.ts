/**
 * The configuration panel: plain, labelled HTML controls rendered from FIELDS, grouped in
 * fieldsets. It holds a draft config (plain data) and reports every edit; the page validates
 * the draft and decides whether to run. `live` edits come from sliders being dragged.
 */
import type { ConfigDraft } from '../../core/config';
import { getPath, setPath } from '../../core/sweep';
import { imageFileToDataUrl } from '../../view/densityImage';
import { isUploadName, rememberUpload } from '../../view/meshFiles';
import { sampleName } from '../model/meshFiles';
import { schemaField } from '../../core/config/schemaFields';
import { readDecimal } from '../../core/config/decimal';
import { FIELDS, type FieldSpec } from './fields';

export interface ControlsEvents {
  /** `forced`: run even when the draft did not change (a file uploaded under the name already asked for). */
  onEdit(draft: ConfigDraft, live: boolean, forced?: boolean): void;
  onError(message: string): void;
}

/**
 * Engine settings, shown in a closed "Advanced" section: sound defaults, no biology in them.
 * Everything else (the surface, the sheet, the cells, the regularity) comes first.
 */
const ADVANCED = new Set([
  'resolution',
  'engine',
  'lloyd.tolerance',
  'lloyd.overRelaxation',
  'lloyd.warmStart',
  'jumpFlood.variant',
  'centroidPath',
  'sheet.minContactLength',
  'sheet.minContactPixels',
  'sheet.layerStep',
  'sheet.validityMaxRatio',
]);
/** Groups in the order a biologist meets them, with their legends. */
const GROUP_ORDER: [FieldSpec['group'], string][] = [
  ['Surface', 'Surface'],
  ['Sheet', 'Sheet: basal and apical surfaces'],
  ['Cells', 'Cells'],
  ['Lloyd', 'Regularity (Voronoi k)'],
  ['Density', 'Cell density'],
];
/** Text beside a field that follows the configuration. */
const LIVE_NOTES: Record<string, (c: ConfigDraft) => string> = {
  'lloyd.maxIterations': (c) => `Voronoi ${c.lloyd.maxIterations + 1}: k = Lloyd iterations + 1 (Voronoi 1 = random sites).`,
  // The tube's radius and length set how many cells go around it (issue 26).
  'surface.length': (c) => {
    if (c.surface.kind !== 'tube') return '';
    const around = 2 * Math.PI * c.surface.radius;
    const diameter = Math.sqrt((around * c.surface.length) / Math.max(1, c.cells));
    return `${c.cells} cells of about ${diameter.toPrecision(3)} µm across: about ${(around / diameter).toFixed(1)} cells around the tube (2π·radius = ${around.toPrecision(4)} µm) and ${(c.surface.length / diameter).toFixed(1)} along it; the radius, the length and the cells set these.`;
  },
};

interface Bound {
  spec: FieldSpec;
  row: HTMLElement;
  label: HTMLLabelElement;
  liveNote?: HTMLElement;
  input: HTMLInputElement | HTMLSelectElement;
  output?: HTMLOutputElement;
  /** A slider's number box (the labelled control: any valid value can be typed). */
  box?: HTMLInputElement;
}

/** Quiet time after the last key before a typed number is taken without Enter, ms. */
const TYPING_PAUSE_MS = 700;

/** Kinds typed as numbers: text boxes read by readDecimal (a decimal comma is a decimal). */
const NUMBER_KINDS = new Set<FieldSpec['kind']>(['number', 'integer', 'optional-number']);

/** A text box for a number: "22,5" stays 22,5 (an <input type="number"> would read 225). */
function numberBox(spec: FieldSpec): HTMLInputElement {
  const box = document.createElement('input');
  box.type = 'text';
  box.inputMode = spec.kind === 'integer' ? 'numeric' : 'decimal';
  box.autocomplete = 'off';
  box.spellcheck = false;
  box.setAttribute('role', 'spinbutton');
  box.className = 'number-box';
  if (spec.min !== undefined) box.setAttribute('aria-valuemin', String(spec.min));
  return box;
}

export class ConfigControls {
  private draft: ConfigDraft;
  private readonly bound: Bound[] = [];

  constructor(
    root: HTMLElement,
    initial: ConfigDraft,
    private readonly events: ControlsEvents,
  ) {
    this.draft = structuredClone(initial);
    // Enter in a field must not submit (reload) the page; no inline handler under the CSP.
    root.addEventListener('submit', (event) => event.preventDefault());
    const groups = new Map<string, HTMLFieldSetElement>();
    const fieldsetOf = (group: string, legend: string, parent: HTMLElement) => {
      let fieldset = groups.get(group);
      if (!fieldset) {
        fieldset = document.createElement('fieldset');
        fieldset.dataset.group = group;
        fieldset.append(Object.assign(document.createElement('legend'), { textContent: legend }));
        groups.set(group, fieldset);
        parent.append(fieldset);
      }
      return fieldset;
    };
    for (const [group, legend] of GROUP_ORDER) fieldsetOf(group, legend, root);
    const advanced = document.createElement('details');
    advanced.className = 'advanced';
    advanced.append(Object.assign(document.createElement('summary'), { textContent: 'Advanced: engine settings (defaults need no change)' }));
    root.append(advanced);
    for (const spec of FIELDS) {
      const fieldset = ADVANCED.has(spec.path) ? fieldsetOf('Advanced', 'Engine', advanced) : fieldsetOf(spec.group, spec.group, root);
      this.bound.push(this.renderField(fieldset, spec));
    }
    this.refresh();
  }

  get config(): ConfigDraft {
    return structuredClone(this.draft);
  }

  /** Writes the draft into the controls again (e.g. a slider's range that follows a result). */
  refreshControls(): void {
    this.refresh();
  }

  /** Replaces the draft (e.g. from a URL) and updates every control. */
  setConfig(config: ConfigDraft): void {
    this.draft = structuredClone(config);
    this.refresh();
  }

  private renderField(fieldset: HTMLFieldSetElement, spec: FieldSpec): Bound {
    const row = document.createElement('div');
    row.className = `field field-${spec.kind}`;
    row.dataset.path = spec.path;
    const id = `field-${spec.path.replace(/\./g, '-')}`;
    const label = document.createElement('label');
    label.htmlFor = id;
    label.textContent = spec.unit ? `${spec.label} (${spec.unit})` : spec.label;
    let input: HTMLInputElement | HTMLSelectElement;
    let output: HTMLOutputElement | undefined;
    let box: HTMLInputElement | undefined;
    if (spec.kind === 'select') {
      const select = document.createElement('select');
      for (const option of spec.options ?? []) {
        select.append(new Option(option.label, option.value));
        select.options[select.options.length - 1].disabled = option.disabled ?? false;
      }
      input = select;
    } else if (NUMBER_KINDS.has(spec.kind)) {
      input = numberBox(spec);
    } else {
      const element = document.createElement('input');
      element.type = { range: 'range', checkbox: 'checkbox', file: 'file', 'mesh-file': 'file' }[spec.kind as 'range' | 'checkbox' | 'file' | 'mesh-file'];
      if (spec.kind === 'file') element.accept = 'image/png,image/jpeg,image/webp';
      if (spec.kind === 'mesh-file') element.accept = '.ply,.obj,.stl';
      if (spec.min !== undefined) element.min = String(spec.min);
      if (spec.step !== undefined) element.step = String(spec.step);
      input = element;
    }
    input.name = spec.path;
    if (spec.kind === 'range') {
      // A slider has a number box beside it: the box is the labelled control (type any valid
      // value, decimals with a point or a comma), the slider sets it by dragging.
      box = numberBox(spec);
      box.id = id;
      input.id = `${id}-slider`;
      input.setAttribute('aria-label', 'drag to change');
      row.append(label, input, box);
    } else {
      input.id = id;
      if (spec.kind === 'checkbox') row.append(input, label);
      else row.append(label, input);
    }
    if (spec.kind === 'mesh-file') {
      output = document.createElement('output');
      output.htmlFor.add(id);
      row.append(output);
    }
    if (spec.note) {
      const note = document.createElement('small');
      note.className = 'note';
      note.textContent = spec.note;
      row.append(note);
    }
    let liveNote: HTMLElement | undefined;
    if (LIVE_NOTES[spec.path]) {
      liveNote = document.createElement('small');
      // Voronoi k keeps the class .live-note; other notes that follow the configuration are .field-note.
      liveNote.className = spec.path === 'lloyd.maxIterations' ? 'note live-note' : 'note field-note';
      row.append(liveNote);
    }
    fieldset.append(row);
    const bound: Bound = { spec, row, label, input, output, liveNote, box };
    input.addEventListener('change', () => void this.edit(bound, false));
    if (spec.live) input.addEventListener('input', () => void this.edit(bound, true));
    // Typing: a value typed or filled in runs without Enter once typing pauses (TYPING_PAUSE_MS)
    // and reads as a number; Enter or leaving the box (change) takes it at once, and cancels the
    // pause, so an unreadable final value ("1,234.5") is refused without its prefix ("1,234")
    // having run.
    const typed = box ?? (NUMBER_KINDS.has(spec.kind) ? (input as HTMLInputElement) : undefined);
    let pause: ReturnType<typeof setTimeout> | undefined;
    if (typed) {
      typed.addEventListener('input', () => {
        clearTimeout(pause);
        if (typed.value.trim() !== '' && readDecimal(typed.value).ok) pause = setTimeout(() => void this.edit(bound, false, typed), TYPING_PAUSE_MS);
      });
      // Before the input's own "change" listener above (boxes: the only one).
      typed.addEventListener('change', () => clearTimeout(pause));
    }
    box?.addEventListener('change', () => void this.edit(bound, false, box));
    return bound;
  }

  private async edit(bound: Bound, live: boolean, from: HTMLInputElement | HTMLSelectElement = bound.input): Promise<void> {
    const { spec } = bound;
    let value: unknown;
    try {
      value = from === bound.box ? this.readNumber(spec, bound.box) : await this.readValue(spec, from);
      from.removeAttribute('aria-invalid');
    } catch (error) {
      from.setAttribute('aria-invalid', 'true');
      this.events.onError((error as Error).message);
      return;
    }
    if (value === undefined) return;
    if (spec.set) this.draft = spec.set(this.draft, value);
    else {
      const next = structuredClone(this.draft);
      setPath(next, spec.path, value);
      this.draft = next;
    }
    this.refresh();
    this.events.onEdit(this.config, live, spec.kind === 'mesh-file');
  }

  private async readValue(spec: FieldSpec, input: HTMLInputElement | HTMLSelectElement): Promise<unknown> {
    switch (spec.kind) {
      case 'checkbox':
        return (input as HTMLInputElement).checked;
      case 'select':
        return input.value;
      case 'file': {
        const file = (input as HTMLInputElement).files?.[0];
        return file ? imageFileToDataUrl(file) : undefined;
      }
      case 'mesh-file': {
        // The bytes stay in memory; the config keeps the file's name (a URL cannot hold the file).
        const element = input as HTMLInputElement;
        const file = element.files?.[0];
        if (!file) return undefined;
        const name = file.name.replace(/\//g, '_') || 'mesh.ply';
        rememberUpload({ name, data: await file.arrayBuffer() });
        element.value = ''; // choosing the same file again re-runs it
        return name;
      }
      case 'range':
        return Number(input.value);
      default:
        return this.readNumber(spec, input as HTMLInputElement);
    }
  }

  /**
   * A typed number (readDecimal: "22,5" is 22.5); what cannot be read is refused in words
   * naming the field. Empty: null for an optional number, else NaN (validation names the field).
   */
  private readNumber(spec: FieldSpec, input: HTMLInputElement): number | null {
    if (input.value.trim() === '') return spec.kind === 'optional-number' ? null : Number.NaN;
    const reading = readDecimal(input.value);
    if (!reading.ok) throw new Error(`${spec.label}${spec.unit ? ` (${spec.unit})` : ''}: ${reading.message}; nothing was run.`);
    return reading.value;
  }

  /** Shows/hides fields for the draft and writes its values into the controls. */
  private refresh(): void {
    for (const { spec, row, label, input, output, liveNote, box } of this.bound) {
      const visible = spec.show ? spec.show(this.draft) : true;
      row.hidden = !visible;
      if (!visible) continue;
      // The tooltip of every control: the schema's description of its field.
      const description = kindDescription(spec.path, this.draft) ?? spec.description?.(this.draft) ?? '';
      input.title = description;
      label.title = description;
      if (box) box.title = description;
      if (liveNote) liveNote.textContent = LIVE_NOTES[spec.path](this.draft);
      if (spec.placeholder && input instanceof HTMLInputElement) input.placeholder = spec.placeholder(this.draft);
      const value = spec.get ? spec.get(this.draft) : getPath(this.draft, spec.path);
      if (spec.max !== undefined && input instanceof HTMLInputElement) {
        const max = String(typeof spec.max === 'function' ? spec.max(this.draft) : spec.max);
        if (spec.kind === 'range') input.max = max;
        else input.setAttribute('aria-valuemax', max);
      }
      if (box) {
        if (document.activeElement !== box) box.value = typeof value === 'number' && Number.isFinite(value) ? String(roundForDisplay(value)) : '';
        box.setAttribute('aria-valuenow', String(value));
      } else if (NUMBER_KINDS.has(spec.kind) && typeof value === 'number') {
        input.setAttribute('aria-valuenow', String(value));
      }
      if (spec.kind === 'checkbox') (input as HTMLInputElement).checked = Boolean(value);
      else if (spec.kind === 'file') continue;
      else if (spec.kind === 'mesh-file') {
        if (output) output.value = meshSourceText(String(value ?? ''));
        continue;
      } else if (document.activeElement !== input || spec.kind === 'select' || spec.kind === 'range') {
        input.value = value === null || value === undefined || (typeof value === 'number' && Number.isNaN(value)) ? '' : String(roundForDisplay(value));
      }
    }
  }
}

/** A union's kind selector: the description of the kind chosen (schema), not of the first one. */
function kindDescription(path: string, c: ConfigDraft): string | null {
  if (path !== 'surface.kind' && path !== 'density.kind') return null;
  const kind = path === 'surface.kind' ? c.surface.kind : c.density.kind;
  try {
    return schemaField(path, kind).description ?? null;
  } catch {
    return null;
  }
}

function meshSourceText(src: string): string {
  const sample = sampleName(src);
  if (sample) return `using the sample ${sample}`;
  return isUploadName(src) ? `using your file ${src} (not in links)` : `using ${src}`;
}

function roundForDisplay(value: unknown): unknown {
  return typeof value === 'number' ? Number(value.toPrecision(10)) : value;
}
