import { describe, expect, it } from 'vitest';
import { decode } from 'tiff';
import { encode } from 'fast-png';
import {
  decodePngLabels,
  decodeTiffPage,
  inspectLabelFile,
  MAX_LAYER_PIXELS,
  MeasureInputError,
  measureTissue,
  micronsPerUnit,
  parseImageJDescription,
  tiffCalibration,
} from '../../src/core/measure';
import { lzwEncode, writeTiff } from './tiffWriter';
import { hexLattice, memoryFile, png16, rasterizeVoronoi } from './images';

const problemOf = (f: () => unknown): string => {
  try {
    f();
  } catch (error) {
    if (error instanceof MeasureInputError) return error.message;
    throw error;
  }
  throw new Error('no error');
};

describe('TIFF decoding through the tiff package', () => {
  it('round-trips 16-bit LZW strips long enough to reset the code table', () => {
    const width = 300;
    const height = 200;
    const data = new Uint16Array(width * height);
    let s = 12345;
    for (let i = 0; i < data.length; i++) {
      s = (s * 1103515245 + 12345) >>> 0;
      data[i] = i % 7 === 0 ? s >>> 16 : Math.floor(i / 97) % 500; // runs and noise
    }
    expect(lzwEncode(new Uint8Array(data.buffer)).length).toBeGreaterThan(0);
    const bytes = writeTiff([{ width, height, bitsPerSample: 16, data, compression: 5, rowsPerStrip: height }]);
    const [ifd] = decode(bytes);
    expect(ifd.compression).toBe(5);
    expect(Array.from(ifd.data as Uint16Array)).toEqual(Array.from(data));
  });

  it('keeps the stored values of a WhiteIsZero page (the decoder inverts them for display)', () => {
    const data = Uint8Array.from([0, 1, 2, 3, 250, 255]);
    const bytes = writeTiff([{ width: 3, height: 2, bitsPerSample: 8, data, photometric: 0 }]);
    const header = inspectLabelFile(bytes, 'w.tif').pages[0];
    expect(Array.from(decodeTiffPage(bytes, 'w.tif', 0, header).data)).toEqual(Array.from(data));
  });

  it('refuses non-square pixels, signed samples and 32-bit labels, naming the file', () => {
    const page = { width: 4, height: 4, bitsPerSample: 16 as const, data: new Uint16Array(16).fill(1) };
    expect(problemOf(() => inspectLabelFile(writeTiff([{ ...page, xResolution: 2, yResolution: 3, resolutionUnit: 3 }]), 'a.tif'))).toMatch(
      /^a\.tif: non-square pixels/,
    );
    expect(problemOf(() => inspectLabelFile(writeTiff([{ ...page, sampleFormat: 2 }]), 's.tif'))).toMatch(/^s\.tif: unsupported pixel type: 16-bit signed/);
    expect(problemOf(() => inspectLabelFile(writeTiff([{ ...page, bitsPerSample: 32, data: new Uint32Array(16) }]), 'l.tif'))).toMatch(
      /^l\.tif: unsupported pixel type: 32-bit labels/,
    );
    expect(problemOf(() => inspectLabelFile(Uint8Array.from([0x49, 0x49, 43, 0, 8, 0, 0, 0]), 'big.tif'))).toMatch(/BigTIFF is not supported/);
    expect(problemOf(() => inspectLabelFile(Uint8Array.from([0x49, 0x49, 42, 0, 200, 0, 0, 0]), 'cut.tif'))).toMatch(/^cut\.tif: corrupt or unsupported TIFF/);
  });
});

describe('PNG headers', () => {
  it('accepts 8-bit palette images (the index is the label) and refuses grey + alpha and 1-bit masks', () => {
    const palette = encode({
      width: 2,
      height: 2,
      data: Uint8Array.from([0, 1, 1, 2]),
      depth: 8,
      channels: 1,
      palette: [
        [0, 0, 0],
        [255, 0, 0],
        [0, 255, 0],
      ],
    });
    expect(inspectLabelFile(palette, 'p.png').pages[0]).toEqual({ width: 2, height: 2, bitsPerSample: 8 });
    expect(Array.from(decodePngLabels(palette, 'p.png').data)).toEqual([0, 1, 1, 2]);
    const greyAlpha = encode({ width: 2, height: 2, data: new Uint8Array(8), depth: 8, channels: 2 });
    expect(problemOf(() => inspectLabelFile(greyAlpha, 'ga.png'))).toMatch(/^ga\.png: unsupported pixel type: 8-bit grey with alpha/);
    const mask = encode({ width: 8, height: 1, data: Uint8Array.from([0b10101010]), depth: 1, channels: 1 }); // packed bits
    expect(problemOf(() => inspectLabelFile(mask, 'm.png'))).toMatch(/^m\.png: unsupported pixel type: 1-bit grey \(a mask, not labels\?\)/);
  });

  it('bounds the size from the header before decoding anything', () => {
    const small = png16({ width: 2, height: 2, data: Uint16Array.from([1, 2, 3, 4]) });
    const huge = small.slice();
    const view = new DataView(huge.buffer);
    view.setUint32(16, 20000); // IHDR width
    view.setUint32(20, 20000); // IHDR height (the image data is far too short: never inflated)
    expect(20000 * 20000).toBeGreaterThan(MAX_LAYER_PIXELS);
    expect(problemOf(() => inspectLabelFile(huge, 'huge.png'))).toMatch(/^huge\.png: 20000 x 20000 pixels is over the limit/);
  });
});

describe('pixel size metadata', () => {
  it('reads ImageJ units, including the escaped micro sign, and the slice spacing', () => {
    expect(micronsPerUnit('micron')).toBe(1);
    expect(micronsPerUnit('\\u00B5m')).toBe(1);
    expect(micronsPerUnit('nm')).toBe(0.001);
    expect(micronsPerUnit('pixel')).toBeNull();
    expect(parseImageJDescription('ImageJ=1.54f\nimages=4\nchannels=2\nunit=\\u00B5m\nspacing=0.3\n')).toEqual({
      unit: '\\u00B5m',
      spacing: 0.3,
      invalidSpacing: null,
      channels: 2,
      frames: 1,
    });
    // A spacing that is no distance is kept apart from an absent one (which means 1 unit).
    expect(parseImageJDescription('ImageJ=1.54f\nunit=um\nspacing=nan\n')).toMatchObject({ spacing: null, invalidSpacing: 'nan' });
    expect(parseImageJDescription('ImageJ=1.54f\nunit=um\n')).toMatchObject({ spacing: null, invalidSpacing: null });
    expect(parseImageJDescription('not ImageJ')).toBeNull();
    const c = tiffCalibration({ xResolution: 10, yResolution: 10, resolutionUnit: 1, description: 'ImageJ=1.54f\nunit=nm\nspacing=200\n' });
    expect(c.pixelSize).toMatchObject({ value: 0.0001, source: 'imagej' });
    expect(c.layerSpacing).toBeCloseTo(0.2, 12);
    expect(tiffCalibration({ xResolution: 10, yResolution: 10, resolutionUnit: 1, description: undefined }).pixelSize).toBeNull();
  });

  it('uses a resolution per inch with a warning, and refuses layers whose metadata disagree', () => {
    const hex = hexLattice(4, 4, 16);
    const image = rasterizeVoronoi(
      hex.width,
      hex.height,
      hex.sites,
      hex.sites.map((_, i) => i + 1),
      true,
    );
    const page = { width: image.width, height: image.height, bitsPerSample: 16 as const, data: image.data };
    const inch = writeTiff([{ ...page, xResolution: 25400, yResolution: 25400, resolutionUnit: 2 }]);
    const r = measureTissue([memoryFile('a.tif', inch), memoryFile('b.tif', inch)], { periodicX: true, version: 'test' });
    expect(r.inputs.pixelSize.value).toBeCloseTo(1, 12);
    expect(r.warnings.some((w) => w.includes('per inch is often a print setting'))).toBe(true);
    const other = writeTiff([{ ...page, xResolution: 2, yResolution: 2, resolutionUnit: 3 }]);
    expect(problemOf(() => measureTissue([memoryFile('a.tif', inch), memoryFile('b.tif', other)], { version: 'test' }))).toMatch(
      /^b\.tif: pixel size 5000 µm differs from 1 µm in a\.tif/,
    );
    // A hyperstack with channels is refused.
    const channels = writeTiff([{ ...page, description: 'ImageJ=1.54f\nimages=2\nchannels=2\n' }, page]);
    expect(problemOf(() => measureTissue([memoryFile('c.tif', channels)], { pixelSize: 1, version: 'test' }))).toMatch(
      /^c\.tif: an ImageJ hyperstack with 2 channels/,
    );
  });
});
