/**
 * Everything checked before a run starts: reading a JSON input (one-line errors naming the
 * file), the feasibility checks of the config, the scale guards and the compute budget
 * (src/core/config/limits.ts) against this GPU's texture limit, and the files the config
 * points to (density image, mesh: loaded and checked once, see sources.ts).
 */
import { readFileSync, statSync } from 'node:fs';
import { totalmem } from 'node:os';
import type { Config } from '../core/config';
import { surfaceLayout } from '../core/config/surfaceLayout';
import { checkLimits, DEFAULT_MAX_WORK, type ComputeBudget, type RunEstimate } from '../core/config/limits';
import type { GrayImage } from '../core/density';
import type { MeshFile } from '../run/index';
import { InputError } from './errors';
import type { Sources } from './sources';

const MAX_JSON_BYTES = 64 * 2 ** 20;

/** Reads and parses a JSON file (a UTF-8 byte-order mark is accepted); errors name the file. */
export function readJsonFile(path: string, what: string): unknown {
  let text: string;
  try {
    const stat = statSync(path);
    if (stat.isDirectory()) throw new InputError(`${path}: is a directory; give the path of the ${what} (a JSON file)`);
    if (stat.size > MAX_JSON_BYTES) throw new InputError(`${path}: ${stat.size} bytes is too large for a ${what}`);
    text = readFileSync(path, 'utf8');
  } catch (error) {
    if (error instanceof InputError) throw error;
    const code = (error as NodeJS.ErrnoException).code;
    throw new InputError(
      `${path}: cannot read the ${what} (${code === 'ENOENT' ? 'no such file' : code === 'EACCES' ? 'permission denied' : (error as Error).message})`,
    );
  }
  // Editors on Windows save UTF-8 with a byte-order mark, which JSON.parse rejects.
  if (text.charCodeAt(0) === 0xfeff) text = text.slice(1);
  if (text.trim() === '') throw new InputError(`${path}: the file is empty; write the ${what} as JSON`);
  try {
    return JSON.parse(text);
  } catch (error) {
    const detail = (error as Error).message.replace(/\s*\n\s*/g, ' ');
    throw new InputError(`${path}: not valid JSON (${detail.length > 160 ? `${detail.slice(0, 157)}...` : detail}); fix the ${what}`);
  }
}

/** The budget a run is checked against: this GPU's texture limit, and work and memory caps. */
export function computeBudget(maxTextureSize: number, allowLarge: boolean): ComputeBudget {
  return {
    maxTextureSize,
    maxWork: allowLarge ? Infinity : DEFAULT_MAX_WORK,
    // Half the machine's memory by default (other jobs share it); all of it with --allow-large.
    maxBytes: allowLarge ? totalmem() : totalmem() / 2,
  };
}

const RAISE_HINT = 'pass --allow-large to lift the work and memory limits';

/** Feasibility, scale guards and budget of one validated config; throws ConfigError (exit 2). */
export function checkRunnable(config: Config, budget: ComputeBudget): RunEstimate {
  surfaceLayout(config).checkFeasible();
  return checkLimits(config, budget, RAISE_HINT);
}

export interface RunInputs {
  densityImage?: GrayImage;
  meshFile?: MeshFile;
}

/** Loads (once, through `sources`) the density image or mesh a config needs. */
export async function loadInputs(config: Config, sources: Sources): Promise<RunInputs> {
  const inputs: RunInputs = {};
  if (config.density.kind === 'image') inputs.densityImage = await sources.densityImage(config.density.src);
  if (config.surface.kind === 'mesh') inputs.meshFile = await sources.mesh(config.surface.src);
  return inputs;
}
