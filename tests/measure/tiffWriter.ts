/**
 * A small baseline TIFF writer for the tests (the `tiff` package only decodes): one or more
 * pages, 8/16/32-bit samples, 1 or 3 samples per pixel, uncompressed, LZW or Deflate, either
 * byte order, and the calibration tags (ImageDescription, X/YResolution, ResolutionUnit).
 */
import { deflateSync } from 'node:zlib';

export interface TiffPage {
  width: number;
  height: number;
  bitsPerSample: 8 | 16 | 32;
  /** Interleaved samples, row-major. */
  data: ArrayLike<number>;
  samplesPerPixel?: number;
  /** 1 unsigned, 2 signed, 3 float. */
  sampleFormat?: 1 | 2 | 3;
  /** 1 none, 5 LZW, 8 Deflate. */
  compression?: 1 | 5 | 8;
  rowsPerStrip?: number;
  description?: string;
  xResolution?: number;
  yResolution?: number;
  resolutionUnit?: 1 | 2 | 3;
  photometric?: number;
}

/** TIFF LZW (MSB-first codes, 9..12 bits, Clear = 256, EOI = 257, libtiff's code-width switch). */
export function lzwEncode(input: Uint8Array): Uint8Array {
  const out: number[] = [];
  let buffer = 0;
  let bits = 0;
  let width = 9;
  const emit = (code: number) => {
    buffer = (buffer << width) | code;
    bits += width;
    while (bits >= 8) {
      out.push((buffer >>> (bits - 8)) & 0xff);
      bits -= 8;
    }
    buffer &= (1 << bits) - 1;
  };
  let table = new Map<number, number>();
  let next = 258;
  emit(256);
  if (input.length === 0) {
    emit(257);
    if (bits > 0) out.push((buffer << (8 - bits)) & 0xff);
    return Uint8Array.from(out);
  }
  let w = input[0];
  for (let i = 1; i < input.length; i++) {
    const c = input[i];
    const key = w * 256 + c;
    const found = table.get(key);
    if (found !== undefined) {
      w = found;
      continue;
    }
    emit(w);
    table.set(key, next++);
    if (next > (1 << width) - 1) width++;
    if (next >= 4093) {
      emit(256);
      table = new Map();
      next = 258;
      width = 9;
    }
    w = c;
  }
  emit(w);
  next++;
  if (next > (1 << width) - 1 && width < 12) width++;
  emit(257);
  if (bits > 0) out.push((buffer << (8 - bits)) & 0xff);
  return Uint8Array.from(out);
}

function sampleBytes(page: TiffPage, littleEndian: boolean, from: number, to: number): Uint8Array {
  const bytes = page.bitsPerSample / 8;
  const out = new Uint8Array((to - from) * bytes);
  const view = new DataView(out.buffer);
  for (let i = from; i < to; i++) {
    const v = page.data[i];
    const o = (i - from) * bytes;
    if (page.bitsPerSample === 8) view.setUint8(o, v);
    else if (page.bitsPerSample === 16) view.setUint16(o, v, littleEndian);
    else if (page.sampleFormat === 3) view.setFloat32(o, v, littleEndian);
    else view.setUint32(o, v, littleEndian);
  }
  return out;
}

type Entry = { tag: number; type: 2 | 3 | 4 | 5; values: number[] | string };

export function writeTiff(pages: TiffPage[], littleEndian = true): Uint8Array {
  const chunks: Uint8Array[] = [];
  let size = 8;
  const append = (bytes: Uint8Array): number => {
    const at = size;
    chunks.push(bytes);
    size += bytes.length;
    if (size % 2) {
      chunks.push(new Uint8Array(1));
      size++;
    }
    return at;
  };
  const header = new Uint8Array(8);
  const hv = new DataView(header.buffer);
  header[0] = header[1] = littleEndian ? 0x49 : 0x4d;
  hv.setUint16(2, 42, littleEndian);
  chunks.push(header);
  let previousNextPointer: { chunk: Uint8Array; offset: number } = { chunk: header, offset: 4 };

  for (const page of pages) {
    const spp = page.samplesPerPixel ?? 1;
    const rowsPerStrip = page.rowsPerStrip ?? Math.max(1, Math.min(page.height, 16));
    const compression = page.compression ?? 1;
    const offsets: number[] = [];
    const counts: number[] = [];
    for (let y = 0; y < page.height; y += rowsPerStrip) {
      const rows = Math.min(rowsPerStrip, page.height - y);
      const raw = sampleBytes(page, littleEndian, y * page.width * spp, (y + rows) * page.width * spp);
      const stored = compression === 5 ? lzwEncode(raw) : compression === 8 ? new Uint8Array(deflateSync(raw)) : raw;
      offsets.push(append(stored));
      counts.push(stored.length);
    }
    const entries: Entry[] = [
      { tag: 256, type: 4, values: [page.width] },
      { tag: 257, type: 4, values: [page.height] },
      { tag: 258, type: 3, values: new Array(spp).fill(page.bitsPerSample) },
      { tag: 259, type: 3, values: [compression] },
      { tag: 262, type: 3, values: [page.photometric ?? (spp === 3 ? 2 : 1)] },
      { tag: 273, type: 4, values: offsets },
      { tag: 277, type: 3, values: [spp] },
      { tag: 278, type: 4, values: [rowsPerStrip] },
      { tag: 279, type: 4, values: counts },
      { tag: 339, type: 3, values: new Array(spp).fill(page.sampleFormat ?? 1) },
    ];
    if (page.description !== undefined) entries.push({ tag: 270, type: 2, values: page.description + '\0' });
    if (page.xResolution !== undefined) entries.push({ tag: 282, type: 5, values: [page.xResolution] });
    if (page.yResolution !== undefined) entries.push({ tag: 283, type: 5, values: [page.yResolution] });
    if (page.resolutionUnit !== undefined) entries.push({ tag: 296, type: 3, values: [page.resolutionUnit] });
    entries.sort((a, b) => a.tag - b.tag);

    // Values that do not fit in 4 bytes go before the IFD.
    const external = new Map<number, number>();
    for (const e of entries) {
      const bytes = encodeValues(e, littleEndian);
      if (bytes.length > 4) external.set(e.tag, append(bytes));
    }
    const ifd = new Uint8Array(2 + 12 * entries.length + 4);
    const v = new DataView(ifd.buffer);
    v.setUint16(0, entries.length, littleEndian);
    entries.forEach((e, k) => {
      const o = 2 + 12 * k;
      const bytes = encodeValues(e, littleEndian);
      v.setUint16(o, e.tag, littleEndian);
      v.setUint16(o + 2, e.type, littleEndian);
      v.setUint32(o + 4, typeof e.values === 'string' ? e.values.length : e.values.length, littleEndian);
      if (bytes.length > 4) v.setUint32(o + 8, external.get(e.tag)!, littleEndian);
      else ifd.set(bytes, o + 8);
    });
    const at = append(ifd);
    new DataView(previousNextPointer.chunk.buffer).setUint32(previousNextPointer.offset, at, littleEndian);
    previousNextPointer = { chunk: ifd, offset: ifd.length - 4 };
  }
  const out = new Uint8Array(size);
  let o = 0;
  for (const c of chunks) {
    out.set(c, o);
    o += c.length;
  }
  return out;
}

function encodeValues(e: Entry, le: boolean): Uint8Array {
  if (typeof e.values === 'string') return new TextEncoder().encode(e.values);
  const size = e.type === 3 ? 2 : e.type === 4 ? 4 : 8;
  const out = new Uint8Array(size * e.values.length);
  const v = new DataView(out.buffer);
  e.values.forEach((x, k) => {
    if (e.type === 3) v.setUint16(2 * k, x, le);
    else if (e.type === 4) v.setUint32(4 * k, x, le);
    else {
      const denominator = Math.max(1, Math.min(1_000_000, Math.floor(0xffffffff / Math.max(1, x))));
      v.setUint32(8 * k, Math.round(x * denominator), le);
      v.setUint32(8 * k + 4, denominator, le);
    }
  });
  return out;
}
