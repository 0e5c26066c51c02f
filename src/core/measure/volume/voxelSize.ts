/**
 * Voxel size of a label volume in µm, first found of (docs/measure.md, "Measuring a volume"):
 * 1. `--voxel-size X,Y,Z` (along image width, height, and between pages);
 * 2. ImageJ metadata: `unit=` in the ImageDescription with XResolution / YResolution in pixels
 *    per unit, `spacing=` between slices (ImageJ leaves `spacing` out when it is 1 unit);
 * 3. OME-XML: PhysicalSizeX/Y/Z of the first Pixels element (units default to µm);
 * otherwise a MeasureInputError asking for `--voxel-size`.
 */
import { MeasureInputError } from '../errors';
import { micronsPerUnit, parseImageJDescription } from '../pixelSize';
import type { TiffChain } from './tiffPages';

export interface VoxelSize {
  readonly x: number;
  readonly y: number;
  readonly z: number;
  readonly source: 'option' | 'imagej' | 'ome';
  /** How it was read, for people. */
  readonly detail: string;
}

/** Parses `--voxel-size X,Y,Z` (three numbers > 0, µm). Returns null when it is not that. */
export function parseVoxelSizeOption(text: string): { x: number; y: number; z: number } | null {
  const parts = text.split(',').map((p) => p.trim());
  if (parts.length !== 3 || parts.some((p) => p === '')) return null;
  const [x, y, z] = parts.map(Number);
  return [x, y, z].every((v) => Number.isFinite(v) && v > 0) ? { x, y, z } : null;
}

const positive = (v: number | null | undefined): v is number => v != null && Number.isFinite(v) && v > 0;

/** The ImageJ calibration, or null when the file has none (or only pixel units, or a `spacing=` that is no distance). */
function imagejVoxelSize(chain: TiffChain): VoxelSize | null {
  const imagej = parseImageJDescription(chain.description ?? undefined);
  if (!imagej?.unit) return null;
  const unit = micronsPerUnit(imagej.unit);
  if (unit === null || unit === 25400) return null;
  const xr = chain.xResolution;
  const yr = positive(chain.yResolution) ? chain.yResolution : xr;
  if (!positive(xr) || !positive(yr)) return null;
  // A spacing the file gives but that is no distance is not "1 unit", which would silently scale
  // every volume, area and height along z: no calibration (chooseVoxelSize says why).
  if (imagej.invalidSpacing !== null) return null;
  const spacing = imagej.spacing ?? 1;
  return {
    x: unit / xr,
    y: unit / yr,
    z: spacing * unit,
    source: 'imagej',
    detail: `ImageJ unit=${imagej.unit}, XResolution ${xr} and YResolution ${yr} px per unit, ${imagej.spacing === null ? 'no spacing (1 unit)' : `spacing=${imagej.spacing}`}`,
  };
}

/** Attribute `name` of the first `<tag ...>` element in an XML text (no entity handling needed for numbers and units). */
function firstElementAttributes(xml: string, tag: string): Map<string, string> | null {
  const match = new RegExp(`<(?:[A-Za-z_][\\w.-]*:)?${tag}\\b([^>]*)>`).exec(xml);
  if (!match) return null;
  const attributes = new Map<string, string>();
  const re = /([A-Za-z_][\w.:-]*)\s*=\s*("([^"]*)"|'([^']*)')/g;
  let m: RegExpExecArray | null;
  while ((m = re.exec(match[1]))) attributes.set(m[1], m[3] ?? m[4] ?? '');
  return attributes;
}

const OME_UNITS: Record<string, number> = { Å: 1e-4, pm: 1e-6 };

function omeUnit(text: string | undefined): number | null {
  if (text === undefined || text === '') return 1; // OME's default unit is µm
  const decoded = text.replace(/&#181;|&#xB5;|&micro;/gi, 'µ');
  return OME_UNITS[decoded] ?? micronsPerUnit(decoded);
}

export interface OmeDescription {
  readonly voxelSize: VoxelSize | null;
  readonly channels: number;
  readonly times: number;
  /** SizeZ of the first image, or null when absent. */
  readonly slices: number | null;
  /** Image elements in the XML (a file may hold several series). */
  readonly images: number;
}

/** What an OME-XML ImageDescription says about the volume, or null when it is not OME-XML. */
export function parseOme(description: string | null): OmeDescription | null {
  if (!description || !/<(?:\w+:)?OME\b/.test(description)) return null;
  const pixels = firstElementAttributes(description, 'Pixels');
  const images = (description.match(/<(?:\w+:)?Image\b/g) ?? []).length;
  if (!pixels) return { voxelSize: null, channels: 1, times: 1, slices: null, images };
  const count = (name: string) => {
    const v = Number(pixels.get(name));
    return Number.isInteger(v) && v > 0 ? v : 1;
  };
  const size = (axis: 'X' | 'Y' | 'Z'): number | null => {
    const value = Number(pixels.get(`PhysicalSize${axis}`));
    const unit = omeUnit(pixels.get(`PhysicalSize${axis}Unit`));
    return positive(value) && unit !== null ? value * unit : null;
  };
  const x = size('X');
  const y = size('Y');
  const z = size('Z');
  const voxelSize: VoxelSize | null =
    x !== null && y !== null && z !== null
      ? {
          x,
          y,
          z,
          source: 'ome',
          detail: `OME-XML PhysicalSizeX/Y/Z ${pixels.get('PhysicalSizeX')}, ${pixels.get('PhysicalSizeY')}, ${pixels.get('PhysicalSizeZ')} ${pixels.get('PhysicalSizeXUnit') ?? 'µm'}`,
        }
      : null;
  const sizeZ = Number(pixels.get('SizeZ'));
  return { voxelSize, channels: count('SizeC'), times: count('SizeT'), slices: Number.isInteger(sizeZ) && sizeZ > 0 ? sizeZ : null, images };
}

/** The voxel size to use, with warnings when the option disagrees with the file. */
export function chooseVoxelSize(
  chain: TiffChain,
  file: string,
  option: { x: number; y: number; z: number } | undefined,
): { voxelSize: VoxelSize; warnings: string[] } {
  const fromFile = imagejVoxelSize(chain) ?? parseOme(chain.description)?.voxelSize ?? null;
  if (option) {
    const warnings: string[] = [];
    if (fromFile) {
      const differs = (a: number, b: number) => Math.abs(a - b) > 1e-6 * Math.max(a, b);
      if (differs(option.x, fromFile.x) || differs(option.y, fromFile.y) || differs(option.z, fromFile.z)) {
        warnings.push(
          `--voxel-size ${option.x},${option.y},${option.z} overrides the file's ${fromFile.x},${fromFile.y},${fromFile.z} µm (${fromFile.detail})`,
        );
      }
    }
    return { voxelSize: { ...option, source: 'option', detail: '--voxel-size' }, warnings };
  }
  if (!fromFile) {
    const badSpacing = parseImageJDescription(chain.description ?? undefined)?.invalidSpacing ?? null;
    if (badSpacing !== null) {
      throw new MeasureInputError(file, `ImageJ spacing=${badSpacing} is not a distance > 0 between slices; give --voxel-size X,Y,Z in µm`);
    }
    throw new MeasureInputError(file, 'no voxel size in the file (neither ImageJ nor OME-XML calibration); give --voxel-size X,Y,Z in µm');
  }
  return { voxelSize: fromFile, warnings: [] };
}
