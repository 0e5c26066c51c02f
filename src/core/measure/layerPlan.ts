/**
 * Which layers the input files make, checked from their headers before any pixel is decoded:
 * one 3D TIFF with two or more pages, or two or more single-page 2D images; the same height
 * everywhere; a pixel size from the option or from consistent metadata.
 */
import { decodePngLabels, inspectPng, isPng } from './decodePng';
import { decodeTiffPage, inspectTiff, isTiff } from './decodeTiff';
import { MeasureInputError } from './errors';
import type { LabelFileHeader, LabelPixels, PageHeader, PixelSizeSource } from './labelImage';

/** An input file: its name (for messages and provenance) and a way to read its bytes. */
export interface LabelFileInput {
  readonly name: string;
  /** Reads the whole file; throws MeasureInputError when it cannot. */
  read(): Uint8Array;
}

export interface PlannedLayer {
  /** "basal", "layer k", "apical". */
  readonly name: string;
  readonly file: number;
  /** Page in its file (0-based). */
  readonly page: number;
  readonly header: PageHeader;
}

interface PlannedFile {
  readonly name: string;
  readonly bytes: number;
  readonly header: LabelFileHeader;
}

interface PixelSizeChoice {
  readonly value: number;
  readonly source: PixelSizeSource;
  /** The file whose metadata gave it (source != "option"). */
  readonly file: string | null;
  readonly detail: string;
}

export interface LayerPlan {
  readonly files: PlannedFile[];
  readonly layers: PlannedLayer[];
  readonly pixelSize: PixelSizeChoice;
  /** Distance between slices from the metadata (µm), or null. */
  readonly layerSpacing: number | null;
  readonly warnings: string[];
}

export function inspectLabelFile(bytes: Uint8Array, file: string): LabelFileHeader {
  if (isPng(bytes)) return inspectPng(bytes, file);
  if (isTiff(bytes)) return inspectTiff(bytes, file);
  if (bytes.length === 0) throw new MeasureInputError(file, 'empty file; give a PNG or TIFF label image');
  throw new MeasureInputError(file, 'not a PNG or TIFF image; give label images (8- or 16-bit PNG or TIFF)');
}

function layerName(index: number, count: number): string {
  if (index === 0) return 'basal';
  if (index === count - 1) return 'apical';
  return `layer ${index}`;
}

export function planLayers(files: LabelFileInput[], pixelSizeOption: number | undefined): LayerPlan {
  if (files.length === 0) throw new MeasureInputError('(no file)', 'give one 3D TIFF or two or more 2D label images');
  const planned: PlannedFile[] = files.map((f) => {
    const bytes = f.read();
    return { name: f.name, bytes: bytes.length, header: inspectLabelFile(bytes, f.name) };
  });
  const pages: { file: number; page: number; header: PageHeader }[] = [];
  if (planned.length === 1) {
    const only = planned[0];
    if (only.header.pages.length < 2) {
      const what = only.header.format === 'tiff' ? 'a 3D stack with one page' : 'one 2D image';
      throw new MeasureInputError(only.name, `${what}; give a 3D TIFF with two or more pages, or two or more 2D images (basal first)`);
    }
    only.header.pages.forEach((header, page) => pages.push({ file: 0, page, header }));
  } else {
    planned.forEach((f, file) => {
      if (f.header.pages.length > 1) {
        throw new MeasureInputError(f.name, `a 3D stack of ${f.header.pages.length} pages among several files; give it alone, or 2D images only`);
      }
      pages.push({ file, page: 0, header: f.header.pages[0] });
    });
  }
  const reference = pages[0];
  for (const p of pages) {
    if (p.header.height !== reference.header.height) {
      const where = planned.length === 1 ? `page ${p.page + 1}: ` : '';
      throw new MeasureInputError(
        planned[p.file].name,
        `${where}height ${p.header.height} differs from the first layer's ${reference.header.height} (${planned[reference.file].name}); layers must have the same height (widths may differ)`,
      );
    }
  }
  const warnings: string[] = [];
  const pixelSize = choosePixelSize(planned, pixelSizeOption, warnings);
  const layers = pages.map((p, k) => ({ name: layerName(k, pages.length), ...p }));
  const layerSpacing = planned.find((f) => f.header.layerSpacing !== null)?.header.layerSpacing ?? null;
  return { files: planned, layers, pixelSize, layerSpacing, warnings };
}

function choosePixelSize(files: PlannedFile[], option: number | undefined, warnings: string[]): PixelSizeChoice {
  let metadata: { file: string; value: number; source: 'imagej' | 'tiff-resolution'; detail: string; perInch: boolean } | null = null;
  for (const f of files) {
    const p = f.header.pixelSize;
    if (!p) continue;
    if (metadata && Math.abs(p.value - metadata.value) > 1e-6 * metadata.value) {
      if (option === undefined) {
        throw new MeasureInputError(
          f.name,
          `pixel size ${p.value} µm differs from ${metadata.value} µm in ${metadata.file}; fix the metadata or give --pixel-size`,
        );
      }
      continue;
    }
    metadata ??= { file: f.name, ...p };
  }
  if (option !== undefined) {
    if (metadata && Math.abs(option - metadata.value) > 1e-6 * option) {
      warnings.push(`--pixel-size ${option} µm overrides ${metadata.value} µm from ${metadata.file} (${metadata.detail})`);
    }
    return { value: option, source: 'option', file: null, detail: '--pixel-size' };
  }
  if (!metadata) {
    throw new MeasureInputError(files[0].name, 'no pixel size in the metadata; give --pixel-size µm (--pixel-size 1 measures in pixels)');
  }
  if (metadata.perInch) {
    warnings.push(
      `pixel size ${metadata.value} µm from ${metadata.file} (${metadata.detail}): a resolution per inch is often a print setting, not a calibration; check it or give --pixel-size`,
    );
  }
  return { value: metadata.value, source: metadata.source, file: metadata.file, detail: metadata.detail };
}

/** Decodes one planned layer from its file's bytes. */
export function decodeLayer(bytes: Uint8Array, plan: LayerPlan, layer: PlannedLayer): LabelPixels {
  const file = plan.files[layer.file];
  return file.header.format === 'png' ? decodePngLabels(bytes, file.name) : decodeTiffPage(bytes, file.name, layer.page, layer.header);
}
