/**
 * A PNG's IHDR chunk (always its first), read before anything is inflated: the one header parse
 * of every host (the Node density loader, the measured label images, the page's image gate),
 * which then bound the size by their own limits (src/core/inputLimits.ts for files the CLI and
 * the library read, the page's in src/view/imageHeader.ts).
 */

const PNG_SIGNATURE: readonly number[] = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

export interface PngHeader {
  readonly width: number;
  readonly height: number;
  readonly bitDepth: number;
  readonly colorType: number;
}

/** Bit depths the PNG specification allows per colour type. */
const VALID_DEPTHS: Record<number, number[]> = { 0: [1, 2, 4, 8, 16], 2: [8, 16], 3: [1, 2, 4, 8], 4: [8, 16], 6: [8, 16] };

export function hasPngSignature(bytes: Uint8Array): boolean {
  return bytes.length >= 8 && PNG_SIGNATURE.every((b, k) => bytes[k] === b);
}

/**
 * The header of PNG bytes (at least their first 33), or the problem that makes them unusable,
 * as a short phrase the caller prefixes with the file's name: "not a PNG file", "truncated or
 * corrupt PNG (no IHDR header)", a zero size, or an invalid colour type and bit depth.
 */
export function readPngIhdr(bytes: Uint8Array): PngHeader | { readonly problem: string } {
  if (!hasPngSignature(bytes)) return { problem: 'not a PNG file' };
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const type = bytes.length >= 16 ? String.fromCharCode(bytes[12], bytes[13], bytes[14], bytes[15]) : '';
  if (bytes.length < 33 || type !== 'IHDR' || view.getUint32(8) !== 13) return { problem: 'truncated or corrupt PNG (no IHDR header)' };
  const header = { width: view.getUint32(16), height: view.getUint32(20), bitDepth: bytes[24], colorType: bytes[25] };
  if (header.width === 0 || header.height === 0) return { problem: `declares ${header.width} x ${header.height} pixels` };
  if (!VALID_DEPTHS[header.colorType]?.includes(header.bitDepth)) {
    return { problem: `invalid PNG (colour type ${header.colorType} with bit depth ${header.bitDepth})` };
  }
  return header;
}
