/**
 * A density image's PNG bytes to luminance, the same in every host: the CLI and Node library
 * (node/image.ts reads the file) and the page (view/densityImage.ts), so one image gives one
 * density wherever it runs (a browser's own decoder applies gamma and colour profiles, and shows
 * a corrupt PNG as black instead of failing).
 *
 * Decoded by fast-png (pure JavaScript). Luminance uses the Rec. 709 luma weights applied to the
 * stored (gamma-encoded) values scaled to [0, 1] (8- and 16-bit, grey, palette or colour), i.e.
 * what an image editor's "grayscale" shows; alpha is ignored, so transparent pixels count with
 * their colour.
 *
 * Untrusted input: the header (IHDR: width, height, bit depth, colour type) is read and bounded
 * before anything is decoded or allocated, so a 48 KB file declaring 20000 x 20000 pixels is
 * refused at once; a file that ends before its IEND chunk is refused as truncated and a corrupt
 * one as corrupt, instead of decoding as black.
 */
import { decode, type DecodedPng } from 'fast-png';
import type { GrayImage } from './density';
import { MAX_IMAGE_PIXELS } from './inputLimits';
import { readPngIhdr, type PngHeader } from './pngHeader';

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
