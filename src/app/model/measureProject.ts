/**
 * The measured tissue in the project file (issue 26, issue 28): section `measured` of
 * projectSections.ts. It keeps the input files themselves (base64, in layer order: the label
 * images or the 3D TIFF are what a measured tissue is drawn from), the option fields, the result
 * and the model comparison. Opening it measures the files again in the worker with those options
 * (the measurement is deterministic: the same numbers, checked against the saved ones) and shows
 * the saved comparison without re-running the model.
 */
export const MAX_KEPT_BYTES = 64 * 1024 * 1024;

export interface MeasuredSection {
  readonly mode: 'layers' | 'volume';
  /** Input files in layer order, or null when they were too large to keep (`omitted` says why). */
  readonly files: { readonly name: string; readonly type: string; readonly base64: string }[] | null;
  readonly omitted?: string;
  /** Option fields of the measure card: id -> value (string) or checked (boolean). */
  readonly fields: Record<string, string | boolean>;
  readonly result: unknown;
  readonly comparison: unknown;
  readonly note: string | null;
}

/** Checks a stored section's shape (untrusted input); one-line errors naming the field. */
export function readMeasuredSection(data: unknown, file: string): MeasuredSection {
  const where = `${file}: sections.measured`;
  if (typeof data !== 'object' || data === null || Array.isArray(data)) throw new Error(`${where}: expected an object.`);
  const d = data as Record<string, unknown>;
  if (d.mode !== 'layers' && d.mode !== 'volume') throw new Error(`${where}.mode: expected "layers" or "volume".`);
  if (d.files !== null && !(Array.isArray(d.files) && d.files.length > 0)) throw new Error(`${where}.files: expected a list of files or null.`);
  const files = d.files as unknown[] | null;
  files?.forEach((f, k) => {
    const r = f as Record<string, unknown>;
    if (typeof f !== 'object' || f === null || typeof r.name !== 'string' || typeof r.type !== 'string' || typeof r.base64 !== 'string') {
      throw new Error(`${where}.files[${k}]: expected { name, type, base64 } strings.`);
    }
  });
  if (typeof d.fields !== 'object' || d.fields === null || Array.isArray(d.fields)) throw new Error(`${where}.fields: expected an object.`);
  for (const [id, value] of Object.entries(d.fields)) {
    if (typeof value !== 'string' && typeof value !== 'boolean') throw new Error(`${where}.fields.${id}: expected a string or true/false.`);
  }
  if (typeof d.result !== 'object' || d.result === null) throw new Error(`${where}.result: expected the measured result.`);
  if (d.note !== null && typeof d.note !== 'string') throw new Error(`${where}.note: expected a string or null.`);
  checkStoredComparison(d.comparison, d.mode, `${where}.comparison`);
  return d as unknown as MeasuredSection;
}

/**
 * Whether a re-measurement gives the saved numbers: the whole summary of the first analysis
 * (headline, counts, per-surface distributions: files in another order differ there), compared
 * as JSON (a saved result has null where a fresh one has NaN).
 */
export function sameMeasurement(a: unknown, b: unknown): boolean {
  const summary = (r: unknown) => (r as { analyses?: { summary?: unknown }[] } | null)?.analyses?.[0]?.summary;
  const x = summary(a);
  const y = summary(b);
  return x !== undefined && y !== undefined && JSON.stringify(x) === JSON.stringify(y);
}

/** The value at a dotted path ("model.percentScutoids.mean"), or undefined. */
function at(value: unknown, path: string): unknown {
  let v = value;
  for (const key of path.split('.')) {
    if (typeof v !== 'object' || v === null || !Object.prototype.hasOwnProperty.call(v, key)) return undefined;
    v = (v as Record<string, unknown>)[key];
  }
  return v;
}

const isNumbersOrNulls = (v: unknown) => Array.isArray(v) && v.every((x) => typeof x === 'number' || x === null);

/**
 * Checks a stored model comparison (untrusted, shown as saved without re-running the model):
 * every field the page reads has its type, else a one-line error naming it. null: no comparison.
 */
export function checkStoredComparison(value: unknown, mode: 'layers' | 'volume', where: string): void {
  if (value === null) return;
  if (typeof value !== 'object' || Array.isArray(value)) throw new Error(`${where}: expected the model comparison or null.`);
  const numbers = ['bestK', 'realizations', 'seed', 'cells', 'meanPercentScutoids', 'sdPercentScutoids', 'surfaceRatio'];
  if (mode === 'volume') {
    numbers.push('geometry.seededCells', 'geometry.thickness.mean', 'geometry.thickness.sd');
    for (const m of ['percentScutoids', 'transitions', 'neighbours3D']) {
      numbers.push(`model.${m}.mean`);
      const ci = at(value, `model.${m}.ci95`);
      if (!isNumbersOrNulls(ci) || (ci as unknown[]).length !== 2) throw new Error(`${where}.model.${m}.ci95: expected two numbers (or null).`);
    }
    const kind = at(value, 'geometry.kind');
    if (kind === 'tube') numbers.push('geometry.innerRadius', 'geometry.outerRadius', 'geometry.length');
    else if (kind === 'mesh')
      numbers.push('geometry.seeded.triangles', 'geometry.other.triangles', 'geometry.projection.alongNormal', 'geometry.projection.parallel');
    else throw new Error(`${where}.geometry.kind: expected "tube" or "mesh".`);
    const seeded = at(value, 'geometry.seededLayer');
    if (seeded !== 'basal' && seeded !== 'apical') throw new Error(`${where}.geometry.seededLayer: expected "basal" or "apical".`);
  }
  for (const path of numbers) if (typeof at(value, path) !== 'number') throw new Error(`${where}.${path}: expected a number.`);
  const bestK = at(value, 'bestK') as number;
  const candidates = at(value, 'candidates');
  if (!Array.isArray(candidates) || !Number.isInteger(bestK) || bestK < 1 || bestK > candidates.length) {
    throw new Error(`${where}.candidates: expected a list with the best k (${bestK}) in it.`);
  }
  candidates.forEach((c, k) => {
    if (!isNumbersOrNulls(at(c, 'polygonDistribution')) || typeof at(c, 'distance') !== 'number') {
      throw new Error(`${where}.candidates[${k}]: expected { polygonDistribution: numbers, distance: number }.`);
    }
  });
  const perSurface = at(value, 'summary.perSurface');
  if (!Array.isArray(perSurface) || !perSurface.every((s) => isNumbersOrNulls(at(s, 'polygonDistribution')))) {
    throw new Error(`${where}.summary.perSurface: expected one record per surface with its polygon distribution.`);
  }
}
