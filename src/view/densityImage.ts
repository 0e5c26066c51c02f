/**
 * Grayscale density images in the page: an uploaded picture is reduced to at most 128 px on its
 * longer side and stored in the config as a PNG data URL (density.src), so the URL and the
 * saved session carry it and a shared link reproduces the run. Decoding gives the GrayImage
 * runSheet needs.
 *
 * Untrusted input: the bytes are read first (a link's src through fetchSourceBytes, which asks
 * before any other origin), the size is read from the header and bounded, and a truncated PNG
 * is refused (imageHeader.ts) before the browser decodes anything; the browser decodes a blob:
 * URL of the checked bytes, so the page's img-src needs no other origin.
 */
import { ConfigError } from '../core/config';
import type { GrayImage } from '../core/density';
import { decodeGrayPng, ImageError } from '../core/grayPng';
import { ImageHeaderError, readImageSize } from './imageHeader';
import { fetchSourceBytes } from './sources';

const MAX_SIDE = 128;

function loadImage(src: string): Promise<HTMLImageElement> {
  return new Promise((resolve, reject) => {
    const image = new Image();
    image.onload = () => resolve(image);
    image.onerror = () => reject(new Error('The density image could not be read; use a PNG or JPEG file.'));
    image.src = src;
  });
}

function draw(image: CanvasImageSource, width: number, height: number): CanvasRenderingContext2D {
  const canvas = document.createElement('canvas');
  canvas.width = width;
  canvas.height = height;
  const context = canvas.getContext('2d', { willReadFrequently: true });
  if (!context) throw new Error('This browser cannot draw images on a canvas.');
  context.drawImage(image, 0, 0, width, height);
  return context;
}

/** A small grayscale PNG data URL of an uploaded image file (size checked from its header first). */
export async function imageFileToDataUrl(file: Blob): Promise<string> {
  const name = file instanceof File ? file.name : 'the image';
  readImageSize(new Uint8Array(await file.arrayBuffer()), `density image ${name}`);
  const url = URL.createObjectURL(file);
  try {
    const image = await loadImage(url);
    const scale = Math.min(1, MAX_SIDE / Math.max(image.naturalWidth, image.naturalHeight));
    const width = Math.max(1, Math.round(image.naturalWidth * scale));
    const height = Math.max(1, Math.round(image.naturalHeight * scale));
    const context = draw(image, width, height);
    const pixels = context.getImageData(0, 0, width, height);
    for (let i = 0; i < pixels.data.length; i += 4) {
      const y = 0.2126 * pixels.data[i] + 0.7152 * pixels.data[i + 1] + 0.0722 * pixels.data[i + 2];
      pixels.data[i] = pixels.data[i + 1] = pixels.data[i + 2] = y;
      pixels.data[i + 3] = 255;
    }
    context.putImageData(pixels, 0, 0);
    return context.canvas.toDataURL('image/png');
  } finally {
    URL.revokeObjectURL(url);
  }
}

/**
 * Decodes an image (URL or data URL) into luminance 0..1, row 0 = top: a PNG as every host does
 * (core/grayPng.ts), a JPEG by the browser. A foreign URL loads only once approved; the header is
 * checked before decoding. Errors are ConfigErrors on density.src.
 */
export async function decodeGrayImage(src: string): Promise<GrayImage> {
  const bytes = new Uint8Array(await fetchSourceBytes('density.src', src));
  const what = `density.src: density image ${src.startsWith('data:') ? 'from the data: URL' : src}`;
  let format: string;
  try {
    format = readImageSize(bytes, what).format;
  } catch (error) {
    if (error instanceof ImageHeaderError) throw new ConfigError('density.src', error.message);
    throw error;
  }
  // A PNG is decoded as the CLI decodes it (core/grayPng.ts): the same density from the same
  // link or file in every host, and a corrupt file refused (the browser shows it as black).
  if (format === 'png') {
    try {
      return decodeGrayPng(bytes, src.startsWith('data:') ? 'from the data: URL' : src);
    } catch (error) {
      if (error instanceof ImageError) throw new ConfigError('density.src', `density.src: ${error.message}`);
      throw error;
    }
  }
  const url = URL.createObjectURL(new Blob([bytes], { type: `image/${format}` }));
  let image: HTMLImageElement;
  try {
    image = await loadImage(url);
  } finally {
    URL.revokeObjectURL(url);
  }
  const width = image.naturalWidth;
  const height = image.naturalHeight;
  const pixels = draw(image, width, height).getImageData(0, 0, width, height).data;
  const luminance = new Float32Array(width * height);
  for (let i = 0; i < luminance.length; i++) {
    luminance[i] = (0.2126 * pixels[i * 4] + 0.7152 * pixels[i * 4 + 1] + 0.0722 * pixels[i * 4 + 2]) / 255;
  }
  return { width, height, luminance };
}
