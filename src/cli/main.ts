import { parseArgs } from './args';
import { errorLine, EXIT, exitCodeFor, InputError } from './errors';
import { runCommand } from './run';
import { sweepCommand } from './sweep';
import { version } from '../version';

const usage = `tissue-sheet ${version}

Usage:
  tissue-sheet run CONFIG.json --out RESULT.json   compute one sheet (see docs/config.md)
  tissue-sheet sweep SWEEP.json --out DIR          a grid of runs; resumes when rerun (docs/sweep.md)
  tissue-sheet sweep SWEEP.json --out DIR --shard I/N   the I-th of N shares of the grid (or --shard slurm)
  tissue-sheet merge DIR... --out DIR              join shard directories into one sweep directory
  tissue-sheet measure LAYER_FILE... --out RESULT.json   measure segmented layers, basal first (docs/measure.md)
  tissue-sheet measure --volume VOLUME.tif --out RESULT.json [--voxel-size X,Y,Z] [--apical lumen|outside]
                       [--lumen-label N] [--min-contact µm] [--quartet-filter] [--compare]   measure a 3D label volume
  tissue-sheet --version | --help

Options:
  --force           overwrite an existing --out that is not a previous tissue-sheet result
  --allow-network   fetch http(s) mesh and density sources (default: file paths only)
  --allow-large     lift the work and memory limits (GPU texture limits still apply)
  --realizations N  run: the headline is the mean % scutoids over N realizations (seeds
                    seed, seed + 1, ...) with its 95 % CI (default 5; 1: this seed alone);
                    RESULT.json is realization 1's, its headline the mean
  --cells-file      run: per-cell lists in RESULT.cells.bin (columns) instead of the JSON;
                    done anyway above 100,000 cell records (README, "Result JSON")
  --max-runs N      sweep: accept up to N runs (default 100000)
  --shard I/N       sweep: compute only shard I of N (1 <= I <= N); every run is in exactly
                    one shard; "slurm" takes I and N from SLURM_ARRAY_TASK_ID/_MIN/_COUNT
  --workers N       how many threads compute the exact-engine work (default: the machine's
                    cores): sweep's runs, run's realizations; the main thread is one of the
                    N (1: no worker thread); the files are the same whatever N

Progress goes to stderr. Exit codes:
  0    done
  1    unexpected failure (a bug: rerun with TISSUE_SHEET_DEBUG=1 and report it)
  2    bad input: config, sweep spec, mesh, image, runs.csv, shards of different
       specs or versions, or arguments
       (one line naming the field or file and what to change)
  3    environment: no usable GPU context or X display, output directory locked
       by another sweep, an output that cannot be written
  130  interrupted (Ctrl-C); rerun the same sweep to resume`;

type Command = (args: string[], signal: AbortSignal, log: (line: string) => void) => Promise<number | void>;

const commands: Record<string, Command> = {
  run: (args, signal, log) =>
    runCommand(
      parseArgs(args, 'run CONFIG.json --out RESULT.json [--realizations N] [--workers N] [--force] [--allow-network] [--allow-large] [--cells-file]'),
      signal,
      log,
    ),
  sweep: (args, signal, log) =>
    sweepCommand(
      parseArgs(args, 'sweep SWEEP.json --out DIR [--force] [--allow-network] [--allow-large] [--max-runs N] [--shard I/N|slurm] [--workers N]', true),
      signal,
      log,
    ),
  merge: async (args, _signal, log) => (await import('./merge')).mergeCommand(args, log),
  measure: async (args, _signal, log) => (await import('./measure')).measureCommand(args, log),
};

export async function main(argv: string[]): Promise<number> {
  const log = (line: string) => process.stderr.write(line + '\n');
  // Ctrl-C (or SIGTERM) stops the work at the next safe point; a second one exits at once.
  const controller = new AbortController();
  const onSignal = () => {
    if (controller.signal.aborted) process.exit(EXIT.interrupted);
    log('tissue-sheet: interrupting after the current step (Ctrl-C again to stop now)');
    controller.abort();
  };
  process.on('SIGINT', onSignal);
  process.on('SIGTERM', onSignal);
  try {
    const [command, ...rest] = argv;
    if (command === undefined || command === '--help' || command === '-h') {
      console.log(usage);
      return command === undefined ? EXIT.input : EXIT.ok;
    }
    if (command === '--version') {
      console.log(version);
      return EXIT.ok;
    }
    const handler = Object.prototype.hasOwnProperty.call(commands, command) ? commands[command] : undefined;
    if (!handler) throw new InputError(`unknown command "${command}"; commands: ${Object.keys(commands).join(', ')} (tissue-sheet --help)`);
    const code = await handler(rest, controller.signal, log);
    return typeof code === 'number' ? code : EXIT.ok;
  } catch (error) {
    return report(error);
  } finally {
    process.off('SIGINT', onSignal);
    process.off('SIGTERM', onSignal);
  }
}

function report(error: unknown): number {
  const code = exitCodeFor(error);
  console.error(`tissue-sheet: ${errorLine(error)}`);
  if (code === EXIT.failure && process.env.TISSUE_SHEET_DEBUG && error instanceof Error && error.stack) console.error(error.stack);
  return code;
}
