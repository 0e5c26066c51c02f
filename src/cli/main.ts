import { existsSync, readFileSync, writeFileSync } from 'node:fs';
import { dirname, resolve } from 'node:path';
import { ConfigError, isClosedConfig, validateAnyConfig, type AnyConfig } from '../core/config';
import { GpuCapabilityError } from '../gpu/context';
import { loadGrayImage } from '../node/image';
import { createHeadlessContext } from '../node/headless';
import { runSheet } from '../run/runSheet';
import { sweepCommand } from './sweep';
import { version } from '../version';

const usage = `tissue-sheet ${version}

Usage:
  tissue-sheet run CONFIG.json --out RESULT.json   compute one sheet (see docs/config.md)
  tissue-sheet sweep SWEEP.json --out DIR          a grid of runs; resumes when rerun (docs/sweep.md)
  tissue-sheet --version | --help

Progress goes to stderr. Exit codes: 0 done, 2 bad input, 3 no usable GPU context, 1 other.`;

/** A problem with what the user gave us: printed as one line, exit code 2. */
class UsageError extends Error {}

export async function main(argv: string[]): Promise<number> {
  try {
    const [command, ...rest] = argv;
    if (command === undefined || command === '--help' || command === '-h') {
      console.log(usage);
      return command === undefined ? 2 : 0;
    }
    if (command === '--version') {
      console.log(version);
      return 0;
    }
    if (command === 'run') return await runCommand(rest);
    if (command === 'measure') return await (await import('./measure')).measureCommand(rest);
    if (command === 'sweep') {
      const { input, out } = parseInputAndOut(rest, 'sweep SWEEP.json --out DIR');
      await sweepCommand(input, out, (line) => process.stderr.write(line + '\n'));
      return 0;
    }
    throw new UsageError(`unknown command "${command}"; try: tissue-sheet run CONFIG.json --out RESULT.json`);
  } catch (error) {
    return report(error);
  }
}

async function runCommand(args: string[]): Promise<number> {
  const { input, out } = parseInputAndOut(args, 'run CONFIG.json --out RESULT.json');
  const config = readConfig(input);
  const densityImage =
    config.density.kind === 'image' ? loadGrayImage(resolve(dirname(input), config.density.src)) : undefined;
  const meshFile = meshNextToConfig(config, input);
  const context = createHeadlessContext();
  try {
    const { result } = await runSheet(config, context, {
      densityImage,
      meshFile,
      onIteration(record, total) {
        process.stderr.write(
          `iteration ${record.iteration}/${total}  energy ${record.energy.toPrecision(8)}  ` +
            `max displacement ${record.maxDisplacement.toPrecision(4)} µm\n`,
        );
      },
    });
    writeFileSync(out, JSON.stringify(result, null, 2) + '\n');
    process.stderr.write(
      `done: ${result.cells.length} cells, ${result.lloyd.iterations.length} iterations, ` +
        `centroid path ${result.gpu.centroidPath}, ${result.timings.totalMs.toFixed(0)} ms -> ${out}\n`,
    );
    return 0;
  } finally {
    context.dispose();
  }
}

export function parseInputAndOut(args: string[], form: string): { input: string; out: string } {
  let input: string | undefined;
  let out: string | undefined;
  for (let i = 0; i < args.length; i++) {
    if (args[i] === '--out' || args[i] === '-o') out = args[++i];
    else if (args[i].startsWith('--out=')) out = args[i].slice('--out='.length);
    else if (args[i].startsWith('-')) throw new UsageError(`unknown option ${args[i]}; usage: tissue-sheet ${form}`);
    else if (input === undefined) input = args[i];
    else throw new UsageError(`unexpected argument ${args[i]}; usage: tissue-sheet ${form}`);
  }
  if (!input) throw new UsageError(`missing input file; usage: tissue-sheet ${form}`);
  if (!out) throw new UsageError(`missing --out; usage: tissue-sheet ${form}`);
  return { input, out };
}

/** A mesh `src` relative to the config file is read from there (else runSheet searches cwd and public/meshes). */
function meshNextToConfig(config: AnyConfig, configPath: string) {
  if (!isClosedConfig(config) || config.surface.kind !== 'mesh') return undefined;
  const path = resolve(dirname(configPath), config.surface.src);
  if (!existsSync(path)) return undefined;
  const bytes = readFileSync(path);
  return { data: bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer, name: path };
}

export function readConfig(path: string): AnyConfig {
  let text: string;
  try {
    text = readFileSync(path, 'utf8');
  } catch {
    throw new UsageError(`${path}: cannot read the file`);
  }
  let json: unknown;
  try {
    json = JSON.parse(text);
  } catch (error) {
    throw new UsageError(`${path}: not valid JSON (${(error as Error).message})`);
  }
  return validateAnyConfig(json);
}

function report(error: unknown): number {
  if (error instanceof UsageError || error instanceof ConfigError) {
    console.error(`tissue-sheet: ${error.message}`);
    return 2;
  }
  if (error instanceof GpuCapabilityError) {
    console.error(`tissue-sheet: ${error.message}`);
    return 3;
  }
  console.error(`tissue-sheet: ${error instanceof Error ? error.message : String(error)}`);
  return 1;
}
