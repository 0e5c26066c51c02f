import { mkdtempSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';
import { encode } from 'fast-png';
import { describe, expect, it } from 'vitest';
import type { DensitySpec } from '../../src/core/config';
import { densityField, type GrayImage } from '../../src/core/density';
import type { Grid } from '../../src/core/grid';
import { decodeGrayPng, loadGrayImage } from '../../src/node/image';

const plane: Grid = { width: 40, height: 30, texelX: 2, texelY: 3, periodicX: false, periodicY: false };
const tube: Grid = { width: 32, height: 64, texelX: 1.5, texelY: 2, periodicX: true, periodicY: false };

/** Texel centre in µm. */
const centre = (grid: Grid, i: number, j: number) => [(i + 0.5) * grid.texelX, (j + 0.5) * grid.texelY] as const;

function expectAllPositiveFinite(field: Float32Array, grid: Grid) {
  expect(field.length).toBe(grid.width * grid.height);
  for (const v of field) expect(v > 0 && Number.isFinite(v)).toBe(true);
}

describe('densityField presets match their formulas', () => {
  it('uniform is 1 everywhere', () => {
    const field = densityField({ kind: 'uniform' }, plane);
    expectAllPositiveFinite(field, plane);
    expect(field.every((v) => v === 1)).toBe(true);
  });

  it('linear interpolates between the values at the start and end of the axis', () => {
    const lengthX = plane.width * plane.texelX;
    const lengthY = plane.height * plane.texelY;
    for (const spec of [
      { kind: 'linear', axis: 'x', from: 2, to: 10 },
      { kind: 'linear', axis: 'y', from: 5, to: 0.5 },
    ] as const) {
      const field = densityField(spec, plane);
      expectAllPositiveFinite(field, plane);
      for (const [i, j] of [
        [0, 0],
        [39, 29],
        [7, 13],
        [20, 3],
      ]) {
        const [u, v] = centre(plane, i, j);
        const t = spec.axis === 'x' ? u / lengthX : v / lengthY;
        expect(field[j * plane.width + i]).toBeCloseTo(spec.from + (spec.to - spec.from) * t, 5);
      }
    }
  });

  it('gaussian follows 1 + (peak-1) exp(-r²/2σ²) with r measured across the seam', () => {
    const lengthX = tube.width * tube.texelX;
    const spec: DensitySpec = { kind: 'gaussian', center: [1, 60], sigma: 7, peak: 9 };
    const field = densityField(spec, tube);
    expectAllPositiveFinite(field, tube);
    for (let j = 0; j < tube.height; j += 5) {
      for (let i = 0; i < tube.width; i += 3) {
        const [u, v] = centre(tube, i, j);
        // Nearest periodic image of the centre, found by brute force over shifts.
        const du = Math.min(...[-1, 0, 1].map((k) => Math.abs(u - 1 + k * lengthX)));
        const r2 = du * du + (v - 60) ** 2;
        expect(field[j * tube.width + i]).toBeCloseTo(1 + 8 * Math.exp(-r2 / 98), 5);
      }
    }
    // Across the seam: the last texel (1.75 µm from the centre through the seam) is much denser
    // than a texel half-way round, and a little less dense than texel 1 (1.25 µm away).
    const row = Math.floor(60 / tube.texelY);
    const seam = field[row * tube.width + (tube.width - 1)];
    expect(field[row * tube.width + 1]).toBeGreaterThan(seam);
    expect(seam).toBeGreaterThan(5 * field[row * tube.width + tube.width / 2]);
  });

  it('gaussian with peak < 1 is a dip that stays positive', () => {
    const field = densityField({ kind: 'gaussian', center: [40, 45], sigma: 10, peak: 0.1 }, plane);
    expectAllPositiveFinite(field, plane);
    expect(Math.min(...field)).toBeGreaterThanOrEqual(0.1 - 1e-6);
  });

  it('stripes: low on the first half of each period, high on the second', () => {
    const lengthY = tube.height * tube.texelY;
    // One period over the whole axis: the first half of the tube is low, the second high.
    const halves = densityField({ kind: 'stripes', axis: 'y', period: lengthY, low: 1, high: 4 }, tube);
    expectAllPositiveFinite(halves, tube);
    for (let j = 0; j < tube.height; j++) {
      for (let i = 0; i < tube.width; i++) expect(halves[j * tube.width + i]).toBe(j < tube.height / 2 ? 1 : 4);
    }
    const period = 12;
    const field = densityField({ kind: 'stripes', axis: 'x', period, low: 2, high: 3 }, plane);
    for (let i = 0; i < plane.width; i++) {
      const [u] = centre(plane, i, 0);
      const expected = u % period < period / 2 ? 2 : 3;
      expect(field[5 * plane.width + i]).toBe(expected);
    }
  });
});

describe('densityField from an image', () => {
  const image: GrayImage = { width: 4, height: 3, luminance: Float32Array.from([0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1, 0.25]) };

  it('maps pixel to texel one to one when sizes match, top row at y = height', () => {
    const grid: Grid = { width: 4, height: 3, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const field = densityField({ kind: 'image', src: 'x.png', low: 1, high: 11, invert: false }, grid, image);
    for (let j = 0; j < 3; j++) {
      for (let i = 0; i < 4; i++) {
        expect(field[j * 4 + i]).toBeCloseTo(1 + 10 * image.luminance[(2 - j) * 4 + i], 5);
      }
    }
    const inverted = densityField({ kind: 'image', src: 'x.png', low: 1, high: 11, invert: true }, grid, image);
    for (let k = 0; k < 12; k++) expect(field[k] + inverted[k]).toBeCloseTo(12, 5);
  });

  it('interpolates bilinearly and clamps on open axes', () => {
    // 2 x 1 image, black then white, stretched over 8 texels: pixel centres at texel x = 2 and 6.
    const ramp: GrayImage = { width: 2, height: 1, luminance: Float32Array.from([0, 1]) };
    const grid: Grid = { width: 8, height: 2, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    const field = densityField({ kind: 'image', src: 'r.png', low: 2, high: 6, invert: false }, grid, ramp);
    for (let i = 0; i < 8; i++) {
      const x = i + 0.5;
      const t = Math.min(1, Math.max(0, (x - 2) / 4));
      expect(field[i]).toBeCloseTo(2 + 4 * t, 5);
      expect(field[8 + i]).toBeCloseTo(field[i], 6);
    }
    // Periodic x wraps: beyond the last pixel centre it blends back towards the first.
    const wrapped = densityField({ kind: 'image', src: 'r.png', low: 2, high: 6, invert: false }, { ...grid, periodicX: true }, ramp);
    expect(wrapped[7]).toBeLessThan(6);
    expect(wrapped[0]).toBeCloseTo(2 + 4 * (1 - 2.5 / 4), 5);
    expect(wrapped[7]).toBeCloseTo(2 + 4 * (1 - 1.5 / 4), 5);
  });

  it('refuses a missing or inconsistent image', () => {
    const grid: Grid = { width: 4, height: 4, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
    expect(() => densityField({ kind: 'image', src: 'a.png', low: 1, high: 2, invert: false }, grid)).toThrow(/a\.png/);
    const bad = { width: 3, height: 3, luminance: new Float32Array(4) };
    expect(() => densityField({ kind: 'image', src: 'a.png', low: 1, high: 2, invert: false }, grid, bad)).toThrow(/inconsistent/);
  });
});

describe('loadGrayImage', () => {
  const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-image-'));

  it('reads a PNG with Rec. 709 luminance, ignoring alpha', () => {
    const pixels = [
      [255, 255, 255, 0],
      [0, 0, 0, 255],
      [255, 0, 0, 255],
      [0, 255, 0, 128],
      [0, 0, 255, 255],
      [100, 150, 200, 255],
    ];
    const path = join(dir, 'test.png');
    writeFileSync(path, encode({ width: 3, height: 2, data: Uint8Array.from(pixels.flat()), depth: 8, channels: 4 }));
    const image = loadGrayImage(path);
    expect([image.width, image.height]).toEqual([3, 2]);
    pixels.forEach(([r, g, b], k) => {
      expect(image.luminance[k]).toBeCloseTo(Math.min(1, (0.2126 * r + 0.7152 * g + 0.0722 * b) / 255), 6);
    });
    expect(image.luminance[0]).toBeLessThanOrEqual(1);
    expect(image.luminance[0]).toBeCloseTo(1, 6);
  });

  it('reads every sample layout as its grey level: 16-bit grey, grey with alpha, palette, 2-bit grey', () => {
    const cases: [string, Uint8Array, number[]][] = [
      ['16-bit grey', encode({ width: 3, height: 1, data: Uint16Array.from([0, 32768, 65535]), depth: 16, channels: 1 }), [0, 32768 / 65535, 1]],
      ['grey + alpha', encode({ width: 2, height: 1, data: Uint8Array.from([51, 0, 204, 255]), depth: 8, channels: 2 }), [0.2, 0.8]],
      [
        'palette',
        encode({
          width: 3,
          height: 1,
          data: Uint8Array.from([2, 0, 1]),
          depth: 8,
          channels: 1,
          palette: [
            [255, 0, 0],
            [0, 255, 0],
            [10, 20, 30],
          ],
        }),
        [(0.2126 * 10 + 0.7152 * 20 + 0.0722 * 30) / 255, 0.2126, 0.7152],
      ],
      // 5 pixels of 2 bits in one row (0b00 01 10 11, then 0b01 and padding): levels 0..3 of 3.
      [
        '2-bit grey',
        encode({ width: 5, height: 2, data: Uint8Array.from([0b00011011, 0b01000000, 0b11111111, 0b11000000]), depth: 2, channels: 1 }),
        [0, 1 / 3, 2 / 3, 1, 1 / 3, 1, 1, 1, 1, 1],
      ],
    ];
    for (const [name, bytes, expected] of cases) {
      const image = decodeGrayPng(bytes, name);
      expect(Array.from(image.luminance).length, name).toBe(expected.length);
      expected.forEach((v, k) => expect(image.luminance[k], `${name} pixel ${k}`).toBeCloseTo(v, 5));
    }
  });

  it('refuses non-PNG and missing files with a clear message', () => {
    const path = join(dir, 'fake.jpg');
    writeFileSync(path, Buffer.from([0xff, 0xd8, 0xff, 0xe0, 1, 2, 3, 4, 5, 6]));
    expect(() => loadGrayImage(path)).toThrow(/not a PNG/);
    expect(() => loadGrayImage(join(dir, 'nope.png'))).toThrow(/cannot read/);
    const corrupt = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a, 0, 0, 0]);
    expect(() => decodeGrayPng(corrupt, 'c.png')).toThrow(/corrupt PNG/);
  });
});
