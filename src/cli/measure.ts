/**
 * `tissue-sheet measure LAYER_FILE... --out RESULT.json [--pixel-size µm] [--periodic-x]
 * [--min-contact µm] [--ratio s] [--compare [--realizations N] [--seed N]]` (docs/measure.md),
 * or `tissue-sheet measure --volume VOLUME.tif --out RESULT.json [--voxel-size X,Y,Z]
 * [--apical lumen|outside] [--lumen-label N] [--min-contact µm] [--quartet-filter]`.
 *
 * Returns the exit code: 0 done, 2 bad input (one line `tissue-sheet: FILE: problem`), 3 an output
 * that cannot be written (checked before any work). Other errors are thrown to the caller (exit 1).
 */
import { totalmem } from 'node:os';
import { resolve } from 'node:path';
import {
  compareMeasured,
  compareVolume,
  MeasureInputError,
  measureTissue,
  measureVolume,
  parseVoxelSizeOption,
  type MeasuredResult,
  type VolumeMeasuredResult,
} from '../core/measure';
import { labelFileFromPath } from '../node/labelImages';
import { version } from '../version';
import { scutoidsText, summaryNumber } from '../core/analysis/summaryText';
import { errorLine, exitCodeFor } from './errors';
import { checkOutFile, writeFileAtomic } from './output';

const FORM =
  'measure LAYER_FILE... --out RESULT.json [--pixel-size µm] [--periodic-x] [--min-contact µm] [--compare] [--force], ' +
  'or measure --volume VOLUME.tif --out RESULT.json [--voxel-size X,Y,Z] [--apical lumen|outside] [--lumen-label N] [--min-contact µm] [--quartet-filter] [--compare [--realizations N] [--seed N]] [--force]';

/** Results with more cells than this are written without indentation. */
export const PRETTY_CELLS = 5000;

interface MeasureArgs {
  files: string[];
  out: string;
  pixelSize?: number;
  periodicX: boolean;
  minContact?: number;
  ratio?: number;
  compare: boolean;
  force: boolean;
  realizations: number;
  seed: number;
  /** --volume: one 3D label TIFF of a curved sheet. */
  volume?: string;
  voxelSize?: { x: number; y: number; z: number };
  apical?: 'lumen' | 'outside';
  lumenLabel?: number;
  quartetFilter: boolean;
}

/** A problem with the command line itself: reported like a file problem, naming the option. */
function optionError(option: string, problem: string): MeasureInputError {
  return new MeasureInputError(option, `${problem}; usage: tissue-sheet ${FORM}`);
}

/** A decimal number (`0.5`, `2e-3`; not `0x10`, `Infinity` or an empty text). */
const DECIMAL = /^[+]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

function positiveNumber(option: string, text: string | undefined, allowZero = false): number {
  const value = Number(text);
  if (text === undefined || !DECIMAL.test(text.trim()) || !Number.isFinite(value) || value < 0 || (!allowZero && value === 0)) {
    throw optionError(option, `needs a number ${allowZero ? '>= 0' : '> 0'} (got ${text === undefined ? 'nothing' : JSON.stringify(text)})`);
  }
  return value;
}

function integer(option: string, text: string | undefined, min: number, max: number): number {
  const value = text !== undefined && /^\d{1,15}$/.test(text) ? Number(text) : Number.NaN;
  if (!Number.isInteger(value) || value < min || value > max) throw optionError(option, `needs an integer ${min}..${max} (got ${text ?? 'nothing'})`);
  return value;
}

export function parseMeasureArgs(args: string[]): MeasureArgs {
  const parsed: MeasureArgs = { files: [], out: '', periodicX: false, compare: false, force: false, realizations: 10, seed: 1, quartetFilter: false };
  const layersOnly: string[] = [];
  const volumeOnly: string[] = [];
  const compareOnly: string[] = [];
  for (let i = 0; i < args.length; i++) {
    const arg = args[i];
    const eq = arg.startsWith('--') ? arg.indexOf('=') : -1;
    const name = eq > 0 ? arg.slice(0, eq) : arg;
    const value = () => (eq > 0 ? arg.slice(eq + 1) : args[++i]);
    // A flag is on when given: `--compare=false` must not mean "on".
    if (eq > 0 && ['--quartet-filter', '--quartets', '--periodic-x', '--compare', '--force'].includes(name)) {
      throw optionError(name, `takes no value (got ${JSON.stringify(arg)}): give ${name} to turn it on, leave it out to keep it off`);
    }
    // Given twice, the second would silently win.
    if (name === '--volume' && parsed.volume !== undefined) throw optionError(name, 'given twice; measure one volume at a time');
    if (name === '--out' || name === '-o') parsed.out = value() ?? '';
    else if (name === '--volume') parsed.volume = value() ?? '';
    else if (name === '--voxel-size') {
      const text = value();
      const size = text === undefined ? null : parseVoxelSizeOption(text);
      if (!size) throw optionError(name, `needs three numbers > 0 in µm, X,Y,Z (got ${text === undefined ? 'nothing' : JSON.stringify(text)})`);
      parsed.voxelSize = size;
      volumeOnly.push(name);
    } else if (name === '--apical') {
      const side = value();
      if (side !== 'lumen' && side !== 'outside')
        throw optionError(name, `needs lumen or outside (got ${side === undefined ? 'nothing' : JSON.stringify(side)})`);
      parsed.apical = side;
      volumeOnly.push(name);
    } else if (name === '--lumen-label') {
      parsed.lumenLabel = integer(name, value(), 1, 2 ** 32 - 1);
      volumeOnly.push(name);
    } else if (name === '--quartet-filter' || name === '--quartets') {
      parsed.quartetFilter = true;
      volumeOnly.push(name);
    } else if (name === '--pixel-size') {
      parsed.pixelSize = positiveNumber(name, value());
      layersOnly.push(name);
    } else if (name === '--min-contact') parsed.minContact = positiveNumber(name, value(), true);
    else if (name === '--ratio') {
      parsed.ratio = positiveNumber(name, value());
      layersOnly.push(name);
    } else if (name === '--realizations') {
      parsed.realizations = integer(name, value(), 1, 1000);
      compareOnly.push(name);
    } else if (name === '--seed') {
      parsed.seed = integer(name, value(), 0, 2 ** 31 - 1);
      compareOnly.push(name);
    } else if (name === '--periodic-x') {
      parsed.periodicX = true;
      layersOnly.push(name);
    } else if (name === '--compare') parsed.compare = true;
    else if (name === '--force') parsed.force = true;
    else if (arg.startsWith('-')) throw optionError(arg, 'unknown option');
    else parsed.files.push(arg);
  }
  if (compareOnly.length > 0 && !parsed.compare) throw optionError(compareOnly[0], 'is for --compare (the model realizations); add --compare or leave it out');
  if (parsed.volume !== undefined) {
    if (!parsed.volume) throw optionError('--volume', 'needs a file: one 3D label TIFF');
    if (parsed.files.length > 0) throw optionError(parsed.files[0], 'with --volume, give no layer files');
    if (layersOnly.length > 0) throw optionError(layersOnly[0], 'is for layer images, not --volume (a volume uses --voxel-size X,Y,Z)');
  } else {
    if (volumeOnly.length > 0) throw optionError(volumeOnly[0], 'is for --volume VOLUME.tif only');
    if (parsed.files.length === 0) throw optionError('LAYER_FILE', 'missing: give one 3D TIFF or two or more 2D label images (or --volume VOLUME.tif)');
  }
  if (!parsed.out) throw optionError('--out', 'missing');
  const out = resolve(parsed.out);
  const clash = [...parsed.files, ...(parsed.volume ? [parsed.volume] : [])].find((f) => resolve(f) === out);
  if (clash) throw new MeasureInputError(clash, 'is also --out; write the result to another file');
  // Before any work: a result that cannot be written is found now, not after the measurement.
  checkOutFile(parsed.out, [], parsed.force);
  return parsed;
}

export async function measureCommand(args: string[], log: (line: string) => void = (l) => process.stderr.write(l + '\n')): Promise<number> {
  try {
    const a = parseMeasureArgs(args);
    if (a.volume !== undefined) return volumeCommand(a, a.volume, log);
    let result: MeasuredResult = measureTissue(a.files.map(labelFileFromPath), {
      pixelSize: a.pixelSize,
      periodicX: a.periodicX,
      minContact: a.minContact,
      surfaceRatio: a.ratio,
      version,
      onProgress: log,
    });
    for (const w of result.warnings) log(`warning: ${w}`);
    if (a.compare) result = withComparison(result, a, log);
    // Pretty-printed like a simulated result, except for large tissues, where the indentation
    // would double the file and the memory needed to write it.
    writeFileAtomic(a.out, JSON.stringify(result, null, result.cells.length > PRETTY_CELLS ? undefined : 2) + '\n');
    const s = result.analyses[0].summary;
    log(
      `done: ${s.cells} cells, ${s.validCells} valid, ${scutoidsText(s.percentScutoids)} over ${s.surfaces} layers, ` +
        `min contact ${result.analyses[0].minContactLength.toPrecision(3)} µm, ${result.timings.totalMs.toFixed(0)} ms -> ${a.out}`,
    );
    return 0;
  } catch (error) {
    // Bad input (2) and an output that cannot be written (3) end here with one line; anything
    // else is a bug, for the caller (exit 1).
    const code = error instanceof MeasureInputError ? 2 : exitCodeFor(error);
    if (code === 2 || code === 3) {
      console.error(`tissue-sheet: ${errorLine(error)}`);
      return code;
    }
    throw error;
  }
}

function volumeCommand(a: MeasureArgs, volume: string, log: (line: string) => void): number {
  let meshes: Parameters<typeof compareVolume>[2];
  let result: VolumeMeasuredResult = measureVolume(labelFileFromPath(volume), {
    voxelSize: a.voxelSize,
    apical: a.apical,
    lumenLabel: a.lumenLabel,
    minContact: a.minContact,
    quartetFilter: a.quartetFilter,
    memory: { maxBytes: totalmem() / 2, why: 'allowed on this machine (half its memory)' },
    version,
    onProgress: log,
    // A closed shell's model runs on its own surfaces: keep them as meshes.
    onSurfaceMeshes: a.compare ? (m) => (meshes = m) : undefined,
  });
  for (const w of result.warnings) log(`warning: ${w}`);
  if (a.compare) {
    const { comparison, note } = compareVolume(result, { realizations: a.realizations, seed: a.seed, onProgress: log }, meshes);
    if (!comparison) {
      log(`warning: ${note}`);
      result = { ...result, warnings: [...result.warnings, note] };
    } else {
      const m = comparison.model.percentScutoids;
      const g = comparison.geometry;
      const shape =
        g.kind === 'tube'
          ? `tube of radius ${g.innerRadius.toFixed(1)} to ${g.outerRadius.toFixed(1)} µm, ${g.length.toFixed(1)} µm long`
          : `the shell's own surfaces (${g.seeded.triangles} and ${g.other.triangles} triangles)`;
      log(
        `model: ${shape}; Voronoi ${comparison.bestK} matches best ` +
          `(L1 ${comparison.candidates[comparison.bestK - 1].distance.toFixed(3)}); it gives ${m.mean.toFixed(1)} % scutoids ` +
          `(95 % CI ${m.ci95[0].toFixed(1)} to ${m.ci95[1].toFixed(1)}; measured ${summaryNumber(comparison.measured.percentScutoids, 1)} %)`,
      );
      result = { ...result, comparison };
    }
  }
  writeFileAtomic(a.out, JSON.stringify(result, null, result.cells.length > PRETTY_CELLS ? undefined : 2) + '\n');
  const s = result.analyses[0].summary;
  const [basal, apical] = result.inputs.layers;
  log(
    `done: ${s.cells} cells, ${s.validCells} valid, ${scutoidsText(s.percentScutoids)}, ` +
      `min contact ${basal.minContact.toPrecision(3)} µm basal, ${apical.minContact.toPrecision(3)} µm apical, ${result.timings.totalMs.toFixed(0)} ms -> ${a.out}`,
  );
  return 0;
}

function withComparison(result: MeasuredResult, a: MeasureArgs, log: (line: string) => void): MeasuredResult {
  const { comparison, note } = compareMeasured(result, { realizations: a.realizations, seed: a.seed, onProgress: log });
  if (!comparison) {
    log(`warning: ${note}`);
    return { ...result, warnings: [...result.warnings, note] };
  }
  log(
    `model: Voronoi ${comparison.bestK} matches best (L1 ${comparison.candidates[comparison.bestK - 1].distance.toFixed(3)}); ` +
      `at ratio ${comparison.surfaceRatio.toFixed(3)} it gives ${comparison.meanPercentScutoids.toFixed(1)} ± ${comparison.sdPercentScutoids.toFixed(1)} % scutoids ` +
      `(measured ${summaryNumber(result.analyses[0].summary.percentScutoids, 1)} %)`,
  );
  return { ...result, comparison };
}
