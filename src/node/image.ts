/**
 * Reads a density image from disk (Node only: the browser decodes images itself).
 *
 * PNG only, because pngjs is pure JavaScript and dependable everywhere the CLI runs; other
 * formats are refused with a message rather than misread. Luminance uses the Rec. 709 luma
 * weights applied to the stored (gamma-encoded) 8-bit values, i.e. what an image editor's
 * "grayscale" shows; alpha is ignored, so transparent pixels count with their colour.
 */
import { readFileSync } from 'node:fs';
import { PNG } from 'pngjs';
import type { GrayImage } from '../core/density';

const PNG_SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

export function loadGrayImage(path: string): GrayImage {
  let bytes: Buffer;
  try {
    bytes = readFileSync(path);
  } catch (error) {
    throw new Error(`density image ${path}: cannot read it (${(error as Error).message}); check the path (relative to the config file)`);
  }
  return decodeGrayPng(bytes, path);
}

/** Decodes PNG bytes; `name` only labels error messages. */
export function decodeGrayPng(bytes: Uint8Array, name = 'image'): GrayImage {
  if (bytes.length < 8 || PNG_SIGNATURE.some((b, k) => bytes[k] !== b)) {
    throw new Error(`density image ${name}: not a PNG file; convert it to PNG (grayscale or RGB)`);
  }
  let png: PNG;
  try {
    // pngjs expands every colour type and bit depth to 8-bit RGBA.
    png = PNG.sync.read(Buffer.from(bytes.buffer, bytes.byteOffset, bytes.byteLength));
  } catch (error) {
    throw new Error(`density image ${name}: corrupt PNG (${(error as Error).message}); re-export it`);
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
