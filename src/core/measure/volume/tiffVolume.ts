/**
 * A 3D label volume from one multi-page TIFF (one page per z-slice): 8-, 16- or 32-bit
 * unsigned samples, one per pixel, strips or tiles, uncompressed, LZW or Deflate (with or
 * without horizontal differencing), either byte order.
 *
 * Every page's header is checked (tiffPages.ts bounds the voxel count while walking the chain)
 * before the one array the volume needs is allocated; pages are then decoded into it directly.
 */
import { unzlibSync, inflateSync } from 'fflate';
import { MeasureInputError } from '../errors';
import { lzwDecodeInto } from './lzw';
import { readTiffChain, type TiffChain, type TiffPageInfo } from './tiffPages';

/** Largest volume accepted, in voxels: bounds memory before decoding. */
export const MAX_VOLUME_VOXELS = 2 ** 30;

export type VolumeArray = Uint8Array | Uint16Array | Uint32Array;

/** A decoded label volume: index (z * height + y) * width + x; 0 = background. */
export interface LabelVolume {
  readonly width: number;
  readonly height: number;
  readonly depth: number;
  readonly bitsPerSample: 8 | 16 | 32;
  readonly data: VolumeArray;
}

export interface VolumeHeader {
  readonly width: number;
  readonly height: number;
  readonly depth: number;
  readonly bitsPerSample: 8 | 16 | 32;
  readonly chain: TiffChain;
}

const COMPRESSIONS = new Set([1, 5, 8, 32946]);

/** Tiles up to this many pixels are accepted whatever the page size (their buffer is allocated from the header). */
const MAX_TILE_SAMPLES = 2 ** 20;

/** Checks every page of a TIFF as a slice of a label volume; throws MeasureInputError. */
export function inspectVolumeTiff(bytes: Uint8Array, file: string, maxVoxels = MAX_VOLUME_VOXELS): VolumeHeader {
  const chain = readTiffChain(bytes, file, maxVoxels);
  const first = chain.pages[0];
  chain.pages.forEach((page, k) => checkPage(page, first, k, chain.pages.length, file));
  if (chain.pages.length < 2) {
    throw new MeasureInputError(file, 'has one page; a label volume needs at least two pages (z-slices)');
  }
  return { width: first.width, height: first.height, depth: chain.pages.length, bitsPerSample: first.bitsPerSample as 8 | 16 | 32, chain };
}

function checkPage(page: TiffPageInfo, first: TiffPageInfo, k: number, pages: number, file: string): void {
  const fail = (problem: string) => new MeasureInputError(file, `page ${k + 1} of ${pages}: ${problem}`);
  const bits = page.bitsPerSample;
  if (page.samplesPerPixel !== 1) throw fail(`${page.samplesPerPixel} samples per pixel (colour?); labels must be one grey channel of unsigned integers`);
  if (page.sampleFormat === 3) throw fail(`${bits}-bit floating point samples; labels must be 8-, 16- or 32-bit unsigned integers`);
  if (page.sampleFormat === 2) throw fail(`${bits}-bit signed samples; labels must be 8-, 16- or 32-bit unsigned integers`);
  if (page.sampleFormat !== 1) throw fail(`sample format ${page.sampleFormat}; labels must be 8-, 16- or 32-bit unsigned integers`);
  if (bits !== 8 && bits !== 16 && bits !== 32) throw fail(`${bits}-bit samples${bits < 8 ? ' (a mask, not labels?)' : ''}; labels must be 8-, 16- or 32-bit`);
  if (page.photometric !== 0 && page.photometric !== 1 && page.photometric !== 3)
    throw fail(`photometric interpretation ${page.photometric}; labels must be grey`);
  if (!COMPRESSIONS.has(page.compression)) throw fail(`compression ${page.compression}; save without compression, or with LZW or Deflate`);
  if (page.predictor !== 1 && page.predictor !== 2) throw fail(`predictor ${page.predictor}; only horizontal differencing (2) is supported`);
  if (page.orientation !== 1) throw fail(`orientation ${page.orientation}; save it top-left (orientation 1)`);
  if (page.width !== first.width || page.height !== first.height) {
    throw fail(`${page.width} x ${page.height} pixels, page 1 has ${first.width} x ${first.height}; every slice must have the same size`);
  }
  if (bits !== first.bitsPerSample) throw fail(`${bits}-bit, page 1 is ${first.bitsPerSample}-bit; every slice must have the same type`);
  // A strip is never larger than its page (bounded with the volume); a tile may be, so bound it.
  const tileLimit = Math.max(MAX_TILE_SAMPLES, (page.width + 16) * (page.height + 16));
  if (page.tiled && (page.tileWidth > 65536 || page.tileHeight > 65536 || page.tileWidth * page.tileHeight > tileLimit)) {
    throw fail(`tiles of ${page.tileWidth} x ${page.tileHeight} pixels, larger than the page; save it with smaller tiles or strips`);
  }
  const blocks = page.tiled
    ? page.tileWidth > 0 && page.tileHeight > 0
      ? Math.ceil(page.width / page.tileWidth) * Math.ceil(page.height / page.tileHeight)
      : -1
    : Math.ceil(page.height / page.rowsPerStrip);
  if (blocks < 0 || page.offsets.length !== blocks || page.byteCounts.length !== blocks) {
    throw fail(`corrupt TIFF (${page.offsets.length} ${page.tiled ? 'tiles' : 'strips'} where ${blocks} are needed)`);
  }
}

/** Decodes every page of a TIFF accepted by inspectVolumeTiff into one array. */
export function decodeVolumeTiff(bytes: Uint8Array, file: string, header: VolumeHeader): LabelVolume {
  const { width, height, depth, bitsPerSample } = header;
  const sliceSize = width * height;
  const data: VolumeArray =
    bitsPerSample === 8 ? new Uint8Array(sliceSize * depth) : bitsPerSample === 16 ? new Uint16Array(sliceSize * depth) : new Uint32Array(sliceSize * depth);
  header.chain.pages.forEach((page, z) => {
    const slice = data.subarray(z * sliceSize, (z + 1) * sliceSize);
    try {
      decodePage(bytes, page, header.chain.littleEndian, slice);
    } catch (error) {
      if (error instanceof MeasureInputError) throw error;
      throw new MeasureInputError(file, `page ${z + 1}: corrupt TIFF (${(error as Error).message})`);
    }
  });
  return { width, height, depth, bitsPerSample, data };
}

function decodePage(bytes: Uint8Array, page: TiffPageInfo, le: boolean, slice: VolumeArray): void {
  const bps = page.bitsPerSample / 8;
  const blockWidth = page.tiled ? page.tileWidth : page.width;
  const blockHeight = page.tiled ? page.tileHeight : page.rowsPerStrip;
  const across = Math.ceil(page.width / blockWidth);
  const buffer = new ArrayBuffer(blockWidth * blockHeight * bps);
  const raw = new Uint8Array(buffer);
  const samples = bps === 1 ? raw : bps === 2 ? new Uint16Array(buffer) : new Uint32Array(buffer);
  for (let b = 0; b < page.offsets.length; b++) {
    const x0 = page.tiled ? (b % across) * blockWidth : 0;
    const y0 = page.tiled ? Math.floor(b / across) * blockHeight : b * blockHeight;
    // A strip's last block may have fewer rows; a tile is always full size.
    const rows = page.tiled ? blockHeight : Math.min(blockHeight, page.height - y0);
    const expected = blockWidth * rows * bps;
    const start = page.offsets[b];
    const end = start + page.byteCounts[b];
    if (!(start >= 0 && end <= bytes.length && end >= start)) throw new Error(`${page.tiled ? 'tile' : 'strip'} ${b + 1} lies outside the file`);
    const stored = bytes.subarray(start, end);
    const out = raw.subarray(0, expected);
    let got: number;
    if (page.compression === 1) {
      got = Math.min(stored.length, expected);
      out.set(stored.subarray(0, got));
    } else if (page.compression === 5) {
      got = lzwDecodeInto(stored, out);
    } else {
      got = inflateInto(stored, out);
    }
    if (got < expected) throw new Error(`${page.tiled ? 'tile' : 'strip'} ${b + 1} holds ${got} bytes of ${expected}`);
    if (bps > 1 && le !== HOST_LITTLE_ENDIAN) swapBytes(raw, expected, bps);
    if (page.predictor === 2) undoDifferencing(samples, blockWidth, rows);
    const visibleWidth = Math.min(blockWidth, page.width - x0);
    const visibleRows = Math.min(rows, page.height - y0);
    for (let y = 0; y < visibleRows; y++) {
      const from = y * blockWidth;
      slice.set(samples.subarray(from, from + visibleWidth), (y0 + y) * page.width + x0);
    }
  }
}

const HOST_LITTLE_ENDIAN = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1;

/** Deflate (zlib-wrapped, or raw as some writers store it) into a buffer of known size. */
function inflateInto(stored: Uint8Array, out: Uint8Array): number {
  let result: Uint8Array;
  try {
    result = unzlibSync(stored, { out });
  } catch {
    result = inflateSync(stored, { out });
  }
  if (result.buffer !== out.buffer || result.byteOffset !== out.byteOffset) out.set(result.subarray(0, out.length));
  return result.length;
}

function swapBytes(raw: Uint8Array, length: number, bps: number): void {
  for (let i = 0; i < length; i += bps) {
    if (bps === 2) {
      const t = raw[i];
      raw[i] = raw[i + 1];
      raw[i + 1] = t;
    } else {
      let t = raw[i];
      raw[i] = raw[i + 3];
      raw[i + 3] = t;
      t = raw[i + 1];
      raw[i + 1] = raw[i + 2];
      raw[i + 2] = t;
    }
  }
}

/** Horizontal differencing: each sample was stored as the difference to its left neighbour. */
function undoDifferencing(samples: VolumeArray, width: number, rows: number): void {
  for (let y = 0; y < rows; y++) {
    const row = y * width;
    for (let x = 1; x < width; x++) samples[row + x] += samples[row + x - 1];
  }
}
