/**
 * What the decoders hand to the measurement: one layer's label pixels, and what a file's header
 * says before anything is decoded.
 */

/** Largest layer accepted, in pixels (8192 x 16384): bounds memory before decoding. */
export const MAX_LAYER_PIXELS = 2 ** 27;

type LabelPixelArray = Uint8Array | Uint16Array;

/** One decoded layer: row-major labels (index y * width + x), 0 = background. */
export interface LabelPixels {
  readonly width: number;
  readonly height: number;
  readonly bitsPerSample: 8 | 16;
  readonly data: LabelPixelArray;
}

/** Where a pixel size came from. */
export type PixelSizeSource = 'option' | 'imagej' | 'tiff-resolution';

/** A pixel size read from a file's metadata. */
export interface PixelSizeMetadata {
  /** µm per pixel (square pixels). */
  readonly value: number;
  readonly source: 'imagej' | 'tiff-resolution';
  /** How it was read, e.g. "ImageJ unit=micron, XResolution 2 px/unit". */
  readonly detail: string;
  /** The resolution was given per inch (often a print setting, not a calibration). */
  readonly perInch: boolean;
}

/** One page of a file, as its header describes it (already checked to be a label image). */
export interface PageHeader {
  readonly width: number;
  readonly height: number;
  readonly bitsPerSample: 8 | 16;
}

/** A file's header: its format, its pages and the calibration it carries. */
export interface LabelFileHeader {
  readonly format: 'png' | 'tiff';
  readonly pages: PageHeader[];
  /** Null when the file carries no usable pixel size. */
  readonly pixelSize: PixelSizeMetadata | null;
  /** Distance between slices (ImageJ `spacing=`), µm, when the file says. */
  readonly layerSpacing: number | null;
}

/** Checks a header's size against MAX_LAYER_PIXELS. Returns a problem, or null when fine. */
export function sizeProblem(width: number, height: number): string | null {
  if (!(Number.isInteger(width) && Number.isInteger(height) && width > 0 && height > 0)) {
    return `invalid image size ${width} x ${height}`;
  }
  if (width * height > MAX_LAYER_PIXELS) {
    return `${width} x ${height} pixels is over the limit of ${MAX_LAYER_PIXELS} pixels per layer; crop or downsample it`;
  }
  return null;
}
