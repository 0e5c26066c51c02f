/**
 * Density images in the page (src/view/imageHeader.ts): the size is read from the header and
 * bounded before decoding; a PNG cut short before IEND is refused, never decoded as black.
 * PNGs are built here from the PNG specification (chunks: length, type, data, CRC).
 */
import { deflateSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import { encode } from 'fast-png';
import { ImageHeaderError, PAGE_MAX_IMAGE_PIXELS, readImageSize } from '../../src/view/imageHeader';

function encodePng(width: number, height: number): Uint8Array {
  return encode({ width, height, data: new Uint8Array(4 * width * height).fill(128), depth: 8, channels: 4 });
}

/** A PNG whose IHDR declares width x height but whose data is tiny (what an attacker sends). */
function lyingPng(width: number, height: number): Uint8Array {
  const real = encodePng(1, 1);
  const out = new Uint8Array(real);
  new DataView(out.buffer).setUint32(16, width);
  new DataView(out.buffer).setUint32(20, height);
  return out;
}

function jpegHeader(width: number, height: number, withEnd = true): Uint8Array {
  // SOI, APP0 (length 16), SOF0 (length 17: precision, height, width, 3 components), ..., EOI
  const app0 = [0xff, 0xe0, 0x00, 0x10, ...new Array(14).fill(0)];
  const sof = [0xff, 0xc0, 0x00, 0x11, 8, height >> 8, height & 255, width >> 8, width & 255, 3, ...new Array(9).fill(0)];
  return new Uint8Array([0xff, 0xd8, ...app0, ...sof, 0xff, 0xda, 0x00, 0x02, ...(withEnd ? [0xff, 0xd9] : [])]);
}

const errorOf = (f: () => unknown) => {
  try {
    f();
  } catch (error) {
    expect(error).toBeInstanceOf(ImageHeaderError);
    expect((error as Error).message).not.toContain('\n');
    return (error as Error).message;
  }
  throw new Error('expected a refusal');
};

describe('readImageSize', () => {
  it('reads the size of a real PNG (fast-png-encoded) and of a JPEG frame header', () => {
    expect(readImageSize(encodePng(37, 11), 'x')).toEqual({ format: 'png', width: 37, height: 11 });
    expect(readImageSize(jpegHeader(640, 480), 'x')).toEqual({ format: 'jpeg', width: 640, height: 480 });
  });

  it('refuses a header over the pixel limit before decoding, naming the size and the limit', () => {
    const message = errorOf(() => readImageSize(lyingPng(20000, 20000), 'density.src: density image big.png'));
    expect(message).toBe(
      `density.src: density image big.png: 20000 x 20000 pixels is more than the ${PAGE_MAX_IMAGE_PIXELS} the page decodes; downscale it (the density is stretched over the grid anyway)`,
    );
    expect(errorOf(() => readImageSize(jpegHeader(5000, 5000), 'j'))).toContain('5000 x 5000 pixels');
    // At the limit exactly: accepted.
    const side = Math.sqrt(PAGE_MAX_IMAGE_PIXELS);
    expect(readImageSize(lyingPng(side, side), 'x').width).toBe(side);
  });

  it('refuses a PNG cut anywhere before its IEND chunk as truncated', () => {
    const whole = encodePng(64, 64);
    for (const cut of [40, Math.floor(whole.length / 2), whole.length - 1]) {
      expect(errorOf(() => readImageSize(whole.subarray(0, cut), 'd'))).toMatch(/^d: truncated PNG \(the file ends at byte \d+, before its IEND chunk\)/);
    }
    expect(errorOf(() => readImageSize(whole.subarray(0, 20), 'd'))).toMatch(/truncated or corrupt PNG \(no IHDR header\)/);
  });

  it('refuses a PNG with no image data, a truncated JPEG, an empty file and other formats', () => {
    const sig = [0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a];
    const ihdr = encodePng(2, 2).subarray(8, 33);
    const iend = [0, 0, 0, 0, 0x49, 0x45, 0x4e, 0x44, 0xae, 0x42, 0x60, 0x82];
    expect(errorOf(() => readImageSize(new Uint8Array([...sig, ...ihdr, ...iend]), 'd'))).toContain('no image data');
    expect(errorOf(() => readImageSize(jpegHeader(10, 10, false), 'd'))).toContain('truncated JPEG');
    expect(errorOf(() => readImageSize(new Uint8Array(), 'd'))).toBe('d: the file is empty; give a PNG or JPEG image');
    expect(errorOf(() => readImageSize(new TextEncoder().encode('GIF89a....'), 'd'))).toContain('not a PNG or JPEG');
    expect(errorOf(() => readImageSize(deflateSync(new Uint8Array(10)), 'd'))).toContain('not a PNG or JPEG');
  });
});
