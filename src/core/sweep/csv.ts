/**
 * Tidy CSV for sweeps (RFC 4180).
 *
 * - Fields are quoted when they contain a comma, a double quote, CR or LF, or start or end with
 *   a space; quotes inside are doubled. Records end with CRLF (the last one too, so appending a
 *   row never needs to look at the previous one).
 * - Cells: null/undefined -> empty; numbers -> String(n) (NaN -> "NaN", Infinity -> "Infinity");
 *   booleans -> "true"/"false"; objects -> JSON.
 * - Formula injection (OWASP "CSV injection"): a text cell starting with =, +, -, @, tab or CR
 *   would open as a formula in a spreadsheet, so it is written with a leading apostrophe
 *   ("'=cmd"); a text cell that already starts with an apostrophe followed by one of those gets
 *   one more, so reading (`parseCsv` removes exactly one) gives back the original text. Numbers,
 *   and text that is a plain decimal number ("-3", "1e-5"), are never altered.
 * - `parseCsv` accepts CRLF or LF, quoted fields with embedded separators, quotes and newlines,
 *   and reports where each record starts (offset and line) so a bad one can be named.
 * - `readCsvTable` reads a header + rows, and reports a truncated tail: text after the last
 *   record terminator is an incomplete record (a write was interrupted); it is not returned as a
 *   row, and `validLength` is the length of the text up to the last complete record. Records
 *   whose field count differs from the header's are dropped and counted in `malformed`.
 * - `flattenSummary` turns a nested summary into columns: nested object keys and array indices
 *   joined with ".", e.g. `perSurface.0.polygonDistribution.3`.
 */

const FORMULA_START = /^'*[=+\-@\t\r]/;
const PLAIN_NUMBER = /^[-+]?(\d+\.?\d*|\.\d+)([eE][-+]?\d+)?$/;

/** A text cell made safe to open in a spreadsheet (see the module comment). */
function neutralizeFormula(text: string): string {
  return FORMULA_START.test(text) && !PLAIN_NUMBER.test(text) ? `'${text}` : text;
}

/** The inverse of neutralizeFormula, applied to every cell read. */
function restoreFormula(text: string): string {
  return text.startsWith("'") && FORMULA_START.test(text) && !PLAIN_NUMBER.test(text.slice(1)) ? text.slice(1) : text;
}

export function csvField(value: unknown): string {
  if (value === null || value === undefined) return '';
  // The text of a number or boolean has no quote, comma, line break or edge space: as it is.
  if (typeof value === 'number' || typeof value === 'boolean' || typeof value === 'bigint') return String(value);
  const text = typeof value === 'string' ? neutralizeFormula(value) : JSON.stringify(value);
  if (/[",\r\n]/.test(text) || /^\s|\s$/.test(text)) return `"${text.replace(/"/g, '""')}"`;
  return text;
}

/** One CSV record including its CRLF terminator. */
export function formatCsvRow(fields: readonly unknown[]): string {
  return `${fields.map(csvField).join(',')}\r\n`;
}

export function formatCsv(header: readonly string[], rows: readonly (readonly unknown[])[]): string {
  return formatCsvRow(header) + rows.map(formatCsvRow).join('');
}

export interface ParsedCsv {
  /** Complete records. */
  records: string[][];
  /** Offset in the text where each record starts. */
  offsets: number[];
  /** 1-based line number where each record starts. */
  lines: number[];
  /** Length of the text up to the end of the last complete record. */
  validLength: number;
  /** True when text follows the last record terminator (an incomplete record). */
  truncated: boolean;
}

/** RFC 4180 parser (CRLF or LF). An unterminated last record is reported, not returned. */
export function parseCsv(text: string): ParsedCsv {
  const records: string[][] = [];
  const offsets: number[] = [0];
  const lines: number[] = [1];
  let line = 1;
  let field = '';
  let record: string[] = [];
  let inQuotes = false;
  let validLength = 0;
  let i = 0;
  const endField = () => {
    record.push(restoreFormula(field));
    field = '';
  };
  const endRecord = (next: number) => {
    endField();
    records.push(record);
    record = [];
    i = next;
    validLength = i;
    line++;
    offsets.push(i);
    lines.push(line);
  };
  while (i < text.length) {
    const ch = text[i];
    if (inQuotes) {
      if (ch === '\n') line++;
      if (ch === '"') {
        if (text[i + 1] === '"') {
          field += '"';
          i += 2;
          continue;
        }
        inQuotes = false;
        i++;
        continue;
      }
      field += ch;
      i++;
      continue;
    }
    if (ch === '"' && field === '') {
      inQuotes = true;
      i++;
    } else if (ch === ',') {
      endField();
      i++;
    } else if (ch === '\r' && text[i + 1] === '\n') {
      endRecord(i + 2);
    } else if (ch === '\n') {
      endRecord(i + 1);
    } else {
      field += ch;
      i++;
    }
  }
  offsets.length = records.length;
  lines.length = records.length;
  return { records, offsets, lines, validLength, truncated: validLength < text.length };
}

export interface CsvTable {
  header: string[];
  rows: Record<string, string>[];
  validLength: number;
  truncated: boolean;
  malformed: number;
}

/** Header + rows as objects (see the module comment). Empty text gives an empty table. */
export function readCsvTable(text: string): CsvTable {
  const parsed = parseCsv(text);
  if (parsed.records.length === 0) return { header: [], rows: [], validLength: 0, truncated: parsed.truncated, malformed: 0 };
  const [header, ...records] = parsed.records;
  const rows: Record<string, string>[] = [];
  let malformed = 0;
  for (const rec of records) {
    if (rec.length !== header.length) {
      malformed++;
      continue;
    }
    const row: Record<string, string> = {};
    header.forEach((h, k) => (row[h] = rec[k]));
    rows.push(row);
  }
  return { header, rows, validLength: parsed.validLength, truncated: parsed.truncated, malformed };
}

/** Nested object/array -> flat column map (keys joined with "."). Typed arrays count as arrays. */
export function flattenSummary(value: unknown, prefix = '', out: Record<string, unknown> = {}): Record<string, unknown> {
  if (value !== null && typeof value === 'object') {
    const entries: [string, unknown][] =
      ArrayBuffer.isView(value) && !(value instanceof DataView)
        ? Array.from(value as ArrayBufferView & ArrayLike<unknown>, (v, k) => [String(k), v])
        : Array.isArray(value)
          ? value.map((v, k) => [String(k), v])
          : Object.entries(value as Record<string, unknown>);
    if (entries.length === 0 && prefix) out[prefix] = '';
    for (const [k, v] of entries) flattenSummary(v, prefix ? `${prefix}.${k}` : k, out);
    return out;
  }
  if (prefix) out[prefix] = value;
  return out;
}
