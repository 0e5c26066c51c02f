/**
 * The sweep panel's form (sweepPanel.ts): which field to vary (any numeric field the current
 * configuration shows, or Voronoi k), from, to, points and realizations, made into the CLI's sweep
 * spec (docs/sweep.md); and a loaded spec shown back in it.
 */
import { validateConfigDraft, type ConfigDraft } from '../../core/config';
import { FIELDS } from './fields';

/** The "Voronoi k" choice: sweeps lloyd.maxIterations = k - 1 with tolerance 0. */
const VORONOI_K = 'voronoi-k';
const NUMERIC_KINDS = new Set(['number', 'integer', 'range', 'optional-number']);

interface Choice {
  value: string;
  label: string;
  integer: boolean;
}

export class SweepForm {
  /** The field varied: a select the panel places in its controls. */
  readonly field: HTMLSelectElement;

  constructor(
    private readonly root: HTMLElement,
    private readonly config: () => ConfigDraft,
    private readonly status: (text: string) => void,
  ) {
    this.field = document.createElement('select');
    this.field.name = 'sweep-field';
    this.field.setAttribute('aria-label', 'field to sweep');
  }

  /** The numeric fields shown for the current configuration, and Voronoi k. */
  refresh(): void {
    let config: ConfigDraft;
    try {
      config = this.config();
    } catch {
      return;
    }
    const choices: Choice[] = [{ value: VORONOI_K, label: 'Voronoi k (Lloyd iterations + 1)', integer: true }];
    for (const spec of FIELDS) {
      if (spec.set || !NUMERIC_KINDS.has(spec.kind) || (spec.show && !spec.show(config))) continue;
      choices.push({ value: spec.path, label: spec.unit ? `${spec.label} (${spec.unit})` : spec.label, integer: spec.kind === 'integer' });
    }
    const previous = this.field.value || (config.surface.kind === 'tube' ? 'sheet.surfaceRatio' : 'sheet.thickness');
    this.field.replaceChildren(
      ...choices.map((c) => {
        const option = new Option(c.label, c.value);
        option.dataset.integer = String(c.integer);
        return option;
      }),
    );
    const announce = this.field.dataset.shown === 'true';
    this.field.dataset.shown = 'true';
    if (choices.some((c) => c.value === previous)) {
      this.field.value = previous;
      return;
    }
    // The field varied is not one of this configuration any more (e.g. the tube's wall is now
    // set by thickness): its counterpart is taken, and the change is said, never silent.
    const counterpart = previous === 'sheet.surfaceRatio' ? 'sheet.thickness' : previous === 'sheet.thickness' ? 'sheet.surfaceRatio' : null;
    const next = counterpart && choices.some((c) => c.value === counterpart) ? counterpart : (choices[1]?.value ?? VORONOI_K);
    this.field.value = next;
    if (announce) {
      const name = (value: string) => FIELDS.find((f) => f.path === value)?.label ?? (value === VORONOI_K ? 'Voronoi k' : value);
      this.status(`vary: ${name(previous)} is not a field of this configuration now; the sweep varies ${name(next)} instead.`);
      this.root.dataset.varyChanged = `${previous}->${next}`;
    }
  }

  /** A loaded sweep's spec in the sweep's form: the field varied, from, to, points, realizations. */
  show(spec: unknown): void {
    const s = spec as { vary?: Record<string, unknown[]>; realizations?: number };
    const [path, values] = Object.entries(s.vary ?? {})[0] ?? [];
    if (!path || !Array.isArray(values) || values.length === 0) return;
    const voronoi = path === 'lloyd.maxIterations';
    const numbers = values.map(Number).map((v) => (voronoi ? v + 1 : v));
    const value = voronoi ? VORONOI_K : path;
    if (![...this.field.options].some((o) => o.value === value)) this.field.append(new Option(FIELDS.find((f) => f.path === path)?.label ?? path, value));
    this.field.value = value;
    this.field.dataset.shown = 'true';
    this.input('from').value = String(Math.min(...numbers));
    this.input('to').value = String(Math.max(...numbers));
    this.input('steps').value = String(numbers.length);
    this.input('realizations').value = String(s.realizations ?? 1);
  }

  /** The CLI sweep spec of the form: the chosen field from..to in points, realizations. */
  spec(): unknown {
    this.refresh();
    // The form's config as it stands: a default resolution stays null, so each grid point gets
    // the default of its own cells and surface (as the CLI gives a spec that leaves it out).
    const base = structuredClone(validateConfigDraft(this.config()));
    const choice = this.field.value;
    const integer = this.field.selectedOptions[0]?.dataset.integer === 'true';
    const from = Number(this.input('from').value);
    const to = Number(this.input('to').value);
    const steps = Math.max(1, Math.min(50, Math.round(Number(this.input('steps').value))));
    if (!Number.isFinite(from) || !Number.isFinite(to)) throw new Error('Sweep: give numbers for "from" and "to".');
    let values = Array.from({ length: steps }, (_, k) => Number((from + (steps > 1 ? ((to - from) * k) / (steps - 1) : 0)).toPrecision(6)));
    if (integer) values = [...new Set(values.map(Math.round))];
    const realizations = Math.max(1, Math.min(1000, Math.round(Number(this.input('realizations').value) || 1)));
    let path = choice;
    if (choice === VORONOI_K) {
      // Voronoi k is k - 1 Lloyd iterations, all of them: no early stop.
      path = 'lloyd.maxIterations';
      values = values.map((k) => k - 1);
      base.lloyd = { ...base.lloyd, tolerance: 0 };
    }
    if (path === 'sheet.surfaceRatio') base.sheet = { ...base.sheet, thickness: 0 };
    if (path === 'sheet.thickness') base.sheet = { ...base.sheet, surfaceRatio: null };
    return { base, vary: { [path]: values }, realizations, seed: base.seed, seedMode: 'per-realization' };
  }

  private input(name: string): HTMLInputElement {
    return this.root.querySelector<HTMLInputElement>(`[name="sweep-${name}"]`)!;
  }
}
