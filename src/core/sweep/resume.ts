/**
 * Resuming a sweep from the runs file it already wrote, without trusting it.
 *
 * The header must equal the one this spec produces (else ResumeError: the file belongs to
 * another spec or version). Every record is then checked and rejected, with its line and the
 * reason, when:
 * - it has another number of fields than the header (hand-edited, or a cut-off write),
 * - its key is not a run of this spec, or repeats a key already accepted (kept: the first),
 * - its realization, seed or varied values differ from that run's,
 * - a column the run fills is empty or not a number (text columns excepted), or a column it
 *   does not fill is not empty.
 * An incomplete last record (an interrupted write) is rejected too. Rejected runs are simply
 * not done: the sweep recomputes them. `rewrite` says the file must be rewritten with the
 * accepted rows only (`cleanText`), so that it never holds two rows for a key.
 */
import { formatCsvRow, parseCsv } from './csv';
import type { ConfigObject, SweepRun } from './expand';
import { valueText } from './expand';
import { fileHeader } from './units';

export class ResumeError extends Error {
  override name = 'ResumeError';
}

export interface RejectedRow {
  /** 1-based line of the record in the file. */
  line: number;
  reason: string;
  /** The record's raw text (to keep it aside). */
  text: string;
}

export interface ResumePlan {
  /** Accepted rows, one per key, in file order. */
  rows: Record<string, string>[];
  rejected: RejectedRow[];
  /** True when the file must be replaced by `cleanText`. */
  rewrite: boolean;
  /** Header + accepted rows. */
  cleanText: string;
}

export interface ResumeSpec<C extends ConfigObject> {
  header: readonly string[];
  fields: readonly string[];
  runs: readonly SweepRun<C>[];
  /** Summary columns a run fills (the others must be empty). */
  filledColumns: (run: SweepRun<C>) => ReadonlySet<string>;
  textColumns: ReadonlySet<string>;
  /**
   * The base configuration's values a run's row carries (runs.csv's geometry columns, units.ts):
   * a row of another configuration under the same key and varied values (cells 50 where this
   * spec has 60) is set aside, not mixed with this spec's rows.
   */
  pointValues?: (run: SweepRun<C>) => Readonly<Record<string, string | number | boolean>>;
}

const isNumberText = (cell: string): boolean => cell === 'NaN' || (cell.trim() === cell && cell !== '' && !Number.isNaN(Number(cell)));

export function planResume<C extends ConfigObject>(text: string, spec: ResumeSpec<C>, fileName = 'runs.csv'): ResumePlan {
  // The file's header carries units (units.ts); rows keep the plain names of spec.header.
  const written = fileHeader(spec.header);
  const headerText = formatCsvRow(written);
  if (text === '') return { rows: [], rejected: [], rewrite: true, cleanText: headerText };
  const parsed = parseCsv(text);
  const [header, ...records] = parsed.records;
  if (!header || header.length !== written.length || header.some((h, k) => h !== written[k])) {
    const move = `give a new --out directory, or move ${fileName} away to start over`;
    // Before units and the geometry columns a header had no unit suffix at all (this version's
    // always has finalEnergy_um4).
    if (header && header[0] === 'key' && header.includes('finalEnergy')) {
      throw new ResumeError(
        `${fileName}: written by an older tissue-sheet (its header has no units, base geometry or scutoid counts), so its rows cannot be mixed with this version's; ${move}`,
      );
    }
    const k = header ? written.findIndex((h, i) => header[i] !== h) : 0;
    const detail = !header
      ? 'it has no complete header line'
      : k === -1
        ? `it has ${header.length} columns, this spec writes ${written.length}`
        : `column ${k + 1} is ${JSON.stringify(header[k] ?? '')}, this spec writes ${JSON.stringify(written[k])}`;
    throw new ResumeError(`${fileName}: written for another spec or version (${detail}); ${move}`);
  }
  const byKey = new Map(spec.runs.map((r) => [r.key, r]));
  const firstLine = new Map<string, number>();
  const rows: Record<string, string>[] = [];
  const rejected: RejectedRow[] = [];
  records.forEach((record, k) => {
    const index = k + 1;
    const line = parsed.lines[index];
    const raw = text.slice(parsed.offsets[index], parsed.offsets[index + 1] ?? parsed.validLength);
    const reason = checkRecord(record, spec, byKey, firstLine);
    if (reason) {
      rejected.push({ line, reason, text: raw });
      return;
    }
    const row: Record<string, string> = {};
    spec.header.forEach((h, i) => (row[h] = record[i]));
    firstLine.set(row.key, line);
    rows.push(row);
  });
  if (parsed.truncated) {
    const line = countLines(text.slice(0, parsed.validLength)) + 1;
    rejected.push({ line, reason: 'incomplete last line (an interrupted write)', text: text.slice(parsed.validLength) });
  }
  const cleanText = headerText + rows.map((r) => formatCsvRow(spec.header.map((h) => r[h]))).join('');
  return { rows, rejected, rewrite: rejected.length > 0, cleanText };
}

function countLines(text: string): number {
  let n = 0;
  for (const ch of text) if (ch === '\n') n++;
  return n;
}

function checkRecord<C extends ConfigObject>(
  record: string[],
  spec: ResumeSpec<C>,
  byKey: Map<string, SweepRun<C>>,
  firstLine: Map<string, number>,
): string | undefined {
  if (record.length !== spec.header.length) return `${record.length} fields where the header has ${spec.header.length}`;
  const cell = (name: string) => record[spec.header.indexOf(name)];
  const key = cell('key');
  const run = byKey.get(key);
  if (!run) return `key ${JSON.stringify(key.length > 80 ? `${key.slice(0, 77)}...` : key)} is not a run of this spec`;
  const seen = firstLine.get(key);
  if (seen !== undefined) return `duplicate of line ${seen} (key ${key})`;
  if (cell('realization') !== String(run.realization))
    return `realization ${JSON.stringify(cell('realization'))} but run ${key} is realization ${run.realization}`;
  if (cell('seed') !== String(run.seed)) return `seed ${JSON.stringify(cell('seed'))} but run ${key} has seed ${run.seed}`;
  for (const f of spec.fields) {
    if (cell(f) !== valueText(run.point[f])) return `${f} is ${JSON.stringify(cell(f))} but run ${key} has ${valueText(run.point[f])}`;
  }
  const expected = spec.pointValues?.(run);
  if (expected) {
    for (const name in expected) {
      const at = spec.header.indexOf(name);
      // The row's text as runCells wrote it: String() of the value.
      if (at >= 0 && record[at] !== String(expected[name])) {
        return `${name} is ${JSON.stringify(record[at])} but run ${key} of this spec has ${String(expected[name])} (a row of another configuration)`;
      }
    }
  }
  const filled = spec.filledColumns(run);
  const fixed = new Set(['key', 'realization', 'seed', ...spec.fields]);
  // Columns of one adjacency method ("labels.*", "exact.*") are filled all or none: which
  // methods a run reports can depend on the engine that ran it.
  const groups = new Map<string, { filled: number; empty: number; first: string }>();
  for (let i = 0; i < spec.header.length; i++) {
    const name = spec.header[i];
    if (fixed.has(name)) continue;
    const value = record[i];
    const group = /^(labels|exact)\./.exec(name)?.[1];
    if (!filled.has(name)) {
      if (value !== '') return `${name} should be empty for this run (got ${JSON.stringify(value)})`;
      continue;
    }
    if (group) {
      const g = groups.get(group) ?? { filled: 0, empty: 0, first: name };
      groups.set(group, g);
      if (value === '') {
        g.empty++;
        continue;
      }
      g.filled++;
    } else if (value === '') {
      return `${name} is empty`;
    }
    if (!spec.textColumns.has(name) && !isNumberText(value)) {
      return `${name}: ${JSON.stringify(value.length > 40 ? `${value.slice(0, 37)}...` : value)} is not a number`;
    }
  }
  for (const [method, g] of groups) {
    if (g.filled > 0 && g.empty > 0) return `${method}.* columns are partly empty (${g.empty} of ${g.filled + g.empty})`;
  }
  if (groups.size > 0 && [...groups.values()].every((g) => g.filled === 0)) return 'no adjacency method has values';
  return undefined;
}
