/**
 * Exit codes and the errors that carry them. Every command ends through `exitCodeFor`, so the
 * same kind of problem gives the same code everywhere:
 *
 *   0   done
 *   1   an unexpected failure (a bug: please report it with TISSUE_SHEET_DEBUG=1 output)
 *   2   bad input: a config, sweep spec, mesh, image, runs file or argument (one line naming
 *       the field or file and what to change)
 *   3   environment: no usable GPU context or display, an output directory locked by another
 *       sweep, a file that cannot be written
 *   130 interrupted (Ctrl-C / SIGINT, SIGTERM); a sweep resumes when rerun
 */
import { ConfigError } from '../core/config';
import { SweepSpecError } from '../core/sweep';
import { GpuCapabilityError } from '../run/index';

export const EXIT = { ok: 0, failure: 1, input: 2, environment: 3, interrupted: 130 } as const;

/** A problem with what the user gave us (exit 2). */
export class InputError extends Error {
  override name = 'InputError';
}

/** A problem with the machine or the file system, not with the input (exit 3). */
export class EnvironmentError extends Error {
  override name = 'EnvironmentError';
}

/** The user interrupted the command (exit 130). */
export class InterruptedError extends Error {
  override name = 'InterruptedError';
}

export function exitCodeFor(error: unknown): number {
  if (error instanceof InputError || error instanceof ConfigError || error instanceof SweepSpecError) return EXIT.input;
  if (error instanceof EnvironmentError || error instanceof GpuCapabilityError) return EXIT.environment;
  if (error instanceof InterruptedError || (error instanceof Error && error.name === 'AbortError')) return EXIT.interrupted;
  return EXIT.failure;
}

/**
 * The one line printed for an error: its message with line breaks folded (never a stack trace
 * or an object dump; unexpected errors show their stack only with TISSUE_SHEET_DEBUG=1).
 */
export function errorLine(error: unknown): string {
  const text = error instanceof Error ? error.message : typeof error === 'string' ? error : 'unexpected failure';
  const line = text.replace(/\s*\n\s*/g, '; ').trim();
  return line.length > 500 ? `${line.slice(0, 497)}...` : line;
}
