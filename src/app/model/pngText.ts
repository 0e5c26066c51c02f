/**
 * Provenance in a PNG: tEXt chunks (keyword, NUL, Latin-1 text; PNG 1.2 §4.2.3.1) inserted right
 * after IHDR (tests/app/pngRead.ts reads them back for the tests). Text outside Latin-1 is written
 * as JSON-style \uXXXX escapes, so a configuration (JSON) survives unchanged. Pure: bytes in,
 * bytes out.
 */

const SIGNATURE = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];

let crcTable: Uint32Array | null = null;

/** CRC-32 (ISO 3309, the PNG chunk checksum) of `bytes`. */
export function crc32(bytes: Uint8Array): number {
  if (!crcTable) {
    crcTable = new Uint32Array(256);
    for (let n = 0; n < 256; n++) {
      let c = n;
      for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
      crcTable[n] = c >>> 0;
    }
  }
  let c = 0xffffffff;
  for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
  return (c ^ 0xffffffff) >>> 0;
}

function latin1(text: string): Uint8Array {
  // Latin-1's printable characters as they are (µm, ², ° read as such in exiftool or Fiji); only
  // what Latin-1 cannot hold, and control characters but the line feed, is escaped.
  const escaped = text.replace(/[^\x20-\x7e\xa0-\xff\n]/g, (ch) => `\\u${ch.charCodeAt(0).toString(16).padStart(4, '0')}`);
  return Uint8Array.from(escaped, (ch) => ch.charCodeAt(0));
}

function chunk(type: string, data: Uint8Array): Uint8Array {
  const out = new Uint8Array(12 + data.length);
  const view = new DataView(out.buffer);
  view.setUint32(0, data.length);
  out.set(latin1(type), 4);
  out.set(data, 8);
  view.setUint32(8 + data.length, crc32(out.subarray(4, 8 + data.length)));
  return out;
}

function checkSignature(png: Uint8Array): void {
  if (png.length < 33 || SIGNATURE.some((b, i) => png[i] !== b)) throw new Error('not a PNG file');
}

/** `png` with a tEXt chunk per entry after IHDR. Keywords: 1 to 79 Latin-1 characters. */
export function withPngText(png: Uint8Array, entries: readonly [keyword: string, text: string][]): Uint8Array {
  checkSignature(png);
  const ihdrEnd = 8 + 12 + new DataView(png.buffer, png.byteOffset).getUint32(8);
  const chunks = entries.map(([keyword, text]) => {
    if (!/^[\x20-\x7e]{1,79}$/.test(keyword)) throw new Error(`PNG text keyword "${keyword}": use 1 to 79 printable characters`);
    const key = latin1(keyword);
    const body = latin1(text);
    const data = new Uint8Array(key.length + 1 + body.length);
    data.set(key, 0);
    data.set(body, key.length + 1);
    return chunk('tEXt', data);
  });
  const size = png.length + chunks.reduce((n, c) => n + c.length, 0);
  const out = new Uint8Array(size);
  out.set(png.subarray(0, ihdrEnd), 0);
  let at = ihdrEnd;
  for (const c of chunks) {
    out.set(c, at);
    at += c.length;
  }
  out.set(png.subarray(ihdrEnd), at);
  return out;
}

/**
 * `png` with a pHYs chunk (PNG 1.2 §4.2.4.3) after IHDR saying `dpi` dots per inch, stored as
 * pixels per metre (unit 1), so a journal's tools print it at the chosen size. Replaces none:
 * call it on a PNG without pHYs (canvas.toBlob writes none).
 */
export function withPngDpi(png: Uint8Array, dpi: number): Uint8Array {
  checkSignature(png);
  if (!(dpi > 0 && dpi <= 10000)) throw new Error(`PNG resolution ${dpi} dpi: choose 1 to 10000`);
  const ihdrEnd = 8 + 12 + new DataView(png.buffer, png.byteOffset).getUint32(8);
  const data = new Uint8Array(9);
  const view = new DataView(data.buffer);
  const perMetre = Math.round(dpi / 0.0254);
  view.setUint32(0, perMetre);
  view.setUint32(4, perMetre);
  data[8] = 1;
  const phys = chunk('pHYs', data);
  const out = new Uint8Array(png.length + phys.length);
  out.set(png.subarray(0, ihdrEnd), 0);
  out.set(phys, ihdrEnd);
  out.set(png.subarray(ihdrEnd), ihdrEnd + phys.length);
  return out;
}
