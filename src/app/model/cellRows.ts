/**
 * The per-cell rows shown in the page's table and written to the per-cell CSV: one source, so
 * the file and the screen always agree. Per surface of the stack (basal, layers, apical): the
 * cell's area, its sides and its neighbour ids (space-separated); per cell: valid, scutoid, and
 * the apico-basal transitions (sides and flags from the analysis shown; the neighbour ids are the
 * label images' contacts, all of them, as the result records them). The CSV starts with provenance comment lines ("# ...": the
 * version, the adjacency method, the full configuration as JSON); read it with a CSV reader's
 * comment option (pandas: `comment="#"`, R: `comment.char = "#"`). Text cells are neutralised
 * against formula injection by formatCsv (core/sweep/csv.ts).
 */
import { formatCsv } from '../../core/sweep';
import { statisticsColumns } from './measuredCsv';
import { methodCaption, type ViewStack } from '../../view/stack';
import { describeHeadline, describeOmitted } from '../../core/analysis/headline';
import { describeEngine } from '../../run/enginePolicy';

interface CellTable {
  header: string[];
  rows: (string | number)[][];
}

function cellTable(stack: ViewStack): CellTable {
  return { header: cellTableHeader(stack), rows: stack.result.cells.map((_, i) => cellRow(stack, i)) };
}

/** The table's column names. */
export function cellTableHeader(stack: ViewStack): string[] {
  const names = stack.surfaces.map((s) => s.name.replace(/\s+/g, '_'));
  return [
    'id',
    'valid',
    'scutoid',
    ...statisticsColumns(names),
    // The result keeps neighbour ids (with contact lengths) from the label images only.
    ...names.map((n) => `label_neighbours_${n}`),
    // Closed surfaces: the site's parameter direction as longitude / latitude.
    ...(stack.closed ? ['longitude_deg', 'latitude_deg'] : ['u_um', 'v_um']),
  ];
}

/** Row `i` of the table (cell i): built one at a time, so the page shows only the rows in view. */
export function cellRow(stack: ViewStack, i: number): (string | number)[] {
  const cell = stack.result.cells[i];
  const stats = stack.analysis?.cells[i];
  return [
    cell.id,
    stack.valid[i],
    stack.scutoid[i],
    ...stack.surfaces.map((s) => s.sides[i]),
    stats?.won ?? '',
    stats?.lost ?? '',
    stats?.transitions ?? '',
    stats?.neighbours3D ?? '',
    ...stack.surfaces.map((s) => round(s.cells[i]?.area ?? Number.NaN, 3)),
    ...stack.surfaces.map((s) => (s.cells[i]?.neighbours ?? []).map((n) => n.id).join(' ')),
    round(cell.surface[0], 3),
    round(cell.surface[1], 3),
  ];
}

/** The engine that ran, in words, with why (not the config's "auto"). */
function engineLine(stack: ViewStack): string {
  const { engine, config } = stack.result;
  return `engine: ${describeEngine(engine)} (engine setting "${config.engine}": ${engine.reason})`;
}

/**
 * Comment lines that say where a file comes from: software, version, the engine that ran, the
 * adjacency method, the headline (mean over realizations with its 95 % CI and n, or one
 * realization, said so) and the configuration.
 */
export function provenanceLines(stack: ViewStack, what: string): string[] {
  const { result } = stack;
  return [
    `${what}, written by ${result.software.name} ${result.software.version}`,
    `scutoid flags, sides and transitions from ${methodCaption(stack.analysis)} (method ${stack.analysis?.method ?? 'none'}); label_neighbours_* columns: ${
      result.adjacency?.method === 'exact' ? 'the neighbours of the exact cells (the exact engine makes no label images)' : 'every contact in the label images'
    }`,
    ...(describeOmitted(result.headline) ? [`methods: ${describeOmitted(result.headline)}`] : []),
    `seed ${result.seed}; config (rerun it to reproduce this file): ${JSON.stringify(result.config)}`,
    engineLine(stack),
    `headline: ${describeHeadline(result.headline)}; the cells in this file are realization 1 (seed ${result.seed})`,
  ];
}

/** PNG tEXt chunks of a picture of `stack`: software, description, version, seed, engine, method, headline, config. */
export function provenanceText(stack: ViewStack, what: string): [string, string][] {
  const { result } = stack;
  return [
    ['Software', `${result.software.name} ${result.software.version}`],
    ['Description', provenanceLines(stack, what).join('\n')],
    ['tissue-sheet:version', result.software.version],
    ['tissue-sheet:seed', String(result.seed)],
    ['tissue-sheet:engine', result.engine.name],
    ['tissue-sheet:method', stack.analysis?.method ?? 'none'],
    ['tissue-sheet:headline', JSON.stringify(result.headline)],
    ['tissue-sheet:config', JSON.stringify(result.config)],
  ];
}

export function cellCsv(stack: ViewStack): string {
  const { header, rows } = cellTable(stack);
  const comments = provenanceLines(stack, 'tissue-sheet per-cell table').map((line) => `# ${line}\r\n`);
  return comments.join('') + formatCsv(header, rows);
}

function round(value: number, digits: number): number {
  const f = 10 ** digits;
  return Math.round(value * f) / f;
}
