/**
 * The CSV form of reference curves: one row per point, columns
 * `curve,label,kind,quantity,source,x,percent,sd,n` in any order (`sd` and `n` optional, their
 * cells may be empty). Rows with the same `curve` id form a curve; its label, kind and quantity
 * must be the same on each of its rows. Errors name the line and the column. The rows are
 * counted before any is read; the document is then checked as a JSON one is (format.ts).
 */
import { parseCsv } from '../sweep/csv';
import {
  checkCurveHead,
  checkDocument,
  checkPoint,
  orderPoints,
  REFERENCE_FORMAT,
  REFERENCE_FORMAT_VERSION,
  REFERENCE_LIMITS,
  ReferenceError,
  type ReferenceCurve,
  type ReferenceDocument,
  type ReferencePoint,
} from './format';

const REFERENCE_CSV_COLUMNS = ['curve', 'label', 'kind', 'quantity', 'source', 'x', 'percent', 'sd', 'n'] as const;
const REQUIRED = ['curve', 'label', 'kind', 'quantity', 'source', 'x', 'percent'];

/** A plain decimal number (no NaN, Infinity, hex or spaces). */
const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

export function parseReferenceCsv(text: string): ReferenceDocument {
  if (text.length > REFERENCE_LIMITS.maxChars) throw new ReferenceError(`file: larger than ${REFERENCE_LIMITS.maxChars} characters`);
  // Bound the rows before parsing any: one line per point at most, plus the header.
  let lines = 0;
  for (let i = text.indexOf('\n'); i >= 0; i = text.indexOf('\n', i + 1)) {
    if (++lines > REFERENCE_LIMITS.maxPoints + 1) throw new ReferenceError(`file: more than ${REFERENCE_LIMITS.maxPoints} rows`);
  }
  const body = text.startsWith('\uFEFF') ? text.slice(1) : text;
  const parsed = parseCsv(body.endsWith('\n') ? body : `${body}\n`);
  if (parsed.truncated) throw new ReferenceError(`line ${parsed.lines.length + 1}: a quoted cell is not closed`);
  const records = parsed.records.map((r, k) => ({ cells: r, line: parsed.lines[k] })).filter((r) => !(r.cells.length === 1 && r.cells[0].trim() === ''));
  if (records.length === 0) throw new ReferenceError('file: empty; the first line must be the header curve,label,kind,quantity,source,x,percent,sd,n');
  const [head, ...rows] = records;
  const header = head.cells.map((h) => h.trim());
  const seen = new Set<string>();
  for (const name of header) {
    if (!(REFERENCE_CSV_COLUMNS as readonly string[]).includes(name))
      throw new ReferenceError(`line ${head.line}: unknown column "${name}" (columns: ${REFERENCE_CSV_COLUMNS.join(', ')})`);
    if (seen.has(name)) throw new ReferenceError(`line ${head.line}: column "${name}" appears twice`);
    seen.add(name);
  }
  for (const name of REQUIRED) if (!seen.has(name)) throw new ReferenceError(`line ${head.line}: missing column "${name}"`);
  if (rows.length === 0) throw new ReferenceError('file: no row after the header');

  const curves = new Map<string, { curve: Omit<ReferenceCurve, 'points' | 'fixed'>; line: number; points: ReferencePoint[] }>();
  for (const { cells, line } of rows) {
    if (cells.length !== header.length) throw new ReferenceError(`line ${line}: ${cells.length} cells, the header has ${header.length}`);
    const cell = (name: string) => {
      const k = header.indexOf(name);
      return k < 0 ? '' : cells[k].trim();
    };
    const where = (field: string) => `line ${line}, column ${field === 'id' ? 'curve' : field}`;
    const head = checkCurveHead(where, { id: cell('curve'), label: cell('label'), kind: cell('kind'), quantity: cell('quantity') });
    let entry = curves.get(head.id);
    if (!entry) {
      if (curves.size >= REFERENCE_LIMITS.maxCurves) throw new ReferenceError(`line ${line}: more than ${REFERENCE_LIMITS.maxCurves} curves`);
      curves.set(head.id, (entry = { curve: head, line, points: [] }));
    } else {
      for (const field of ['label', 'kind', 'quantity'] as const) {
        if (entry.curve[field] !== head[field])
          throw new ReferenceError(`line ${line}, column ${field}: curve "${head.id}" has ${field} "${entry.curve[field]}" on line ${entry.line}`);
      }
    }
    const number = (name: string, optional: boolean): unknown => {
      const value = cell(name);
      if (value === '') {
        if (optional) return null;
        throw new ReferenceError(`${where(name)}: empty`);
      }
      if (!NUMBER.test(value)) throw new ReferenceError(`${where(name)}: "${value.length > 40 ? `${value.slice(0, 40)}…` : value}" is not a number`);
      return Number(value);
    };
    entry.points.push(
      checkPoint(where, { x: number('x', false), percent: number('percent', false), sd: number('sd', true), n: number('n', true), source: cell('source') }),
    );
  }
  const list: ReferenceCurve[] = [...curves.values()].map(({ curve, points }) => ({ ...curve, fixed: {}, points: orderPoints(`curve "${curve.id}"`, points) }));
  checkDocument(list);
  return { format: REFERENCE_FORMAT, version: REFERENCE_FORMAT_VERSION, title: '', provenance: null, curves: list };
}
