/**
 * Density images in the page are untrusted input (a link's `density.src`, an upload): their
 * size is read from the header and bounded before the browser decodes anything, and a PNG that
 * ends before its IEND chunk is refused as truncated (a browser decodes the rows it has and
 * leaves the rest black, which would silently become a density of zeros). Pure: bytes in, a
 * size or a one-line error out.
 *
 * Formats: PNG (IHDR, every chunk walked to IEND) and JPEG (the SOF marker; a JPEG must end with
 * its EOI marker). Anything else is refused, naming the formats that are accepted.
 */

import { hasPngSignature, readPngIhdr } from '../core/pngHeader';

/** Pixels a density image may have in the page: 4096 x 4096 (decoding takes ~12 bytes a pixel). */
export const PAGE_MAX_IMAGE_PIXELS = 4096 * 4096;

/** A density image the page refuses; the message is one line starting with the field. */
export class ImageHeaderError extends Error {
  override name = 'ImageHeaderError';
}

export interface ImageSize {
  format: 'png' | 'jpeg';
  width: number;
  height: number;
}

/**
 * The image's size from its header, checked against PAGE_MAX_IMAGE_PIXELS and for completeness.
 * `what` names the image in errors ("density.src: density image x.png").
 */
export function readImageSize(bytes: Uint8Array, what: string): ImageSize {
  if (bytes.length === 0) throw new ImageHeaderError(`${what}: the file is empty; give a PNG or JPEG image`);
  let size: ImageSize;
  if (hasPngSignature(bytes)) size = pngSize(bytes, what);
  else if (bytes.length >= 3 && bytes[0] === 0xff && bytes[1] === 0xd8 && bytes[2] === 0xff) size = jpegSize(bytes, what);
  else throw new ImageHeaderError(`${what}: not a PNG or JPEG image; convert it to PNG`);
  if (size.width === 0 || size.height === 0) throw new ImageHeaderError(`${what}: declares ${size.width} x ${size.height} pixels; re-export it`);
  if (size.width * size.height > PAGE_MAX_IMAGE_PIXELS) {
    throw new ImageHeaderError(
      `${what}: ${size.width} x ${size.height} pixels is more than the ${PAGE_MAX_IMAGE_PIXELS} the page decodes; downscale it (the density is stretched over the grid anyway)`,
    );
  }
  return size;
}

/** IHDR's size, after walking every chunk: the file must reach IEND with every chunk whole. */
function pngSize(bytes: Uint8Array, what: string): ImageSize {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const typeAt = (at: number) => String.fromCharCode(bytes[at], bytes[at + 1], bytes[at + 2], bytes[at + 3]);
  const header = readPngIhdr(bytes);
  if ('problem' in header) throw new ImageHeaderError(`${what}: ${header.problem}; re-export it`);
  const size: ImageSize = { format: 'png', width: header.width, height: header.height };
  let at = 8;
  let sawData = false;
  while (at + 8 <= bytes.length) {
    const length = view.getUint32(at);
    const type = typeAt(at + 4);
    const end = at + 12 + length; // length, type, data, CRC
    if (end > bytes.length) break;
    if (type === 'IDAT') sawData = true;
    if (type === 'IEND') {
      if (!sawData) throw new ImageHeaderError(`${what}: corrupt PNG (no image data); re-export it`);
      return size;
    }
    at = end;
  }
  throw new ImageHeaderError(`${what}: truncated PNG (the file ends at byte ${bytes.length}, before its IEND chunk); download or export it again`);
}

/** The first start-of-frame marker's size; the file must end with EOI. */
function jpegSize(bytes: Uint8Array, what: string): ImageSize {
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  let at = 2;
  while (at + 4 <= bytes.length) {
    if (bytes[at] !== 0xff) break;
    const marker = bytes[at + 1];
    if (marker === 0xff) {
      at++; // fill byte
      continue;
    }
    const length = view.getUint16(at + 2);
    // SOF0..SOF15 except DHT (C4), JPG (C8) and DAC (CC): precision, height, width.
    if (marker >= 0xc0 && marker <= 0xcf && marker !== 0xc4 && marker !== 0xc8 && marker !== 0xcc) {
      if (at + 9 > bytes.length) break;
      if (bytes[bytes.length - 2] !== 0xff || bytes[bytes.length - 1] !== 0xd9) {
        throw new ImageHeaderError(`${what}: truncated JPEG (no end-of-image marker); download or export it again`);
      }
      return { format: 'jpeg', width: view.getUint16(at + 7), height: view.getUint16(at + 5) };
    }
    at += 2 + length;
  }
  throw new ImageHeaderError(`${what}: truncated or corrupt JPEG (no frame header); re-export it`);
}
