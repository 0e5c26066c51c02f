/** Command-line arguments of `run` and `sweep`: one input, --out, and the opt-in flags. */
import { MAX_REALIZATIONS } from '../core/analysis/realizations';
import { InputError } from './errors';

export interface CliOptions {
  input: string;
  out: string;
  /** Overwrite an existing --out that is not a previous result of ours. */
  force: boolean;
  /** Fetch http(s) mesh and density sources (off: file paths only). */
  allowNetwork: boolean;
  /** Lift the work and memory budget (texture limits still apply). */
  allowLarge: boolean;
  /** `run`: per-cell lists in a binary side file whatever the size (README, "Result JSON"). */
  cellsFile: boolean;
  /** Sweeps: the largest number of runs accepted. */
  maxRuns?: number;
  /** Sweeps: "I/N" or "slurm" (parsed by parseShard). */
  shard?: string;
  /**
   * Threads for exact-engine work (default: the machine's cores): sweeps' runs; `run`'s
   * realizations (the main thread counting as one; 1: all on the main thread).
   */
  workers?: number;
  /** run: realizations the headline is over (seeds seed, seed + 1, ...; default DEFAULT_REALIZATIONS). */
  realizations?: number;
}

export function parseArgs(args: string[], form: string, sweep = false): CliOptions {
  let input: string | undefined;
  let out: string | undefined;
  const options = {
    force: false,
    allowNetwork: false,
    allowLarge: false,
    cellsFile: false,
    maxRuns: undefined as number | undefined,
    shard: undefined as string | undefined,
    workers: undefined as number | undefined,
    realizations: undefined as number | undefined,
  };
  const usage = `usage: tissue-sheet ${form}`;
  for (let i = 0; i < args.length; i++) {
    const arg = args[i];
    const [name, inline] = arg.startsWith('--') && arg.includes('=') ? [arg.slice(0, arg.indexOf('=')), arg.slice(arg.indexOf('=') + 1)] : [arg, undefined];
    const value = (): string => {
      const v = inline ?? args[++i];
      if (v === undefined || v === '') throw new InputError(`${name} needs a value; ${usage}`);
      return v;
    };
    // A flag is on when given; `--force=false` must not mean "on" (nor anything else).
    const flag = (): true => {
      if (inline !== undefined)
        throw new InputError(`${name} takes no value (got ${JSON.stringify(arg)}): give ${name} to turn it on, leave it out to keep it off; ${usage}`);
      return true;
    };
    if (name === '--out' || name === '-o') out = value();
    else if (name === '--force') options.force = flag();
    else if (name === '--allow-network' || name === '--allow-fetch') options.allowNetwork = flag();
    else if (name === '--allow-large') options.allowLarge = flag();
    else if (!sweep && name === '--cells-file') options.cellsFile = flag();
    else if (sweep && name === '--max-runs') {
      const v = value();
      const n = wholeNumber(v);
      if (!(n >= 1)) throw new InputError(`--max-runs: must be a positive integer (got ${JSON.stringify(v)})`);
      options.maxRuns = n;
    } else if (sweep && name === '--shard') options.shard = value();
    else if (!sweep && name === '--realizations') {
      const v = value();
      const n = wholeNumber(v);
      if (!(n >= 1 && n <= MAX_REALIZATIONS))
        throw new InputError(`--realizations: must be a whole number from 1 to ${MAX_REALIZATIONS} (got ${JSON.stringify(v)})`);
      options.realizations = n;
    } else if (name === '--workers') {
      const v = value();
      const n = wholeNumber(v);
      if (!(n >= 1 && n <= 1024)) throw new InputError(`--workers: must be an integer from 1 to 1024 (got ${JSON.stringify(v)})`);
      options.workers = n;
    } else if (arg.startsWith('-') && arg !== '-') throw new InputError(`unknown option ${name}; ${usage}`);
    else if (input === undefined) input = arg;
    else throw new InputError(`unexpected argument ${arg}; ${usage}`);
  }
  if (!input) throw new InputError(`missing input file; ${usage}`);
  if (!out) throw new InputError(`missing --out; ${usage}`);
  return { input, out, ...options };
}

/** A whole number written in decimal digits (not `0x10`, `1e3` or ` 5`), else NaN. */
function wholeNumber(text: string): number {
  return /^\d{1,15}$/.test(text) ? Number(text) : Number.NaN;
}
