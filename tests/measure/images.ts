/** Synthetic label images for the measure tests, and writers for them. */
import { encode } from 'fast-png';
import type { LabelFileInput } from '../../src/core/measure';
import { MeasureInputError } from '../../src/core/measure';

export interface LabelImage {
  width: number;
  height: number;
  data: Uint16Array;
}

/**
 * Nearest-site labels (pixel centres, Euclidean, minimum image in x when periodicX), label of
 * site i = labels[i]. Brute force: the tests keep images small.
 */
export function rasterizeVoronoi(width: number, height: number, sites: number[][], labels: number[], periodicX: boolean): LabelImage {
  const data = new Uint16Array(width * height);
  for (let y = 0; y < height; y++) {
    for (let x = 0; x < width; x++) {
      let best = Infinity;
      let bestId = -1;
      for (let i = 0; i < sites.length; i++) {
        let dx = Math.abs(x + 0.5 - sites[i][0]);
        if (periodicX) dx = Math.min(dx, width - dx);
        const dy = y + 0.5 - sites[i][1];
        const d = dx * dx + dy * dy;
        if (d < best - 1e-9) {
          best = d;
          bestId = i;
        }
      }
      data[y * width + x] = labels[bestId];
    }
  }
  return { width, height, data };
}

/**
 * A hexagonal lattice of `columns` x `rows` sites with spacing `a` px, periodic in x when the
 * image is columns * a wide; odd rows shifted by a/2. Returns the sites and, for each site, its
 * six lattice neighbours (those that exist), by site index.
 */
export function hexLattice(columns: number, rows: number, a: number): { sites: number[][]; neighbours: number[][]; width: number; height: number } {
  const h = (a * Math.sqrt(3)) / 2;
  const sites: number[][] = [];
  for (let j = 0; j < rows; j++) for (let i = 0; i < columns; i++) sites.push([(i + 0.25 + 0.5 * (j % 2)) * a, (j + 0.5) * h]);
  const index = (i: number, j: number) => j * columns + (((i % columns) + columns) % columns);
  const neighbours = sites.map((_, s) => {
    const i = s % columns;
    const j = Math.floor(s / columns);
    // Same row: i +- 1; rows j +- 1: columns i, i+1 (odd rows, shifted right) or i-1, i (even rows).
    const shift = j % 2 === 1 ? [0, 1] : [-1, 0];
    const list = [index(i - 1, j), index(i + 1, j)];
    for (const dj of [-1, 1]) if (j + dj >= 0 && j + dj < rows) for (const di of shift) list.push(index(i + di, j + dj));
    return list.sort((p, q) => p - q);
  });
  return { sites, neighbours, width: columns * a, height: Math.ceil(rows * h) };
}

/** Stretches an image horizontally by an integer factor (nearest neighbour). */
export function stretchX(image: LabelImage, factor: number): LabelImage {
  const width = image.width * factor;
  const data = new Uint16Array(width * image.height);
  for (let y = 0; y < image.height; y++) for (let x = 0; x < width; x++) data[y * width + x] = image.data[y * image.width + Math.floor(x / factor)];
  return { width, height: image.height, data };
}

export function png16(image: LabelImage): Uint8Array {
  return encode({ width: image.width, height: image.height, data: image.data, depth: 16, channels: 1 });
}

/** 8-bit grey PNG (labels must be < 256). */
export function png8(image: LabelImage): Uint8Array {
  return encode({ width: image.width, height: image.height, data: Uint8Array.from(image.data), depth: 8, channels: 1 });
}

/** An in-memory input file. */
export function memoryFile(name: string, bytes: Uint8Array): LabelFileInput {
  return { name, read: () => bytes };
}

export function missingFile(name: string): LabelFileInput {
  return {
    name,
    read() {
      throw new MeasureInputError(name, 'no such file');
    },
  };
}

/** Deterministic pseudo-random sites (mulberry32). */
export function randomSites(count: number, width: number, height: number, seed: number): number[][] {
  let s = seed >>> 0;
  const next = () => {
    s = (s + 0x6d2b79f5) >>> 0;
    let t = s;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
  return Array.from({ length: count }, () => [next() * width, next() * height]);
}
