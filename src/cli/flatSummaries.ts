/**
 * Run summaries as a sweep's rows take them: column names and values side by side (flatList), not
 * a nested summary flattened per run. The names are made once per shape of summary (flatValues);
 * the values come straight from the result (sweepSummaryValues) once that shape's first run showed
 * them equal to flatValues(sweepSummary(result)), else from the summary itself. The sweep's worker
 * threads send them to the main thread this way (its `layout` number names a key list sent once),
 * and the main thread's own runs take the same path.
 */
import { flattenSummary } from '../core/sweep';
import { flatKeys, flatValues } from '../core/sweep/flatValues';
import { sweepSummary, sweepSummaryValues, type SheetResult } from '../run/index';

export interface FlatSummary {
  /** The number of its key list, in the order shapes were met. */
  readonly layout: number;
  readonly keys: string[];
  /** Whether a summary of this key list was flattened before (a thread sent its keys then). */
  readonly known: boolean;
  readonly values: unknown[];
}

export class FlatSummaries {
  /** Per summary shape (flatValues): its layout number, keys, and whether its values line up with the keys. */
  private readonly layouts = new Map<string, { layout: number; keys: string[]; aligned: boolean }>();
  /**
   * Per shape of sweepSummaryValues: the layout of the summaries of that shape, once their values
   * were found to be flatValues' (on the shape's first run); null where they were not (the
   * summary is then flattened as it is, every run).
   */
  private readonly directShapes = new Map<string, { layout: number; keys: string[] } | null>();

  /** The summary of `result`, flat. */
  of(result: SheetResult): FlatSummary {
    const direct = sweepSummaryValues(result);
    if (!direct) return this.flattened(result);
    const kept = this.directShapes.get(direct.shape);
    if (kept) return { ...kept, known: true, values: direct.values };
    const generic = this.flattened(result);
    if (kept === undefined) {
      const same = generic.values.length === direct.values.length && generic.values.every((value, n) => Object.is(value, direct.values[n]));
      this.directShapes.set(direct.shape, same ? { layout: generic.layout, keys: generic.keys } : null);
    }
    return generic;
  }

  /** Through the nested summary: flatValues, with the keys of flattenSummary made once per shape. */
  private flattened(result: SheetResult): FlatSummary {
    const summary = sweepSummary(result);
    const flat = flatValues(summary);
    let shape = this.layouts.get(flat.shape);
    const known = shape !== undefined;
    if (shape === undefined) {
      const keys = Object.keys(flattenSummary(summary));
      const own = flatKeys(summary);
      const aligned = own.length === keys.length && own.every((k, n) => k === keys[n]);
      this.layouts.set(flat.shape, (shape = { layout: this.layouts.size, keys, aligned }));
    }
    const { layout, keys } = shape;
    return { layout, keys, known, values: shape.aligned ? flat.values : Object.values(flattenSummary(summary)) };
  }
}
