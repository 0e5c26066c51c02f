/**
 * The pages of a classic TIFF, read from the IFD chain alone (no pixel decoded): what a label
 * volume needs (size, sample type, compression, where the strips or tiles are) and the first
 * page's calibration tags (ImageDescription, X/YResolution).
 *
 * Our own reader rather than the `tiff` package's: that one decodes 8/16-bit integers and
 * floats but not 32-bit unsigned labels nor BigTIFF (which OME-TIFF writers often produce), and
 * it re-walks the chain for every page it decodes. Classic TIFF and BigTIFF are both read.
 * The walk is bounded before it allocates: it stops as soon as the pages read so far hold more
 * voxels than the caller's limit, never follows an offset twice, and reads only inside the file.
 */
import { MeasureInputError } from '../errors';

export interface TiffPageInfo {
  readonly width: number;
  readonly height: number;
  readonly bitsPerSample: number;
  readonly samplesPerPixel: number;
  /** 1 unsigned, 2 signed, 3 float (TIFF default 1). */
  readonly sampleFormat: number;
  readonly compression: number;
  readonly photometric: number;
  /** 1 none, 2 horizontal differencing. */
  readonly predictor: number;
  readonly orientation: number;
  /** Strips (rowsPerStrip rows each) or tiles (tileWidth x tileHeight). */
  readonly tiled: boolean;
  readonly rowsPerStrip: number;
  readonly tileWidth: number;
  readonly tileHeight: number;
  readonly offsets: number[];
  readonly byteCounts: number[];
}

export interface TiffChain {
  readonly littleEndian: boolean;
  readonly pages: TiffPageInfo[];
  /** First page's ImageDescription (ImageJ or OME-XML metadata), or null. */
  readonly description: string | null;
  readonly xResolution: number | null;
  readonly yResolution: number | null;
  /** 1 none, 2 inch, 3 centimetre. */
  readonly resolutionUnit: number;
}

/** Size in bytes of one value of each TIFF field type (1 BYTE ... 12 DOUBLE, 13 IFD; BigTIFF's 16 LONG8, 17 SLONG8, 18 IFD8). */
const TYPE_SIZE: Record<number, number> = { 1: 1, 2: 1, 3: 2, 4: 4, 5: 8, 6: 1, 7: 1, 8: 2, 9: 4, 10: 8, 11: 4, 12: 8, 13: 4, 16: 8, 17: 8, 18: 8 };

/** Most IFD entries a page may have (real files have 10-30). */
const MAX_ENTRIES = 4096;

/** Most pages (z-slices) a volume may have. */
const MAX_PAGES = 65536;

/** Most values a tag we decode may hold (strip or tile offsets of one page). */
const MAX_TAG_VALUES = 2 ** 22;

function isClassicOrBigTiff(bytes: Uint8Array): boolean {
  if (bytes.length < 8) return false;
  const le = bytes[0] === 0x49 && bytes[1] === 0x49;
  const be = bytes[0] === 0x4d && bytes[1] === 0x4d;
  return le || be;
}

/**
 * Walks the IFD chain. `maxVoxels` bounds width x height x pages: a header declaring more is
 * refused as soon as the walk reaches that page, before anything else is read or allocated.
 */
export function readTiffChain(bytes: Uint8Array, file: string, maxVoxels: number): TiffChain {
  const fail = (problem: string) => new MeasureInputError(file, problem);
  if (bytes.length < 8 || !isClassicOrBigTiff(bytes)) throw fail('not a TIFF file (a 3D label volume must be a multi-page TIFF)');
  const view = new DataView(bytes.buffer, bytes.byteOffset, bytes.byteLength);
  const le = bytes[0] === 0x49;
  const magic = view.getUint16(2, le);
  if (magic !== 42 && magic !== 43) throw fail(`not a TIFF file (magic number ${magic})`);
  const big = magic === 43;
  if (big && (bytes.length < 16 || view.getUint16(4, le) !== 8)) throw fail('corrupt BigTIFF header (offsets must be 8 bytes)');
  /** An unsigned 64-bit offset or count; beyond 2^53 it is out of any file we read anyway. */
  const u64 = (at: number) => Number(view.getBigUint64(at, le));
  const entrySize = big ? 20 : 12;
  const countSize = big ? 8 : 2;
  const inline = big ? 8 : 4;

  const inFile = (offset: number, length: number) => offset >= 0 && length >= 0 && offset + length <= bytes.length;
  const values = (type: number, count: number, at: number): number[] => {
    const size = TYPE_SIZE[type];
    if (!size) return [];
    const out: number[] = [];
    for (let k = 0; k < count; k++) {
      const o = at + k * size;
      if (type === 3) out.push(view.getUint16(o, le));
      else if (type === 4 || type === 13) out.push(view.getUint32(o, le));
      else if (type === 16 || type === 18) out.push(u64(o));
      else if (type === 5) {
        const d = view.getUint32(o + 4, le);
        out.push(d === 0 ? NaN : view.getUint32(o, le) / d);
      } else if (type === 1 || type === 7) out.push(view.getUint8(o));
      else out.push(NaN); // signed or float types: no tag we read uses them
    }
    return out;
  };

  const pages: TiffPageInfo[] = [];
  const seen = new Set<number>();
  let description: string | null = null;
  let xResolution: number | null = null;
  let yResolution: number | null = null;
  let resolutionUnit = 2;
  let offset = big ? u64(8) : view.getUint32(4, le);
  while (offset !== 0) {
    if (seen.has(offset)) throw fail('corrupt TIFF (its chain of pages loops)');
    if (pages.length >= MAX_PAGES) throw fail(`more than ${MAX_PAGES} pages; a label volume has one page per z-slice`);
    seen.add(offset);
    if (!inFile(offset, countSize)) throw fail(`corrupt TIFF (page ${pages.length + 1} starts outside the file)`);
    const entries = big ? u64(offset) : view.getUint16(offset, le);
    if (entries > MAX_ENTRIES || !inFile(offset + countSize, entries * entrySize + inline))
      throw fail(`corrupt TIFF (page ${pages.length + 1} has a truncated tag directory)`);
    const tags = new Map<number, number[]>();
    for (let e = 0; e < entries; e++) {
      const at = offset + countSize + entrySize * e;
      const tag = view.getUint16(at, le);
      const type = view.getUint16(at + 2, le);
      const count = big ? u64(at + 4) : view.getUint32(at + 4, le);
      const size = (TYPE_SIZE[type] ?? 0) * count;
      const valueField = at + (big ? 12 : 8);
      const valueAt = size <= inline ? valueField : big ? u64(valueField) : view.getUint32(valueField, le);
      if (!TYPE_SIZE[type] || !inFile(valueAt, size)) continue; // unknown type or out of the file: ignored
      if (tag === 270 && pages.length === 0 && type === 2) {
        description = new TextDecoder('utf-8', { fatal: false }).decode(bytes.subarray(valueAt, valueAt + size)).replace(/\0+$/, '');
        continue;
      }
      // Only the tags we use are decoded (others may be long arrays we do not need).
      if (!USED_TAGS.has(tag)) continue;
      if (count > MAX_TAG_VALUES) throw fail(`page ${pages.length + 1}: tag ${tag} holds ${count} values, over the limit of ${MAX_TAG_VALUES}`);
      tags.set(tag, values(type, count, valueAt));
    }
    const first = (tag: number, fallback: number) => tags.get(tag)?.[0] ?? fallback;
    const page = pageInfo(tags, first);
    const where = `page ${pages.length + 1}`;
    if (!(page.width > 0 && page.height > 0)) throw fail(`corrupt TIFF (${where} has no image size)`);
    if (page.width * page.height * (pages.length + 1) > maxVoxels) {
      throw fail(
        `the header declares ${page.width} x ${page.height} pixels per page and at least ${pages.length + 1} pages, over the limit of ${maxVoxels} voxels; crop or downsample it`,
      );
    }
    if (pages.length === 0) {
      xResolution = tags.has(282) ? first(282, NaN) : null;
      yResolution = tags.has(283) ? first(283, NaN) : null;
      resolutionUnit = first(296, 2);
    }
    pages.push(page);
    const next = offset + countSize + entrySize * entries;
    offset = big ? u64(next) : view.getUint32(next, le);
  }
  if (pages.length === 0) throw fail('TIFF without any image');
  return { littleEndian: le, pages, description, xResolution, yResolution, resolutionUnit };
}

const USED_TAGS = new Set([256, 257, 258, 259, 262, 273, 274, 277, 278, 279, 282, 283, 296, 317, 322, 323, 324, 325, 339]);

function pageInfo(tags: Map<number, number[]>, first: (tag: number, fallback: number) => number): TiffPageInfo {
  const width = first(256, 0);
  const height = first(257, 0);
  const tiled = tags.has(322) || tags.has(324);
  return {
    width,
    height,
    bitsPerSample: first(258, 1),
    samplesPerPixel: first(277, 1),
    sampleFormat: first(339, 1),
    compression: first(259, 1),
    photometric: first(262, 1),
    predictor: first(317, 1),
    orientation: first(274, 1),
    tiled,
    rowsPerStrip: Math.min(first(278, height), height) || height,
    tileWidth: first(322, 0),
    tileHeight: first(323, 0),
    offsets: tags.get(tiled ? 324 : 273) ?? [],
    byteCounts: tags.get(tiled ? 325 : 279) ?? [],
  };
}
