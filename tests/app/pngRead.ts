/**
 * Readers for what src/app/model/pngText.ts writes into a PNG (tEXt chunks, pHYs), for the unit
 * and e2e tests that check the app's PNG exports.
 */
import { crc32 } from '../../src/app/model/pngText';

function checkSignature(png: Uint8Array): void {
  const signature = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
  if (png.length < 33 || signature.some((b, i) => png[i] !== b)) throw new Error('not a PNG file');
}

/** Every tEXt chunk of `png` (keyword -> text), checking each chunk's CRC. */
export function readPngText(png: Uint8Array): Record<string, string> {
  checkSignature(png);
  const view = new DataView(png.buffer, png.byteOffset, png.byteLength);
  const out: Record<string, string> = Object.create(null);
  let at = 8;
  while (at + 12 <= png.length) {
    const length = view.getUint32(at);
    const type = String.fromCharCode(...png.subarray(at + 4, at + 8));
    const data = png.subarray(at + 8, at + 8 + length);
    if (view.getUint32(at + 8 + length) !== crc32(png.subarray(at + 4, at + 8 + length))) throw new Error(`PNG chunk ${type}: bad CRC`);
    if (type === 'tEXt') {
      const nul = data.indexOf(0);
      out[String.fromCharCode(...data.subarray(0, nul))] = Array.from(data.subarray(nul + 1), (b) => String.fromCharCode(b)).join('');
    }
    if (type === 'IEND') break;
    at += 12 + length;
  }
  return out;
}

/** Dots per inch from a PNG's pHYs chunk (unit metre), null when it has none. */
export function readPngDpi(png: Uint8Array): number | null {
  checkSignature(png);
  const view = new DataView(png.buffer, png.byteOffset, png.byteLength);
  for (let at = 8; at + 12 <= png.length;) {
    const length = view.getUint32(at);
    const type = String.fromCharCode(...png.subarray(at + 4, at + 8));
    if (type === 'pHYs' && png[at + 8 + 8] === 1) return view.getUint32(at + 8) * 0.0254;
    if (type === 'IEND') break;
    at += 12 + length;
  }
  return null;
}
