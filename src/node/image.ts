/**
 * Reads a density image from disk (Node only): the file's size is bounded before it is read and
 * its PNG header before the rest, then core/grayPng.ts decodes it as every host does. PNG only;
 * other formats are refused with a message rather than misread.
 */
import { closeSync, fstatSync, openSync, readSync, statSync } from 'node:fs';
import { decodeGrayPng, ImageError, readPngHeader } from '../core/grayPng';
import type { GrayImage } from '../core/density';
import { MAX_PNG_BYTES } from '../core/inputLimits';

export { decodeGrayPng, ImageError };

export function loadGrayImage(path: string): GrayImage {
  return decodeGrayPng(readImageFile(path), path);
}

/** Reads a file for a density image with one-line errors (missing, a directory, too large). */
export function readImageFile(path: string): Uint8Array {
  let fd: number;
  try {
    if (statSync(path).isDirectory()) throw new ImageError(`density image ${path}: is a directory; give the path of a PNG file`);
    fd = openSync(path, 'r');
  } catch (error) {
    if (error instanceof ImageError) throw error;
    const code = (error as NodeJS.ErrnoException).code;
    const why = code === 'ENOENT' ? 'no such file' : code === 'EACCES' ? 'permission denied' : (error as Error).message;
    throw new ImageError(`density image ${path}: cannot read it (${why}); check density.src (relative to the config file)`);
  }
  try {
    const size = fstatSync(fd).size;
    if (size > MAX_PNG_BYTES) throw new ImageError(`density image ${path}: ${size} bytes is more than the ${MAX_PNG_BYTES} allowed; downscale it`);
    // The header first: a huge declared size is refused before the rest is read.
    const head = new Uint8Array(Math.min(size, 33));
    readSync(fd, head, 0, head.length, 0);
    readPngHeader(head, path);
    const bytes = new Uint8Array(size);
    let offset = 0;
    while (offset < size) {
      const n = readSync(fd, bytes, offset, size - offset, offset);
      if (n === 0) break;
      offset += n;
    }
    return bytes.subarray(0, offset);
  } finally {
    closeSync(fd);
  }
}
