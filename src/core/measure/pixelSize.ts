/**
 * Pixel size from TIFF metadata (see docs/measure.md, "Pixel size").
 *
 * - ImageJ/Fiji (and tifffile with imagej=True) write `unit=micron` (or another unit) in the
 *   ImageDescription and XResolution in pixels per that unit; ResolutionUnit is then 1 (none).
 *   `spacing=` is the distance between slices in the same unit.
 * - Otherwise XResolution with ResolutionUnit 3 (centimetre) or 2 (inch; also the TIFF default
 *   when the tag is absent) gives pixels per centimetre or per inch.
 * - Pixels must be square: YResolution, when present, must equal XResolution.
 */
import type { PixelSizeMetadata } from './labelImage';

/** µm per unit for the units ImageJ and common writers use; null for "pixel" or unknown. */
export function micronsPerUnit(unit: string): number | null {
  const u = unit
    .trim()
    .toLowerCase()
    .replace(/\\u00b5/g, 'µ')
    .replace(/μ/g, 'µ');
  if (['micron', 'microns', 'µm', 'um', 'micrometer', 'micrometre', 'micrometers', 'micrometres'].includes(u)) return 1;
  if (['nm', 'nanometer', 'nanometre', 'nanometers', 'nanometres'].includes(u)) return 1e-3;
  if (['mm', 'millimeter', 'millimetre', 'millimeters', 'millimetres'].includes(u)) return 1e3;
  if (['cm', 'centimeter', 'centimetre', 'centimeters', 'centimetres'].includes(u)) return 1e4;
  if (['m', 'meter', 'metre', 'meters', 'metres'].includes(u)) return 1e6;
  if (['inch', 'inches', 'in'].includes(u)) return 25400;
  return null;
}

export interface ImageJDescription {
  readonly unit: string | null;
  /** `spacing=` when it is a number > 0, else null (absent: ImageJ leaves out a spacing of 1 unit). */
  readonly spacing: number | null;
  /** The text of a `spacing=` that is present but not a number > 0 (0, NaN, negative), else null. */
  readonly invalidSpacing: string | null;
  readonly channels: number;
  readonly frames: number;
}

/** The fields of an ImageJ ImageDescription ("ImageJ=1.54f\nimages=3\nunit=micron\n..."), or null. */
export function parseImageJDescription(description: string | undefined): ImageJDescription | null {
  if (!description || !description.startsWith('ImageJ=')) return null;
  const fields = new Map<string, string>();
  for (const line of description.split(/\r?\n/)) {
    const eq = line.indexOf('=');
    if (eq > 0) fields.set(line.slice(0, eq).trim(), line.slice(eq + 1).trim());
  }
  const integer = (key: string) => {
    const v = Number(fields.get(key));
    return Number.isInteger(v) && v > 0 ? v : 1;
  };
  const spacing = Number(fields.get('spacing'));
  const validSpacing = fields.has('spacing') && Number.isFinite(spacing) && spacing > 0;
  return {
    unit: fields.get('unit') ?? null,
    spacing: validSpacing ? spacing : null,
    invalidSpacing: fields.has('spacing') && !validSpacing ? fields.get('spacing')! : null,
    channels: integer('channels'),
    frames: integer('frames'),
  };
}

export interface TiffCalibrationInput {
  readonly xResolution: number | undefined;
  readonly yResolution: number | undefined;
  /** 1 none, 2 inch, 3 centimetre (TIFF default 2). */
  readonly resolutionUnit: number;
  readonly description: string | undefined;
}

export interface TiffCalibration {
  readonly pixelSize: PixelSizeMetadata | null;
  /** µm between slices (ImageJ spacing), or null. */
  readonly layerSpacing: number | null;
  /** A problem with the calibration (non-square pixels), or null. */
  readonly problem: string | null;
}

/** Pixel size and slice spacing from a TIFF page's tags. */
export function tiffCalibration(input: TiffCalibrationInput): TiffCalibration {
  const imagej = parseImageJDescription(input.description);
  const x = input.xResolution;
  const y = input.yResolution;
  const usable = (r: number | undefined): r is number => r !== undefined && Number.isFinite(r) && r > 0;
  const imagejUnit = imagej?.unit ? micronsPerUnit(imagej.unit) : null;
  const layerSpacing = imagej?.spacing != null && imagejUnit !== null ? imagej.spacing * imagejUnit : null;
  if (!usable(x)) return { pixelSize: null, layerSpacing, problem: null };
  if (usable(y) && Math.abs(x - y) > 1e-6 * Math.max(x, y)) {
    return {
      pixelSize: null,
      layerSpacing,
      problem: `non-square pixels (XResolution ${x}, YResolution ${y}); resample to square pixels`,
    };
  }
  if (imagej && imagejUnit !== null) {
    return {
      pixelSize: {
        value: imagejUnit / x,
        source: 'imagej',
        detail: `ImageJ unit=${imagej.unit}, XResolution ${x} px per unit`,
        perInch: imagejUnit === 25400,
      },
      layerSpacing,
      problem: null,
    };
  }
  if (input.resolutionUnit === 3 || input.resolutionUnit === 2) {
    const perInch = input.resolutionUnit === 2;
    return {
      pixelSize: {
        value: (perInch ? 25400 : 1e4) / x,
        source: 'tiff-resolution',
        detail: `XResolution ${x} px per ${perInch ? 'inch' : 'centimetre'}`,
        perInch,
      },
      layerSpacing,
      problem: null,
    };
  }
  return { pixelSize: null, layerSpacing, problem: null };
}
