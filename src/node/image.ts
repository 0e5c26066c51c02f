/**
 * Reads a density image from disk (Node only: the browser decodes images itself).
 *
 * PNG only, because pngjs is pure JavaScript and dependable everywhere the CLI runs; other
 * formats are refused with a message rather than misread. Luminance uses the Rec. 709 luma
 * weights applied to the stored (gamma-encoded) 8-bit values, i.e. what an image editor's
 * "grayscale" shows; alpha is ignored, so transparent pixels count with their colour.
 *
 * Untrusted input: the header (IHDR: width, height, bit depth, colour type) is read and bounded
 * before anything is decoded or allocated, so a 48 KB file declaring 20000 x 20000 pixels is
 * refused at once; a file larger than MAX_PNG_BYTES is refused before it is read; a file that
 * ends before its IEND chunk is refused as truncated instead of decoding as black.
 */
import { closeSync, fstatSync, openSync, readSync, statSync } from 'node:fs';
import { PNG } from 'pngjs';
import type { GrayImage } from '../core/density';

const PNG_SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
import { MAX_IMAGE_PIXELS, MAX_PNG_BYTES } from '../core/inputLimits';

// The limits every host shares (core/inputLimits.ts): 8192 x 8192 pixels, 256 MiB.
export { MAX_IMAGE_PIXELS, MAX_PNG_BYTES };

export class ImageError extends Error {
  override name = 'ImageError';
}

export interface PngHeader {
  width: number;
  height: number;
  bitDepth: number;
  colorType: number;
}

const VALID_DEPTHS: Record<number, number[]> = { 0: [1, 2, 4, 8, 16], 2: [8, 16], 3: [1, 2, 4, 8], 4: [8, 16], 6: [8, 16] };

/** Reads and checks the IHDR chunk (the first 33 bytes); throws ImageError naming the file. */
export function readPngHeader(bytes: Uint8Array, name = 'image', maxPixels = MAX_IMAGE_PIXELS): PngHeader {
  if (bytes.length === 0) throw new ImageError(`density image ${name}: the file is empty; give a PNG file`);
  if (bytes.length < 8 || PNG_SIGNATURE.some((b, k) => bytes[k] !== b)) {
    throw new ImageError(`density image ${name}: not a PNG file; convert it to PNG (grayscale or RGB)`);
  }
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const type = bytes.length >= 16 ? String.fromCharCode(...bytes.subarray(12, 16)) : '';
  if (bytes.length < 33 || type !== 'IHDR' || view.getUint32(8) !== 13) {
    throw new ImageError(`density image ${name}: truncated or corrupt PNG (no IHDR header); re-export it`);
  }
  const header = { width: view.getUint32(16), height: view.getUint32(20), bitDepth: bytes[24], colorType: bytes[25] };
  if (header.width === 0 || header.height === 0)
    throw new ImageError(`density image ${name}: declares ${header.width} x ${header.height} pixels; re-export it`);
  if (!VALID_DEPTHS[header.colorType]?.includes(header.bitDepth)) {
    throw new ImageError(`density image ${name}: invalid PNG (colour type ${header.colorType} with bit depth ${header.bitDepth}); re-export it`);
  }
  if (header.width * header.height > maxPixels) {
    throw new ImageError(
      `density image ${name}: ${header.width} x ${header.height} pixels is more than the ${maxPixels} allowed; downscale it (the density is stretched over the grid, which has at most resolution² texels)`,
    );
  }
  return header;
}

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

/** Decodes PNG bytes (header checked first); `name` only labels error messages. */
export function decodeGrayPng(bytes: Uint8Array, name = 'image', maxPixels = MAX_IMAGE_PIXELS): GrayImage {
  readPngHeader(bytes, name, maxPixels);
  if (!endsWithIend(bytes)) throw new ImageError(`density image ${name}: truncated PNG (it ends before its IEND chunk); re-export it`);
  let png: PNG;
  try {
    // pngjs expands every colour type and bit depth to 8-bit RGBA.
    png = PNG.sync.read(Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength));
  } catch (error) {
    throw new ImageError(`density image ${name}: corrupt PNG (${(error as Error).message}); re-export it`);
  }
  const { width, height, data } = png;
  const luminance = new Float32Array(width * height);
  for (let k = 0; k < width * height; k++) {
    const r = data[4 * k];
    const g = data[4 * k + 1];
    const b = data[4 * k + 2];
    // The weights sum to 1 only up to rounding: clamp so white is exactly <= 1.
    luminance[k] = Math.min(1, (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255);
  }
  return { width, height, luminance };
}

/** The last chunk of a complete PNG is IEND (length 0, type "IEND", CRC): its last 12 bytes. */
function endsWithIend(bytes: Uint8Array): boolean {
  const n = bytes.length;
  return n >= 12 && String.fromCharCode(...bytes.subarray(n - 8, n - 4)) === 'IEND';
}
