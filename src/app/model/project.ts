/**
 * Project files and result files opened in the page.
 *
 * A project (`.tissue-sheet.json`) holds what the screen shows: the result (the CLI's document),
 * every label image the views draw (run-length encoded; closed surfaces also their geometry
 * image), and the view state (camera, visible surfaces, cut, scutoid highlight, picked cell, its solid). Opening
 * it draws exactly that, without running anything.
 *
 * A result JSON written by the CLI (`tissue-sheet run`) has no label images. On planes and tubes
 * the views are drawn from the file's own cells: each surface's label image is the exact Voronoi
 * diagram of the file's sites on it, rasterized (what the exact engine's views show; a GPU run's
 * label images differ from it by texels at cell borders, the statistics shown are the file's).
 * Closed surfaces cannot be drawn from the cells alone: the caller re-runs `result.config`
 * (the seed makes it reproduce the result) and says so.
 *
 * Files are untrusted input: sizes are checked before allocating, label ids against the cells,
 * and the configuration through the schema; every refusal is one line naming the field.
 */
import { validateConfig } from '../../core/config';
import { exactLabelImage } from '../../view/exactLabels';
import type { Grid } from '../../core/grid';
import type { LabelImage, SheetOutput, SheetResult } from '../../run';
import { fromBase64, toBase64 } from './base64';
import { savedSections } from './projectSections';

const PROJECT_FORMAT = 'tissue-sheet-project';
const PROJECT_FORMAT_VERSION = 1;
/** Largest label image a file may bring, texels (the page's own runs stay far below). */
const MAX_TEXELS = 1 << 24;
/** Largest stack of grids a result may bring, texels in all (its label images are drawn from them). */
const MAX_STACK_TEXELS = 1 << 26;

export interface ViewState {
  camera: { position: [number, number, number]; target: [number, number, number] } | null;
  /** Visibility per surface of the stack. */
  visible: boolean[];
  cut: number;
  highlightScutoids: boolean;
  /** The picked cell, or null. */
  selectedCell: number | null;
  /** The picked cell drawn as a 3D solid (absent in older files: off). */
  cellSolid?: boolean;
}

interface StoredImage {
  name: string;
  grid: Grid;
  /** Int32 pairs (label, run length) over the row-major labels, base64. */
  labelsRle: string;
  /** Float32 x, y, z per texel, base64 (closed surfaces). */
  positions?: string;
}

interface ProjectFile {
  format: typeof PROJECT_FORMAT;
  formatVersion: number;
  software: SheetResult['software'];
  savedAt: string;
  result: SheetResult;
  labelImages: StoredImage[];
  view: ViewState;
  /** Other parts of the page (projectSections.ts), e.g. `measured`: the measured tissue. */
  sections?: Record<string, unknown>;
}

/**
 * The project file of `output` as the page shows it; `sections` and `savedAt` are the page's
 * (given by a worker that builds the file: model/exportFiles.ts).
 */
export function projectJson(
  output: SheetOutput,
  view: ViewState,
  sections: Record<string, unknown> | undefined = savedSections(),
  savedAt = new Date().toISOString(),
): string {
  const file: ProjectFile = {
    format: PROJECT_FORMAT,
    formatVersion: PROJECT_FORMAT_VERSION,
    software: output.result.software,
    savedAt,
    result: output.result,
    labelImages: output.labelImages.map((image) => ({
      name: image.name,
      grid: { ...image.grid },
      labelsRle: toBase64(new Uint8Array(runLengths(image.labels).buffer)),
      ...(image.positions ? { positions: toBase64(new Uint8Array(image.positions.buffer, image.positions.byteOffset, image.positions.byteLength)) } : {}),
    })),
    view,
    sections,
  };
  return JSON.stringify(file);
}

export type OpenedFile =
  | { kind: 'project'; output: SheetOutput; view: ViewState; sections?: unknown }
  | { kind: 'result'; output: SheetOutput; drawnFrom: 'cells' }
  | { kind: 'result-rerun'; result: SheetResult };

/** The JSON of an opened file, or a one-line refusal naming it. */
export function parseFileJson(text: string, name: string): unknown {
  try {
    return JSON.parse(text) as unknown;
  } catch {
    throw new Error(`${name}: not JSON; open a project file (.tissue-sheet.json) or a result JSON written by tissue-sheet run.`);
  }
}

/**
 * A project file or a CLI result JSON, parsed (parseFileJson; a result whose cells came from its
 * side file: model/resultFiles.ts), checked; `name` is used in messages.
 */
export function openParsed(data: unknown, name: string): OpenedFile {
  if (!isObject(data)) throw new Error(`${name}: not a tissue-sheet file (a JSON object was expected).`);
  if (data.format === PROJECT_FORMAT) {
    if (data.formatVersion !== PROJECT_FORMAT_VERSION)
      throw new Error(`${name}: formatVersion ${String(data.formatVersion)}: this page reads project files of version ${PROJECT_FORMAT_VERSION}.`);
    const result = checkResult(data.result, `${name}: result`);
    if (!Array.isArray(data.labelImages) || data.labelImages.length !== result.surfaces.length + 1) {
      throw new Error(`${name}: labelImages: expected ${result.surfaces.length + 1} images, one per surface of the result.`);
    }
    const labelImages = data.labelImages.map((image, k) => readImage(image, result.cells.length, `${name}: labelImages[${k}]`));
    return { kind: 'project', output: { result, labelImages }, view: readView(data.view, labelImages.length, `${name}: view`), sections: data.sections };
  }
  const result = checkResult(data, name);
  if (result.closed !== undefined) return { kind: 'result-rerun', result };
  return { kind: 'result', output: { result, labelImages: labelsFromCells(result) }, drawnFrom: 'cells' };
}

/** Label images of a plane's or tube's result drawn from its cells (exact cells, rasterized). */
function labelsFromCells(result: SheetResult): LabelImage[] {
  const last = result.surfaces[result.surfaces.length - 1];
  const seededName = last?.name === 'apical' ? 'basal' : 'apical';
  const surfaces = [{ name: seededName, grid: result.grid, cells: result.cells }, ...result.surfaces];
  return surfaces.map((surface) => {
    const grid = { ...surface.grid };
    const sites = new Float64Array(result.cells.length * 2);
    surface.cells.forEach((cell, i) => {
      sites[2 * i] = cell.surface[0] / grid.texelX;
      sites[2 * i + 1] = cell.surface[1] / grid.texelY;
    });
    return { name: surface.name, grid, labels: exactLabelImage(grid, sites) };
  });
}

function checkResult(value: unknown, where: string): SheetResult {
  if (!isObject(value) || !isObject(value.software) || value.software.name !== 'tissue-sheet') {
    throw new Error(`${where}: software.name is not "tissue-sheet": not a result written by tissue-sheet.`);
  }
  try {
    validateConfig(value.config);
  } catch (error) {
    throw new Error(`${where}: config: ${(error as Error).message}`);
  }
  if (!Array.isArray(value.cells) || value.cells.length === 0) throw new Error(`${where}: cells: expected the list of cells.`);
  if (!Array.isArray(value.surfaces) || value.surfaces.length === 0)
    throw new Error(`${where}: surfaces: expected the list of the stack's other surfaces (at least one).`);
  if (!Array.isArray(value.analyses) || value.analyses.length === 0) throw new Error(`${where}: analyses: expected the list of analyses (at least one).`);
  const n = value.cells.length;
  // Every grid is sized before anything is allocated from it (label images, pictures, textures).
  checkGrid(value.grid, `${where}: grid`);
  let texels = (value.grid as Grid).width * (value.grid as Grid).height;
  value.surfaces.forEach((surface, k) => {
    if (!isObject(surface) || !Array.isArray(surface.cells) || surface.cells.length !== n || !isObject(surface.grid)) {
      throw new Error(`${where}: surfaces[${k}]: expected a grid and ${n} cells.`);
    }
    const grid = checkGrid(surface.grid, `${where}: surfaces[${k}].grid`);
    texels += grid.width * grid.height;
    if (texels > MAX_STACK_TEXELS) throw new Error(`${where}: surfaces[${k}].grid: the grids of the stack exceed ${MAX_STACK_TEXELS} texels in all.`);
  });
  checkCells(value.cells, n, `${where}: cells`);
  value.surfaces.forEach((surface, k) => checkCells((surface as { cells: unknown[] }).cells, n, `${where}: surfaces[${k}].cells`));
  value.analyses.forEach((analysis, k) => checkAnalysis(analysis, n, `${where}: analyses[${k}]`));
  if (value.headline !== undefined && value.headline !== null && !isObject(value.headline))
    throw new Error(`${where}: headline: expected the headline record or null.`);
  // Checked above field by field: the shape of a SheetResult.
  return value as typeof value & SheetResult;
}

/**
 * Each cell i of a surface: id i, a surface position [u, v] of numbers, and neighbours that are
 * cells of the result (an id out of range would be read as a cell by the views and the picked
 * cell's panel).
 */
function checkCells(cells: unknown[], n: number, where: string): void {
  cells.forEach((cell, i) => {
    if (!isObject(cell) || cell.id !== i || !Array.isArray(cell.surface) || !Array.isArray(cell.neighbours))
      throw new Error(`${where}[${i}]: expected id ${i}, surface [u, v] and neighbours.`);
    if (cell.surface.length !== 2 || !cell.surface.every((x) => typeof x === 'number' && Number.isFinite(x)))
      throw new Error(`${where}[${i}].surface: expected [u, v], two finite numbers.`);
    cell.neighbours.forEach((neighbour, k) => {
      const id = isObject(neighbour) ? neighbour.id : undefined;
      if (!(Number.isInteger(id) && (id as number) >= 0 && (id as number) < n))
        throw new Error(`${where}[${i}].neighbours[${k}]: id ${String(id)} is not a cell of the ${n}.`);
    });
  });
}

/** The fields of an analysis's summary the page reads (a saved NaN is null). */
const SUMMARY_NUMBERS = [
  'cells',
  'validCells',
  'excludedCells',
  'surfaces',
  'scutoids',
  'percentScutoids',
  'percentScutoidsEnds',
  'meanTransitions',
  'meanWon',
  'meanLost',
  'meanNeighbours3D',
] as const;

/**
 * An analysis as the views, the results panel and the charts read it: its method, a summary
 * with numbers (or null) and one record per surface, and one record per cell with its sides.
 */
function checkAnalysis(value: unknown, n: number, where: string): void {
  if (!isObject(value)) throw new Error(`${where}: expected an analysis (method, summary, cells).`);
  if (value.method !== 'labels' && value.method !== 'exact') throw new Error(`${where}.method: expected "labels" or "exact".`);
  const summary = value.summary;
  if (!isObject(summary)) throw new Error(`${where}.summary: expected the analysis summary (an object).`);
  for (const key of SUMMARY_NUMBERS) {
    if (!(typeof summary[key] === 'number' || summary[key] === null)) throw new Error(`${where}.summary.${key}: expected a number.`);
  }
  if (!Array.isArray(summary.perSurface) || summary.perSurface.length === 0) throw new Error(`${where}.summary.perSurface: expected one record per surface.`);
  const numbers = (v: unknown) => Array.isArray(v) && v.every((x) => typeof x === 'number' || x === null);
  summary.perSurface.forEach((surface, k) => {
    const at = `${where}.summary.perSurface[${k}]`;
    if (!isObject(surface)) throw new Error(`${at}: expected a surface's summary.`);
    if (!(typeof surface.meanSides === 'number' || surface.meanSides === null)) throw new Error(`${at}.meanSides: expected a number.`);
    for (const key of ['polygonDistribution', 'polygonCounts']) if (!numbers(surface[key])) throw new Error(`${at}.${key}: expected a list of numbers.`);
    for (const key of ['lewis', 'aboavWeaire']) if (!Array.isArray(surface[key])) throw new Error(`${at}.${key}: expected a list.`);
  });
  const cells = value.cells;
  if (!Array.isArray(cells) || cells.length !== n) throw new Error(`${where}.cells: expected ${n} cell records, one per cell.`);
  cells.forEach((cell, i) => {
    if (!isObject(cell) || cell.id !== i || typeof cell.valid !== 'boolean' || typeof cell.scutoid !== 'boolean' || !numbers(cell.sides))
      throw new Error(`${where}.cells[${i}]: expected id ${i}, valid, scutoid and sides per surface.`);
  });
}

function checkGrid(value: unknown, where: string): Grid {
  if (!isObject(value)) throw new Error(`${where}: expected a grid.`);
  const { width, height, texelX, texelY, periodicX, periodicY } = value;
  const whole = (x: unknown) => Number.isInteger(x) && (x as number) > 0;
  if (!whole(width) || !whole(height) || (width as number) * (height as number) > MAX_TEXELS) {
    throw new Error(`${where}: width and height: positive integers, at most ${MAX_TEXELS} texels in all.`);
  }
  const positive = (x: unknown) => typeof x === 'number' && Number.isFinite(x) && x > 0;
  if (!positive(texelX) || !positive(texelY) || typeof periodicX !== 'boolean' || typeof periodicY !== 'boolean') {
    throw new Error(`${where}: texelX, texelY (> 0) and periodicX, periodicY (booleans) are required.`);
  }
  return { width, height, texelX, texelY, periodicX, periodicY } as Grid;
}

function readImage(value: unknown, cellCount: number, where: string): LabelImage {
  if (!isObject(value) || typeof value.name !== 'string' || typeof value.labelsRle !== 'string')
    throw new Error(`${where}: expected name, grid and labelsRle.`);
  const grid = checkGrid(value.grid, `${where}.grid`);
  const texels = grid.width * grid.height;
  const runs = new Int32Array(fromBase64Words(value.labelsRle, `${where}.labelsRle`, 8 * texels).buffer);
  const labels = new Int32Array(texels);
  let at = 0;
  for (let k = 0; k + 1 < runs.length; k += 2) {
    const [id, count] = [runs[k], runs[k + 1]];
    if (id < -1 || id >= cellCount || count <= 0 || at + count > texels)
      throw new Error(`${where}.labelsRle: run ${k / 2} (id ${id}, length ${count}) does not fit ${texels} texels of ${cellCount} cells.`);
    labels.fill(id, at, at + count);
    at += count;
  }
  if (at !== texels) throw new Error(`${where}.labelsRle: covers ${at} of ${texels} texels.`);
  if (value.positions === undefined) return { name: value.name, grid, labels };
  const bytes = fromBase64Words(String(value.positions), `${where}.positions`, 12 * texels);
  if (bytes.length !== 12 * texels) throw new Error(`${where}.positions: expected x, y, z for each of ${texels} texels.`);
  return { name: value.name, grid, labels, positions: new Float32Array(bytes.buffer) };
}

function readView(value: unknown, surfaces: number, where: string): ViewState {
  if (!isObject(value)) throw new Error(`${where}: expected the view state.`);
  const vec = (v: unknown) => Array.isArray(v) && v.length === 3 && v.every((x) => Number.isFinite(x));
  const camera =
    isObject(value.camera) && vec(value.camera.position) && vec(value.camera.target)
      ? { position: value.camera.position as [number, number, number], target: value.camera.target as [number, number, number] }
      : null;
  const visible = Array.isArray(value.visible)
    ? Array.from({ length: surfaces }, (_, k) => (value.visible as unknown[])[k] !== false)
    : Array(surfaces).fill(true);
  const cut = Number.isFinite(value.cut) ? Math.max(0, Math.min(1, value.cut as number)) : 0;
  const selected = Number.isInteger(value.selectedCell) ? (value.selectedCell as number) : null;
  return { camera, visible, cut, highlightScutoids: value.highlightScutoids !== false, selectedCell: selected, cellSolid: value.cellSolid === true };
}

/** (label, run length) pairs of `labels`. */
function runLengths(labels: Int32Array): Int32Array {
  const runs: number[] = [];
  for (let i = 0; i < labels.length;) {
    let j = i + 1;
    while (j < labels.length && labels[j] === labels[i]) j++;
    runs.push(labels[i], j - i);
    i = j;
  }
  return Int32Array.from(runs);
}

/** Base64 of 4-byte values, at most `maxBytes` of them, decoded. */
function fromBase64Words(text: string, where: string, maxBytes: number): Uint8Array {
  if (text.length > (maxBytes * 4) / 3 + 4) throw new Error(`${where}: larger than the image it describes.`);
  const bytes = fromBase64(text, where);
  if (bytes.length % 4 !== 0) throw new Error(`${where}: not a whole number of 4-byte values.`);
  return bytes;
}

function isObject(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/** What became of a run the page asked for (main.ts `run`). */
export type RunOutcome =
  | { kind: 'done'; result: SheetResult }
  | { kind: 'refused'; message: string }
  | { kind: 'waiting'; path: string; host: string }
  | { kind: 'cancelled' }
  | { kind: 'failed'; message: string };

/**
 * Says whether a re-run of a closed-surface result's configuration reproduced the file: same
 * number of cells, every site within 1e-3 µm (relative to the sheet) of the file's. Only a run
 * of the file's configuration that finished (`outcome.kind === 'done'`) is compared; otherwise
 * the note says what became of the run (refused, waiting for the user's approval, cancelled,
 * failed), never comparing the file with the result that was on screen before.
 */
export function rerunNote(file: SheetResult, outcome: RunOutcome): string {
  const base = 'a result JSON holds no label images and a closed surface cannot be drawn from its cells, so its configuration';
  const kept = 'the previous result is still shown';
  switch (outcome.kind) {
    case 'refused':
      return `${base} was to be run again, but the run was refused (see the message); nothing was run and ${kept}.`;
    case 'waiting':
      return `${base} will be run again once you allow loading ${outcome.path} from ${outcome.host} (the question above); nothing has run yet.`;
    case 'cancelled':
      return `${base} was being run again, and the run was cancelled; ${kept}.`;
    case 'failed':
      return `${base} was run again, and the run failed (see the message); ${kept}.`;
    case 'done':
      break;
  }
  const ran = `${base} was run again`;
  const a = file.cells;
  const b = outcome.result.cells;
  if (a.length !== b.length) return `${ran}: the run gave ${b.length} cells, the file has ${a.length}; the page shows the run's statistics.`;
  let worst = 0;
  let scale = 0;
  for (let i = 0; i < a.length; i++) {
    for (let k = 0; k < 3; k++) {
      worst = Math.max(worst, Math.abs(a[i].position[k] - b[i].position[k]));
      scale = Math.max(scale, Math.abs(a[i].position[k]));
    }
  }
  const same = worst <= 1e-3 * Math.max(1, scale);
  return same
    ? `${ran}; it reproduced the file's sites (largest difference ${worst.toExponential(2)} µm).`
    : `${ran}; its sites differ from the file's by up to ${worst.toPrecision(3)} µm (another version or engine?): the page shows the run's statistics.`;
}
