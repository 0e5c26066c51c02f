import { describe, expect, it } from 'vitest';
import { analyzeSurfaces, withMinBoundaryLength, type SurfaceAdjacency } from '../../src/core/analysis';
import { labelAdjacency } from '../../src/core/labels';
import { measureTissue, type MeasuredResult } from '../../src/core/measure';
import type { AnalysisRecord } from '../../src/run/result';
import { writeTiff } from './tiffWriter';
import { hexLattice, memoryFile, png16, png8, randomSites, rasterizeVoronoi, stretchX, type LabelImage } from './images';

const version = 'test';

function neighboursOf(result: MeasuredResult, label: number, layer: number): number[] {
  return result.cells.find((c) => c.label === label)!.neighbours[layer];
}

describe('measureTissue', () => {
  // 8 x 6 hexagons of 24 px, periodic in x: every lattice neighbour, and only those.
  const hex = hexLattice(8, 6, 24);
  const hexLabels = hex.sites.map((_, i) => 3 * i + 11);
  const hexImage = rasterizeVoronoi(hex.width, hex.height, hex.sites, hexLabels, true);

  it('finds the known neighbours of a hexagonal tiling (periodic x), with identical layers giving 0 % scutoids', () => {
    const r = measureTissue([memoryFile('basal.png', png16(hexImage)), memoryFile('apical.png', png16(hexImage))], {
      pixelSize: 0.5,
      periodicX: true,
      version,
    });
    expect(r.cells).toHaveLength(hex.sites.length);
    hex.sites.forEach((_, i) => {
      const expected = hex.neighbours[i].map((j) => hexLabels[j]);
      expect(neighboursOf(r, hexLabels[i], 0), `cell ${i}`).toEqual(expected);
      expect(neighboursOf(r, hexLabels[i], 1)).toEqual(expected);
    });
    const s = r.analyses[0].summary;
    // Only the first and last rows touch the top/bottom border; left/right wrap.
    expect(s.validCells).toBe(8 * 4);
    expect(r.exclusions).toEqual({ touchesBorder: 16, missing: 0, total: 16 });
    expect(s.percentScutoids).toBe(0);
    expect(s.meanTransitions).toBe(0);
    expect(s.perSurface[0].polygonDistribution[3]).toBe(1); // class "6"
    expect(s.perSurface[0].meanSides).toBe(6);
    // Areas: pixel counts x 0.25 µm², summing to the labelled image.
    const total = r.cells.reduce((a, c) => a + c.areas[0], 0);
    expect(total).toBeCloseTo(hex.width * hex.height * 0.25, 9);
    expect(r.inputs.pixelSize).toMatchObject({ value: 0.5, source: 'option' });
    expect(r.surfaceRatio).toEqual({ value: 1, source: 'areas' });
  });

  it('excludes the left/right columns without --periodic-x, with the reason', () => {
    const r = measureTissue([memoryFile('a.png', png16(hexImage)), memoryFile('b.png', png16(hexImage))], { pixelSize: 1, version });
    // Row 2, column 0: the tiling wraps, so this cell reaches both the left and the right edge.
    const leftmost = r.cells.find((c) => c.label === hexLabels[2 * 8])!;
    expect(leftmost.valid).toBe(false);
    expect(leftmost.exclusion!.touchesBorder).toEqual([
      { layer: 0, sides: ['left', 'right'] },
      { layer: 1, sides: ['left', 'right'] },
    ]);
    expect(leftmost.exclusion!.reason).toBe('touches the left and right borders on basal; touches the left and right borders on apical');
    // A cell of the left column still counts as a neighbour of its valid neighbour.
    const inner = r.cells.find((c) => c.label === hexLabels[2 * 8 + 1])!;
    expect(inner.valid).toBe(true);
    expect(inner.neighbours[0]).toContain(leftmost.label);
  });

  it('gives the same neighbours for the same tiling at twice the width (unrolled tube), areas doubled', () => {
    const wide = stretchX(hexImage, 2);
    const r = measureTissue([memoryFile('basal.png', png16(hexImage)), memoryFile('apical.png', png16(wide))], {
      pixelSize: 1,
      periodicX: true,
      minContact: 0,
      version,
    });
    expect(r.analyses[0].summary.percentScutoids).toBe(0);
    for (const c of r.cells) {
      expect(c.neighbours[1]).toEqual(c.neighbours[0]);
      expect(c.areas[1]).toBe(2 * c.areas[0]);
    }
    expect(r.surfaceRatio).toEqual({ value: 2, source: 'widths' });
    expect(r.inputs.layers.map((l) => l.width)).toEqual([hex.width, 2 * hex.width]);
  });

  it('reports a cell missing from a layer as excluded, and a changed neighbour set as a scutoid', () => {
    const width = 120;
    const height = 90;
    const sites = randomSites(30, width, height, 3);
    const labels = sites.map((_, i) => i + 1);
    const basal = rasterizeVoronoi(width, height, sites, labels, true);
    // Apical: site 0 is gone (its area goes to its neighbours): it is missing, its neighbours change.
    const apical = rasterizeVoronoi(width, height, sites.slice(1), labels.slice(1), true);
    const r = measureTissue([memoryFile('basal.png', png8(basal)), memoryFile('apical.png', png8(apical))], { pixelSize: 1, periodicX: true, version });
    const gone = r.cells.find((c) => c.label === 1)!;
    expect(gone.valid).toBe(false);
    expect(gone.exclusion).toMatchObject({ missingFrom: [1], reason: expect.stringContaining('missing from apical') });
    expect(gone.areas[1]).toBe(0);
    expect(r.exclusions.missing).toBe(1);
    // Every valid former neighbour of cell 1 lost it, so it is a scutoid.
    for (const label of gone.neighbours[0]) {
      const c = r.cells.find((x) => x.label === label)!;
      if (c.valid) expect(c.scutoid, `label ${label}`).toBe(true);
    }
    expect(r.analyses[0].summary.scutoids).toBeGreaterThan(0);
  });

  it('equals analyzeSurfaces on labelAdjacency of the same images (an independent adjacency)', () => {
    const width = 150;
    const height = 100;
    const sites = randomSites(60, width, height, 11);
    const labels = sites.map((_, i) => 500 + 2 * i);
    const s = 1.5;
    const layers: LabelImage[] = [0, 1, 2].map((k) => {
      const f = 1 + ((s - 1) * k) / 2;
      const w = Math.round(width * f);
      return rasterizeVoronoi(
        w,
        height,
        sites.map(([x, y]) => [x * (w / width), y]),
        labels,
        true,
      );
    });
    const r = measureTissue(
      layers.map((l, k) => memoryFile(`l${k}.png`, png16(l))),
      { pixelSize: 0.8, periodicX: true, minContact: 2.5, version },
    );
    const reference: SurfaceAdjacency[] = layers.map((l) => {
      const dense = Int32Array.from(l.data, (v) => (v - 500) / 2);
      // measure counts 4-connected pixel edges (its definition): the staircase lengths.
      const a = labelAdjacency({ width: l.width, height, texelX: 0.8, texelY: 0.8, periodicX: true, periodicY: false }, dense, sites.length, 'staircase');
      return withMinBoundaryLength(a, 2.5);
    });
    const expected = analyzeSurfaces(reference).summary;
    const got = r.analyses[0].summary;
    expect({ ...got, perSurface: got.perSurface.map((p) => ({ ...p, label: undefined })) }).toEqual(expected);
    expect(r.inputs.layers.map((l) => l.name)).toEqual(['basal', 'layer 1', 'apical']);
  });

  it('reads one 3D TIFF (uncompressed, LZW, Deflate; either byte order) with the ImageJ calibration', () => {
    const apical = stretchX(hexImage, 1);
    const pages = (compression: 1 | 5 | 8) =>
      [hexImage, apical, hexImage].map((img) => ({
        width: img.width,
        height: img.height,
        bitsPerSample: 16 as const,
        data: img.data,
        compression,
        description: 'ImageJ=1.54f\nimages=3\nslices=3\nunit=micron\nspacing=2.5\n',
        xResolution: 4,
        yResolution: 4,
        resolutionUnit: 1 as const,
      }));
    const results = ([1, 5, 8] as const).flatMap((compression) =>
      [true, false].map((le) => measureTissue([memoryFile('stack.tif', writeTiff(pages(compression), le))], { periodicX: true, version })),
    );
    for (const r of results) {
      expect(r.inputs.pixelSize).toMatchObject({ value: 0.25, source: 'imagej' });
      expect(r.inputs.layerSpacing).toBe(2.5);
      expect(r.inputs.layers.map((l) => l.page)).toEqual([0, 1, 2]);
      expect(r.cells).toEqual(results[0].cells);
      expect(r.analyses).toEqual(results[0].analyses);
    }
    expect(results[0].cells.find((c) => c.label === hexLabels[20])!.neighbours[2]).toEqual(hex.neighbours[20].map((j) => hexLabels[j]));
  });

  it('takes the pixel size from XResolution per centimetre, and lets --pixel-size override it with a warning', () => {
    const page = {
      width: hexImage.width,
      height: hexImage.height,
      bitsPerSample: 16 as const,
      data: hexImage.data,
      xResolution: 5000,
      yResolution: 5000,
      resolutionUnit: 3 as const,
    };
    const files = () => [memoryFile('a.tif', writeTiff([page])), memoryFile('b.tif', writeTiff([page]))];
    const fromMetadata = measureTissue(files(), { periodicX: true, version });
    expect(fromMetadata.inputs.pixelSize).toMatchObject({ value: 2, source: 'tiff-resolution', file: 'a.tif' });
    expect(fromMetadata.warnings).toEqual([]);
    const overridden = measureTissue(files(), { periodicX: true, pixelSize: 1, version });
    expect(overridden.inputs.pixelSize).toMatchObject({ value: 1, source: 'option' });
    expect(overridden.warnings[0]).toContain('--pixel-size 1 µm overrides 2 µm from a.tif');
    // Same neighbours either way (the default min-contact scales with the cell size).
    expect(overridden.cells.map((c) => c.neighbours)).toEqual(fromMetadata.cells.map((c) => c.neighbours));
  });

  it('writes the per-cell statistics with the shape of a simulated AnalysisRecord', () => {
    const r = measureTissue([memoryFile('a.png', png16(hexImage)), memoryFile('b.png', png16(hexImage))], { pixelSize: 1, periodicX: true, version });
    const record: AnalysisRecord = r.analyses[0]; // compile-time check of the shape
    expect(record.method).toBe('labels');
    expect(record.cells.map((c) => c.id)).toEqual(r.cells.map((c) => c.id));
    expect(r.analyses[0].cells.map((c) => c.label)).toEqual([...hexLabels].sort((a, b) => a - b));
    // Default min-contact: 6 / 102.4 of the mean cell diameter on the basal layer.
    const meanArea = (hex.width * hex.height) / hex.sites.length;
    expect(record.minContactLength).toBeCloseTo((6 / 102.4) * Math.sqrt(meanArea), 12);
    expect(r.inputs.options.minContactSource).toBe('default');
  });
});
