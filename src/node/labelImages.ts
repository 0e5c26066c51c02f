/**
 * Label image files for `tissue-sheet measure`: checks that a path is a readable file of a
 * bounded size before reading it whole (the decoders in src/core/measure work on bytes).
 */
import { readFileSync, statSync } from 'node:fs';
import { MeasureInputError, type LabelFileInput } from '../core/measure';

/** Largest file read (a 3D stack is held in memory whole while its pages are decoded). */
const MAX_LABEL_FILE_BYTES = 2 ** 30;

export function labelFileFromPath(path: string): LabelFileInput {
  return {
    name: path,
    read(): Uint8Array {
      let size: number;
      try {
        const stat = statSync(path);
        if (stat.isDirectory()) throw new MeasureInputError(path, 'is a directory; give label image files (PNG or TIFF)');
        if (!stat.isFile()) throw new MeasureInputError(path, 'not a regular file; give label image files (PNG or TIFF)');
        size = stat.size;
      } catch (error) {
        if (error instanceof MeasureInputError) throw error;
        const code = (error as NodeJS.ErrnoException).code;
        throw new MeasureInputError(path, code === 'ENOENT' ? 'no such file' : `cannot read it (${code ?? (error as Error).message})`);
      }
      if (size > MAX_LABEL_FILE_BYTES) {
        throw new MeasureInputError(path, `${size} bytes is over the limit of ${MAX_LABEL_FILE_BYTES} bytes; crop it or split the stack into 2D files`);
      }
      try {
        const buffer = readFileSync(path);
        return new Uint8Array(buffer.buffer, buffer.byteOffset, buffer.byteLength);
      } catch (error) {
        throw new MeasureInputError(path, `cannot read it (${(error as NodeJS.ErrnoException).code ?? (error as Error).message})`);
      }
    },
  };
}
