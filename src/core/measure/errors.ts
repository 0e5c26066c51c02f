/**
 * A problem with one input file, reported to the user as one line `FILE: problem` (exit code 2
 * in the CLI). Everything the user can fix by giving another file or option is one of these;
 * any other exception is a bug.
 */
export class MeasureInputError extends Error {
  constructor(
    readonly file: string,
    readonly problem: string,
  ) {
    super(`${file}: ${problem}`);
    this.name = 'MeasureInputError';
  }
}
