/**
 * Reference curves: % scutoids against a swept quantity, each point with its source, to lay
 * beside a sweep (docs/reference-curves.md). This module is the format and its validation only:
 * a JSON document is checked field by field with one-line errors naming the field
 * (`curves[2].points[5].percent: ...`); the CSV form (referenceCsv.ts) builds the same
 * document and goes through the same checks. The work is bounded before anything is allocated
 * per point (text size, curve count, point count), and no key may reach a prototype.
 */
import { FORBIDDEN_KEYS } from '../sweep/expand';

export const REFERENCE_FORMAT = 'tissue-sheet-reference-curves';
export const REFERENCE_FORMAT_VERSION = 1;

/** Bounds checked before the work they bound. */
export const REFERENCE_LIMITS = {
  /** Characters of a file's text (UTF-16 units, at most its bytes); the page checks the file's bytes too. */
  maxChars: 2 * 1024 * 1024,
  maxCurves: 64,
  /** Points over all curves. */
  maxPoints: 10_000,
  maxLabel: 200,
  maxSource: 2000,
  /** Nesting of the free-form `provenance` object. */
  maxDepth: 16,
} as const;

type ReferenceKind = 'model' | 'data';

export interface ReferencePoint {
  x: number;
  /** % scutoids, 0..100. */
  percent: number;
  /** Standard deviation of the percent, when given. */
  sd: number | null;
  /** Number of realizations or samples behind the point, when given. */
  n: number | null;
  /** Where the number comes from: citation with figure or table, or how it was computed. */
  source: string;
}

export interface ReferenceCurve {
  id: string;
  label: string;
  kind: ReferenceKind;
  /** The x quantity: "surfaceRatio", "voronoiK", or a dotted config path ("sheet.thickness"). */
  quantity: string;
  /** Other quantities held fixed along the curve (e.g. { voronoiK: 4 }), when known. */
  fixed: Record<string, number>;
  /** Points in increasing x, each x once. */
  points: ReferencePoint[];
}

export interface ReferenceDocument {
  format: typeof REFERENCE_FORMAT;
  version: typeof REFERENCE_FORMAT_VERSION;
  title: string;
  /** Free-form: how the set was made (JSON only). */
  provenance: Record<string, unknown> | null;
  curves: ReferenceCurve[];
}

/** A bad reference file: one line naming the field (or row) and what is wrong. */
export class ReferenceError extends Error {
  override name = 'ReferenceError';
}

const QUANTITY = /^[A-Za-z][A-Za-z0-9]*(\.[A-Za-z][A-Za-z0-9]*)*$/;
const ID = /^[A-Za-z0-9][A-Za-z0-9 _.:=+-]*$/;

const fail = (where: string, message: string): never => {
  throw new ReferenceError(`${where}: ${message}`);
};

const isObject = (value: unknown): value is Record<string, unknown> => value !== null && typeof value === 'object' && !Array.isArray(value);

function checkKeys(where: string, value: Record<string, unknown>, allowed: readonly string[], required: readonly string[]): void {
  for (const key of Object.keys(value)) {
    if (FORBIDDEN_KEYS.has(key)) fail(where, `the key "${key}" is not allowed`);
    if (!allowed.includes(key)) fail(where, `unknown field "${key}" (allowed: ${allowed.join(', ')})`);
  }
  for (const key of required) if (!Object.prototype.hasOwnProperty.call(value, key)) fail(where, `missing field "${key}"`);
}

/** Refuses prototype keys at any depth of free-form JSON, and deep nesting. */
function checkFreeForm(where: string, value: unknown, depth = 0): void {
  if (depth > REFERENCE_LIMITS.maxDepth) fail(where, `nested deeper than ${REFERENCE_LIMITS.maxDepth} levels`);
  if (Array.isArray(value)) value.forEach((v, k) => checkFreeForm(`${where}[${k}]`, v, depth + 1));
  else if (isObject(value)) {
    for (const key of Object.keys(value)) {
      if (FORBIDDEN_KEYS.has(key)) fail(where, `the key "${key}" is not allowed`);
      checkFreeForm(`${where}.${key}`, value[key], depth + 1);
    }
  }
}

function text(where: string, value: unknown, max: number): string {
  if (typeof value !== 'string') fail(where, `must be text, got ${describe(value)}`);
  const trimmed = (value as string).trim();
  if (trimmed === '') fail(where, 'must not be empty');
  if (trimmed.length > max) fail(where, `longer than ${max} characters`);
  return trimmed;
}

function finite(where: string, value: unknown): number {
  if (typeof value !== 'number' || !Number.isFinite(value)) fail(where, `must be a finite number, got ${describe(value)}`);
  return value as number;
}

function describe(value: unknown): string {
  if (typeof value === 'number') return String(value);
  if (typeof value === 'string') return JSON.stringify(value.length > 40 ? `${value.slice(0, 40)}…` : value);
  if (value === null) return 'null';
  return Array.isArray(value) ? 'an array' : typeof value;
}

/** A point's fields, checked (shared by the JSON and CSV readers, which name `where`). */
export function checkPoint(where: (field: string) => string, raw: { x: unknown; percent: unknown; sd: unknown; n: unknown; source: unknown }): ReferencePoint {
  const x = finite(where('x'), raw.x);
  const percent = finite(where('percent'), raw.percent);
  if (percent < 0 || percent > 100) fail(where('percent'), `${percent} is outside 0..100`);
  let sd: number | null = null;
  if (raw.sd !== null && raw.sd !== undefined) {
    sd = finite(where('sd'), raw.sd);
    if (sd < 0) fail(where('sd'), `${sd} is negative`);
  }
  let n: number | null = null;
  if (raw.n !== null && raw.n !== undefined) {
    n = finite(where('n'), raw.n);
    if (!Number.isInteger(n) || n < 1 || n > 1e9) fail(where('n'), `${n} is not a whole number from 1 to 1e9`);
  }
  if (raw.source === undefined || raw.source === null || (typeof raw.source === 'string' && raw.source.trim() === '')) {
    fail(where('source'), 'every point needs a source (a citation with figure or table, or how it was computed)');
  }
  const source = text(where('source'), raw.source, REFERENCE_LIMITS.maxSource);
  return { x, percent, sd, n, source };
}

/** A curve's own fields (not its points), checked. */
export function checkCurveHead(
  where: (field: string) => string,
  raw: { id: unknown; label: unknown; kind: unknown; quantity: unknown },
): Omit<ReferenceCurve, 'points' | 'fixed'> {
  const id = text(where('id'), raw.id, REFERENCE_LIMITS.maxLabel);
  if (!ID.test(id)) fail(where('id'), `${describe(id)} may hold letters, digits, space and _ . : = + - only`);
  const label = text(where('label'), raw.label, REFERENCE_LIMITS.maxLabel);
  if (raw.kind !== 'model' && raw.kind !== 'data') fail(where('kind'), `must be "model" or "data", got ${describe(raw.kind)}`);
  const quantity = text(where('quantity'), raw.quantity, REFERENCE_LIMITS.maxLabel);
  if (!QUANTITY.test(quantity)) fail(where('quantity'), `${describe(quantity)} is not a quantity name ("surfaceRatio", "voronoiK" or a dotted config path)`);
  const bad = quantity.split('.').find((p) => FORBIDDEN_KEYS.has(p));
  if (bad) fail(where('quantity'), `"${bad}" is not allowed`);
  return { id, label, kind: raw.kind as ReferenceKind, quantity };
}

/** Sorts a curve's points by x and refuses a repeated x. */
export function orderPoints(where: string, points: ReferencePoint[]): ReferencePoint[] {
  const sorted = [...points].sort((a, b) => a.x - b.x);
  for (let k = 1; k < sorted.length; k++) if (sorted[k].x === sorted[k - 1].x) fail(where, `x = ${sorted[k].x} appears twice`);
  return sorted;
}

/** The whole document's bounds and uniqueness (after the curves were read). */
export function checkDocument(curves: ReferenceCurve[]): void {
  if (curves.length === 0) fail('curves', 'the file holds no curve');
  const ids = new Set<string>();
  for (const curve of curves) {
    if (ids.has(curve.id)) fail(`curve "${curve.id}"`, 'the id is used by two curves');
    ids.add(curve.id);
  }
}

/** Parses and validates a JSON reference document (see the module comment). */
export function parseReferenceJson(text: string): ReferenceDocument {
  if (text.length > REFERENCE_LIMITS.maxChars) fail('file', `larger than ${REFERENCE_LIMITS.maxChars} characters`);
  let data: unknown;
  try {
    data = JSON.parse(text);
  } catch (error) {
    fail('file', `not JSON (${(error as Error).message})`);
  }
  return validateReferenceDocument(data);
}

/** Validates a parsed JSON reference document. */
export function validateReferenceDocument(data: unknown): ReferenceDocument {
  if (!isObject(data)) fail('document', 'must be a JSON object');
  const doc = data as Record<string, unknown>;
  checkKeys('document', doc, ['format', 'version', 'title', 'provenance', 'curves'], ['format', 'version', 'curves']);
  if (doc.format !== REFERENCE_FORMAT) fail('format', `must be "${REFERENCE_FORMAT}", got ${describe(doc.format)}`);
  if (doc.version !== REFERENCE_FORMAT_VERSION) fail('version', `must be ${REFERENCE_FORMAT_VERSION}, got ${describe(doc.version)}`);
  const title = doc.title === undefined ? '' : text('title', doc.title, REFERENCE_LIMITS.maxSource);
  let provenance: Record<string, unknown> | null = null;
  if (doc.provenance !== undefined && doc.provenance !== null) {
    if (!isObject(doc.provenance)) fail('provenance', 'must be an object');
    checkFreeForm('provenance', doc.provenance);
    provenance = doc.provenance as Record<string, unknown>;
  }
  if (!Array.isArray(doc.curves)) fail('curves', `must be an array, got ${describe(doc.curves)}`);
  const rawCurves = doc.curves as unknown[];
  if (rawCurves.length > REFERENCE_LIMITS.maxCurves) fail('curves', `${rawCurves.length} curves, more than ${REFERENCE_LIMITS.maxCurves}`);
  // Count every point before reading any.
  let total = 0;
  rawCurves.forEach((c, i) => {
    if (!isObject(c)) fail(`curves[${i}]`, 'must be an object');
    const points = (c as Record<string, unknown>).points;
    if (!Array.isArray(points)) fail(`curves[${i}].points`, `must be an array, got ${describe(points)}`);
    total += (points as unknown[]).length;
    if (total > REFERENCE_LIMITS.maxPoints) fail('curves', `more than ${REFERENCE_LIMITS.maxPoints} points`);
  });
  const curves = rawCurves.map((c, i) => readCurve(`curves[${i}]`, c as Record<string, unknown>));
  checkDocument(curves);
  return { format: REFERENCE_FORMAT, version: REFERENCE_FORMAT_VERSION, title, provenance, curves };
}

function readCurve(where: string, raw: Record<string, unknown>): ReferenceCurve {
  checkKeys(where, raw, ['id', 'label', 'kind', 'quantity', 'fixed', 'points'], ['id', 'label', 'kind', 'quantity', 'points']);
  const head = checkCurveHead((f) => `${where}.${f}`, raw as { id: unknown; label: unknown; kind: unknown; quantity: unknown });
  const fixed: Record<string, number> = {};
  if (raw.fixed !== undefined) {
    if (!isObject(raw.fixed)) fail(`${where}.fixed`, 'must be an object of quantity: number');
    for (const [key, value] of Object.entries(raw.fixed as Record<string, unknown>)) {
      if (FORBIDDEN_KEYS.has(key) || !QUANTITY.test(key)) fail(`${where}.fixed`, `${describe(key)} is not a quantity name`);
      fixed[key] = finite(`${where}.fixed.${key}`, value);
    }
  }
  const rawPoints = raw.points as unknown[];
  if (rawPoints.length === 0) fail(`${where}.points`, 'the curve has no point');
  const points = rawPoints.map((p, j) => {
    const at = `${where}.points[${j}]`;
    if (!isObject(p)) fail(at, 'must be an object');
    const point = p as Record<string, unknown>;
    checkKeys(at, point, ['x', 'percent', 'sd', 'n', 'source'], ['x', 'percent', 'source']);
    return checkPoint((f) => `${at}.${f}`, point as { x: unknown; percent: unknown; sd: unknown; n: unknown; source: unknown });
  });
  return { ...head, fixed, points: orderPoints(`${where}.points`, points) };
}
