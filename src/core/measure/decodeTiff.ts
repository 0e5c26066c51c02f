/**
 * TIFF label images (2D, or 3D as one page per layer), decoded by the `tiff` package (pure
 * JavaScript: strips or tiles, uncompressed, LZW or Deflate, 8/16-bit, either byte order).
 *
 * Every page's tags are read and checked (size, pixel type, compression) before any pixel is
 * decoded; pages are then decoded one at a time, so a 3D stack never holds two decoded layers.
 */
import { decode, type TiffIfd } from 'tiff';
import { MeasureInputError } from './errors';
import { type LabelFileHeader, type LabelPixels, type PageHeader, sizeProblem } from './labelImage';
import { parseImageJDescription, tiffCalibration } from './pixelSize';

export function isTiff(bytes: Uint8Array): boolean {
  if (bytes.length < 4) return false;
  const le = bytes[0] === 0x49 && bytes[1] === 0x49;
  const be = bytes[0] === 0x4d && bytes[1] === 0x4d;
  if (!le && !be) return false;
  const magic = le ? bytes[2] | (bytes[3] << 8) : (bytes[2] << 8) | bytes[3];
  return magic === 42 || magic === 43;
}

const COMPRESSIONS: Record<number, string> = { 1: 'none', 5: 'LZW', 8: 'Deflate', 32946: 'Deflate' };
const PHOTOMETRIC: Record<number, string> = { 0: 'grey', 1: 'grey', 2: 'RGB colour', 3: 'palette', 4: 'mask', 5: 'CMYK', 6: 'YCbCr' };

function readIfds(bytes: Uint8Array, file: string, options: { pages?: number[]; ignoreImageData: boolean }): TiffIfd[] {
  try {
    return decode(bytes, options);
  } catch (error) {
    throw new MeasureInputError(file, `corrupt or unsupported TIFF (${(error as Error).message})`);
  }
}

function numberTag(ifd: TiffIfd, name: string): number | undefined {
  const value = ifd.get(name) as unknown;
  if (typeof value === 'number') return value;
  if (Array.isArray(value) && typeof value[0] === 'number') return value[0];
  return undefined;
}

/** Checks one page's tags; returns its header or throws MeasureInputError. */
function checkPage(ifd: TiffIfd, file: string, index: number, pages: number): PageHeader {
  const where = pages > 1 ? `page ${index + 1}: ` : '';
  const fail = (problem: string) => new MeasureInputError(file, where + problem);
  const samples = ifd.samplesPerPixel ?? 1;
  const bits = ifd.bitsPerSample ?? 1;
  const photometric = ifd.type;
  const format = ifd.sampleFormat;
  if (samples !== 1) {
    throw fail(`unsupported pixel type: ${samples} samples per pixel (${PHOTOMETRIC[photometric] ?? 'colour'}); labels must be one 8- or 16-bit grey channel`);
  }
  if (format === 3) throw fail(`unsupported pixel type: ${bits}-bit floating point; labels must be 8- or 16-bit unsigned integers`);
  if (format === 2) throw fail(`unsupported pixel type: ${bits}-bit signed integers; labels must be 8- or 16-bit unsigned integers`);
  if (format !== 1) throw fail(`unsupported sample format ${format}; labels must be 8- or 16-bit unsigned integers`);
  if (bits === 32) throw fail('unsupported pixel type: 32-bit labels; save them as 16-bit (up to 65,535 labels)');
  if (bits !== 8 && bits !== 16) throw fail(`unsupported pixel type: ${bits}-bit${bits < 8 ? ' (a mask, not labels?)' : ''}; labels must be 8- or 16-bit`);
  if (photometric !== 0 && photometric !== 1 && photometric !== 3) {
    throw fail(`unsupported pixel type: ${PHOTOMETRIC[photometric] ?? `photometric ${photometric}`}; labels must be grey`);
  }
  const compression = ifd.compression ?? 1;
  if (!(compression in COMPRESSIONS)) throw fail(`unsupported compression ${compression}; save without compression, or with LZW or Deflate`);
  const orientation = numberTag(ifd, 'Orientation') ?? 1;
  if (orientation !== 1) throw fail(`unsupported orientation ${orientation}; save it top-left (orientation 1)`);
  const problem = sizeProblem(ifd.width, ifd.height);
  if (problem) throw fail(problem);
  return { width: ifd.width, height: ifd.height, bitsPerSample: bits as 8 | 16 };
}

/** Pages, pixel types and calibration of a TIFF; throws MeasureInputError when unusable. */
export function inspectTiff(bytes: Uint8Array, file: string): LabelFileHeader {
  const le = bytes[0] === 0x49;
  const magic = le ? bytes[2] | (bytes[3] << 8) : (bytes[2] << 8) | bytes[3];
  if (magic === 43) throw new MeasureInputError(file, 'BigTIFF is not supported; save it as a standard TIFF');
  const ifds = readIfds(bytes, file, { ignoreImageData: true });
  if (ifds.length === 0) throw new MeasureInputError(file, 'TIFF without any image');
  const pages = ifds.map((ifd, k) => checkPage(ifd, file, k, ifds.length));
  // One label space for a whole stack (docs/measure.md): a page of 16 bits beside pages of 8
  // is not the same labelling saved twice.
  const odd = pages.findIndex((page) => page.bitsPerSample !== pages[0].bitsPerSample);
  if (odd >= 0) {
    throw new MeasureInputError(
      file,
      `page ${odd + 1}: ${pages[odd].bitsPerSample}-bit, page 1 is ${pages[0].bitsPerSample}-bit; every page must have the same type`,
    );
  }
  const first = ifds[0];
  const imagej = parseImageJDescription(first.imageDescription);
  if (imagej && imagej.channels > 1) {
    throw new MeasureInputError(file, `an ImageJ hyperstack with ${imagej.channels} channels; save the label channel alone`);
  }
  const calibration = tiffCalibration({
    xResolution: numberTag(first, 'XResolution'),
    yResolution: numberTag(first, 'YResolution'),
    resolutionUnit: numberTag(first, 'ResolutionUnit') ?? 2,
    description: first.imageDescription,
  });
  if (calibration.problem) throw new MeasureInputError(file, calibration.problem);
  return { format: 'tiff', pages, pixelSize: calibration.pixelSize, layerSpacing: calibration.layerSpacing };
}

/** Decodes one page (0-based) of a TIFF already accepted by inspectTiff. */
export function decodeTiffPage(bytes: Uint8Array, file: string, page: number, header: PageHeader): LabelPixels {
  const [ifd] = readIfds(bytes, file, { pages: [page], ignoreImageData: false });
  const data = ifd?.data;
  const expected = header.width * header.height;
  if (!data || data.length !== expected || !(data instanceof Uint8Array || data instanceof Uint16Array)) {
    throw new MeasureInputError(file, `corrupt TIFF (page ${page + 1} decoded to ${data?.length ?? 0} samples for ${expected} pixels)`);
  }
  if (ifd.type === 0) {
    // WhiteIsZero: the decoder inverted the values for display; labels are the stored values.
    const max = 2 ** header.bitsPerSample - 1;
    for (let i = 0; i < data.length; i++) data[i] = max - data[i];
  }
  return { width: header.width, height: header.height, bitsPerSample: header.bitsPerSample, data };
}
