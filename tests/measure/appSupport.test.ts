import { describe, expect, it } from 'vitest';
import { compareMeasured, compareWithModel, measureTissue, type LabelPixels } from '../../src/core/measure';
import { cellsByLabel, paintLayer, reduceLabels, withSelected } from '../../src/view/measurePicture';
import { RGB, sideColorIndex } from '../../src/view/sideColors';
import { memoryFile, png16, randomSites, rasterizeVoronoi } from './images';

const version = 'test';
const width = 96;
const height = 64;
const sites = randomSites(20, width, height, 3);
const labels = sites.map((_, i) => 2 * i + 1);
const basal = rasterizeVoronoi(width, height, sites, labels, true);
const apical = rasterizeVoronoi(
  2 * width,
  height,
  sites.map(([x, y]) => [2 * x, y]),
  labels,
  true,
);
const files = () => [memoryFile('basal.png', png16(basal)), memoryFile('apical.png', png16(apical))];

describe('what the app needs of measureTissue', () => {
  it("hands each decoded layer to onLayerPixels, basal first, with the file's pixels", () => {
    const seen: [number, LabelPixels][] = [];
    const r = measureTissue(files(), { pixelSize: 1, periodicX: true, version, onLayerPixels: (k, p) => seen.push([k, p]) });
    expect(seen.map(([k]) => k)).toEqual([0, 1]);
    expect(Array.from(seen[0][1].data)).toEqual(Array.from(basal.data));
    expect(Array.from(seen[1][1].data)).toEqual(Array.from(apical.data));
    // Keeping the pixels changes nothing in the result.
    const plain = measureTissue(files(), { pixelSize: 1, periodicX: true, version });
    expect({ ...r, timings: null }).toEqual({ ...plain, timings: null });
  });

  it("compareMeasured passes the CLI's arguments to compareWithModel", () => {
    const r = measureTissue(files(), { pixelSize: 0.5, periodicX: true, version });
    const { comparison } = compareMeasured(r, { realizations: 2, seed: 4 });
    const direct = compareWithModel({
      width,
      height,
      pixelSize: 0.5,
      periodicX: true,
      cells: 20,
      distribution: r.analyses[0].summary.perSurface[0].polygonDistribution,
      layers: 2,
      surfaceRatio: 2,
      realizations: 2,
      seed: 4,
    });
    expect(comparison).toEqual(direct);
  });
});

describe('measured layer pictures', () => {
  const image: LabelPixels = { width, height, bitsPerSample: 16, data: basal.data };

  it('reduces by one integer step, nearest pixel, to at most maxSide', () => {
    const full = reduceLabels(image, 1024);
    expect([full.width, full.height, full.step]).toEqual([width, height, 1]);
    const half = reduceLabels(image, 50);
    expect([half.width, half.height, half.step]).toEqual([48, 32, 2]);
    for (let y = 0; y < half.height; y++) for (let x = 0; x < half.width; x++) expect(half.labels[y * 48 + x]).toBe(basal.data[2 * y * width + 2 * x]);
  });

  it('paints inner pixels in the side colour of their cell on that layer, and the picked cell white', () => {
    const r = measureTissue(files(), { pixelSize: 1, periodicX: true, version });
    const layer = reduceLabels(image);
    const cells = cellsByLabel(r.cells, 2);
    const rgba = paintLayer(layer, 0, cells, true);
    const record = r.cells.find((c) => c.valid)!;
    // Scutoids are striped every `stripe` diagonals (sideColors.ts's rule): those pixels are dark.
    const stripe = Math.max(4, Math.round(Math.min(width, height) / 24));
    // A pixel whose right and lower neighbours share its label is not on a boundary.
    let checked = 0;
    for (let y = 0; y + 1 < height; y++) {
      for (let x = 0; x + 1 < width; x++) {
        const k = y * width + x;
        if (layer.labels[k] !== record.label || layer.labels[k + 1] !== record.label || layer.labels[k + width] !== record.label) continue;
        if (record.scutoid && (x + y) % stripe === 0) {
          expect(Array.from(rgba.subarray(4 * k, 4 * k + 3))).toEqual([20, 20, 20]);
          continue;
        }
        expect(Array.from(rgba.subarray(4 * k, 4 * k + 3))).toEqual(RGB[sideColorIndex(record.sides[0])]);
        checked++;
      }
    }
    expect(checked).toBeGreaterThan(0);
    const picked = withSelected({ ...layer, name: 'basal', rgba }, record.label, true);
    let white = 0;
    for (let k = 0; k < width * height; k++) if (picked[4 * k] === 255 && picked[4 * k + 1] === 255 && picked[4 * k + 2] === 255) white++;
    const inner = layer.labels.filter((v) => v === record.label).length;
    expect(white).toBeGreaterThan(0);
    expect(white).toBeLessThanOrEqual(inner);
    // The unpicked picture is untouched.
    expect(rgba).not.toBe(picked);
  });
});
