/**
 * PNG label images, decoded by fast-png (pure JavaScript, the one PNG decoder on the Node side;
 * it keeps a 16-bit grey image as one 16-bit channel).
 *
 * The header (IHDR, always the first chunk: src/core/pngHeader.ts) is read and checked before
 * anything is inflated.
 * Accepted: 8- or 16-bit grey, 8-bit palette (the index is the label). PNG's pHYs is ignored
 * (editors write 72 or 96 dpi there, not a microscope calibration).
 */
import { decode } from 'fast-png';
import { hasPngSignature, readPngIhdr } from '../pngHeader';
import { MeasureInputError } from './errors';
import { type LabelFileHeader, type LabelPixels, sizeProblem } from './labelImage';

export const isPng = hasPngSignature;

const COLOUR_TYPES: Record<number, string> = {
  0: 'grey',
  2: 'RGB colour',
  3: 'palette',
  4: 'grey with alpha',
  6: 'RGBA colour',
};

/** The PNG's size and pixel type from its IHDR chunk; throws MeasureInputError when unusable. */
export function inspectPng(bytes: Uint8Array, file: string): LabelFileHeader {
  const header = readPngIhdr(bytes);
  if ('problem' in header) throw new MeasureInputError(file, header.problem);
  const { width, height, bitDepth: depth, colorType: colourType } = header;
  const colour = COLOUR_TYPES[colourType];
  if (colourType !== 0 && colourType !== 3) {
    throw new MeasureInputError(file, `unsupported pixel type: ${depth}-bit ${colour}; labels must be one 8- or 16-bit grey channel`);
  }
  if (depth !== 8 && !(depth === 16 && colourType === 0)) {
    const hint = depth < 8 ? ' (a mask, not labels?)' : '';
    throw new MeasureInputError(file, `unsupported pixel type: ${depth}-bit ${colour}${hint}; labels must be 8- or 16-bit`);
  }
  const problem = sizeProblem(width, height);
  if (problem) throw new MeasureInputError(file, problem);
  return { format: 'png', pages: [{ width, height, bitsPerSample: depth as 8 | 16 }], pixelSize: null, layerSpacing: null };
}

/** Decodes a PNG already accepted by inspectPng. */
export function decodePngLabels(bytes: Uint8Array, file: string): LabelPixels {
  const header = inspectPng(bytes, file).pages[0];
  let png;
  try {
    png = decode(bytes);
  } catch (error) {
    throw new MeasureInputError(file, `corrupt PNG (${(error as Error).message})`);
  }
  const expected = header.width * header.height;
  if (png.channels !== 1 || png.data.length !== expected) {
    throw new MeasureInputError(file, `corrupt PNG (decoded ${png.data.length} samples for ${header.width} x ${header.height} pixels)`);
  }
  const data = header.bitsPerSample === 16 ? (png.data as Uint16Array) : (png.data as Uint8Array);
  return { width: header.width, height: header.height, bitsPerSample: header.bitsPerSample, data };
}
