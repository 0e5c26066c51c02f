/**
 * Which reference curves can be laid over a sweep, and why the others cannot: a curve is drawn
 * only when its x quantity is the sweep's swept field; where curves name the other quantities
 * they hold fixed (`fixed`) and some match the sweep's configuration, only those are drawn. A
 * reference set that records the configuration it was computed with (`provenance.spec.base`)
 * is compared with the sweep's, so the page can say where they differ.
 */
import { getPath } from '../sweep/expand';
import type { ReferenceCurve, ReferenceDocument } from './format';

/** Sweep field path -> reference quantity name (the rest are their own names). */
const QUANTITY_OF_FIELD: Record<string, string> = { 'sheet.surfaceRatio': 'surfaceRatio', 'lloyd.maxIterations': 'voronoiK' };

export function quantityOfField(field: string): string {
  return QUANTITY_OF_FIELD[field] ?? field;
}

/** The value of a quantity in a configuration (Voronoi k = lloyd.maxIterations + 1), or null. */
function quantityValue(config: unknown, quantity: string): number | null {
  const field = Object.keys(QUANTITY_OF_FIELD).find((f) => QUANTITY_OF_FIELD[f] === quantity) ?? quantity;
  let value: unknown;
  try {
    value = getPath(config, field);
  } catch {
    return null;
  }
  if (typeof value !== 'number' || !Number.isFinite(value)) return null;
  return quantity === 'voronoiK' ? value + 1 : value;
}

export interface Overlay {
  drawn: ReferenceCurve[];
  /** Curves left out, each with the reason. */
  skipped: { curve: ReferenceCurve; reason: string }[];
}

/** The curves of `curves` drawn over a sweep of `field` on the configuration `base`. */
export function overlayFor(curves: readonly ReferenceCurve[], field: string, base: unknown): Overlay {
  const quantity = quantityOfField(field);
  const skipped: Overlay['skipped'] = [];
  const onAxis: ReferenceCurve[] = [];
  for (const curve of curves) {
    if (curve.quantity === quantity) onAxis.push(curve);
    else skipped.push({ curve, reason: `x is ${curve.quantity}, the sweep varies ${quantity}` });
  }
  const fixedMismatch = (curve: ReferenceCurve): string | null => {
    for (const [name, value] of Object.entries(curve.fixed)) {
      const own = quantityValue(base, name);
      if (own !== null && Math.abs(own - value) > 1e-9 * Math.max(1, Math.abs(value))) return `held at another ${name} than the sweep's ${name} = ${own}`;
    }
    return null;
  };
  const matching = onAxis.filter((c) => Object.keys(c.fixed).length > 0 && fixedMismatch(c) === null);
  if (matching.length === 0) return { drawn: onAxis, skipped };
  for (const curve of onAxis)
    if (!matching.includes(curve)) skipped.push({ curve, reason: fixedMismatch(curve) ?? 'does not say which value of the other quantities it holds' });
  return { drawn: matching, skipped };
}

/** Config fields whose values decide whether two sets of % scutoids are comparable. */
const COMPARED_FIELDS = [
  'surface.kind',
  'surface.radius',
  'surface.length',
  'cells',
  'minSpacing',
  'sheet.protocol',
  'sheet.adjacency',
  'sheet.seeded',
  'sheet.direction',
  'density.kind',
] as const;

/** Where the sweep's configuration differs from the one a reference set records (`provenance.spec.base`). */
export function configDifferences(doc: ReferenceDocument, base: unknown): { field: string; reference: unknown; sweep: unknown }[] {
  const recorded = doc.provenance && getPath(doc.provenance, 'spec.base');
  if (!recorded || typeof recorded !== 'object') return [];
  const out = [];
  for (const field of COMPARED_FIELDS) {
    const reference = getPath(recorded, field);
    const sweep = getPath(base, field);
    if (reference === undefined) continue;
    const same =
      typeof reference === 'number' && typeof sweep === 'number' ? Math.abs(reference - sweep) <= 1e-6 * Math.max(1, Math.abs(reference)) : reference === sweep;
    if (!same) out.push({ field, reference, sweep });
  }
  return out;
}
