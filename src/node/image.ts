/**
 * Reads a density image from disk (Node only: the browser decodes images itself).
 *
 * PNG only, decoded by fast-png (pure JavaScript, the one PNG decoder on the Node side: the
 * measured label images use it too); other formats are refused with a message rather than
 * misread. Luminance uses the Rec. 709 luma weights applied to the stored (gamma-encoded)
 * values scaled to [0, 1] (8- and 16-bit, grey, palette or colour), i.e. what an image
 * editor's "grayscale" shows; alpha is ignored, so transparent pixels count with their colour.
 *
 * Untrusted input: the header (IHDR: width, height, bit depth, colour type) is read and bounded
 * before anything is decoded or allocated, so a 48 KB file declaring 20000 x 20000 pixels is
 * refused at once; a file larger than MAX_PNG_BYTES is refused before it is read; a file that
 * ends before its IEND chunk is refused as truncated instead of decoding as black.
 */
import { closeSync, fstatSync, openSync, readSync, statSync } from 'node:fs';
import { decode, type DecodedPng } from 'fast-png';
import type { GrayImage } from '../core/density';
import { MAX_IMAGE_PIXELS, MAX_PNG_BYTES } from '../core/inputLimits';
import { readPngIhdr, type PngHeader } from '../core/pngHeader';

// The limits every host shares (core/inputLimits.ts): 8192 x 8192 pixels, 256 MiB.
export { MAX_IMAGE_PIXELS, MAX_PNG_BYTES };

export class ImageError extends Error {
  override name = 'ImageError';
}

/** Reads and checks the IHDR chunk (the first 33 bytes); throws ImageError naming the file. */
export function readPngHeader(bytes: Uint8Array, name = 'image', maxPixels = MAX_IMAGE_PIXELS): PngHeader {
  if (bytes.length === 0) throw new ImageError(`density image ${name}: the file is empty; give a PNG file`);
  const header = readPngIhdr(bytes);
  if ('problem' in header) {
    const hint = header.problem === 'not a PNG file' ? 'convert it to PNG (grayscale or RGB)' : 're-export it';
    throw new ImageError(`density image ${name}: ${header.problem}; ${hint}`);
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
  let png: DecodedPng;
  try {
    png = decode(bytes);
  } catch (error) {
    throw new ImageError(`density image ${name}: corrupt PNG (${(error as Error).message}); re-export it`);
  }
  const { width, height } = png;
  const luminance = new Float32Array(width * height);
  const rgb = new Float64Array(3);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      pixelRgb(png, x, y, rgb);
      // The weights sum to 1 only up to rounding: clamp so white is exactly <= 1.
      luminance[y * width + x] = Math.min(1, 0.2126 * rgb[0] + 0.7152 * rgb[1] + 0.0722 * rgb[2]);
    }
  }
  return { width, height, luminance };
}

/**
 * The colour of pixel (x, y) in [0, 1]³ from fast-png's decoded data: samples of `depth` bits,
 * `channels` per pixel (grey, grey + alpha, RGB, RGBA, or a palette index), rows packed to
 * whole bytes below 8 bits.
 */
function pixelRgb(png: DecodedPng, x: number, y: number, out: Float64Array): void {
  const { width, depth, channels, data, palette } = png;
  let first: number; // the pixel's first sample, raw
  if (depth >= 8) first = data[(y * width + x) * channels];
  else {
    const rowBytes = Math.ceil((depth * channels * width) / 8);
    const bit = x * depth * channels;
    first = (data[y * rowBytes + (bit >> 3)] >> (8 - depth - (bit & 7))) & ((1 << depth) - 1);
  }
  if (palette) {
    const colour = palette[first] ?? [0, 0, 0];
    for (let c = 0; c < 3; c++) out[c] = colour[c] / 255;
    return;
  }
  const max = 2 ** depth - 1;
  if (channels < 3) out.fill(first / max);
  else for (let c = 0; c < 3; c++) out[c] = data[(y * width + x) * channels + c] / max;
}

/** The last chunk of a complete PNG is IEND (length 0, type "IEND", CRC): its last 12 bytes. */
function endsWithIend(bytes: Uint8Array): boolean {
  const n = bytes.length;
  return n >= 12 && String.fromCharCode(...bytes.subarray(n - 8, n - 4)) === 'IEND';
}
