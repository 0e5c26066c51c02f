/**
 * The page's drawing of a measured volume (src/view/volumeSurfaces.ts) on a synthetic shell
 * (tests/measure/volumes.ts): each drawn triangle belongs to the cell of the nearest voxel with a
 * face on that surface (checked by brute force over every voxel), each cell's drawn share of the
 * surface follows its measured area, the triangle budget holds, and a picked cell's shape
 * encloses its measured volume.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { LUMEN, measureVolume, OUTSIDE, type ClassifiedVolume, type VolumeMeasuredResult } from '../../src/core/measure';
import { signedVolume } from '../../src/core/mesh/types';
import { cellShape, drawSurface } from '../../src/view/volumeSurfaces';
import { writeTiff } from '../measure/tiffWriter';
import { labelData, permutedLabels, shellVolume, volumePages } from '../measure/volumes';

let result: VolumeMeasuredResult;
let voxels: ClassifiedVolume;

beforeAll(() => {
  const shell = shellVolume({ voxel: { x: 0.5, y: 0.5, z: 0.75 }, a: 9, b: 8, c: 7, h: 3, sites: 24, seed: 2, margin: 2 });
  const labels = permutedLabels(24, 3, 7, 5);
  const bytes = writeTiff(volumePages(shell, labelData(shell, labels, 16), 16) as never);
  result = measureVolume({ name: 'shell.tif', read: () => bytes }, { voxelSize: shell.voxel, version: 'test', onVoxels: (v) => (voxels = v) });
});

/** Every triangle's centre, and the cell of the nearest surface voxel found by scanning the whole volume. */
function bruteForceCell(v: ClassifiedVolume, background: number, x: number, y: number, z: number): { cell: number; distance: number } {
  const { width: W, height: H, depth: D, voxelSize: s } = v;
  const { ids, classes } = v.classes;
  const at = (i: number, j: number, k: number) => (i < 0 || j < 0 || k < 0 || i >= W || j >= H || k >= D ? -1 : classes[(k * H + j) * W + i]);
  let best = { cell: -1, distance: Infinity };
  for (let k = 0; k < D; k++)
    for (let j = 0; j < H; j++)
      for (let i = 0; i < W; i++) {
        const id = ids[(k * H + j) * W + i];
        if (id === 0) continue;
        const faces = [at(i - 1, j, k), at(i + 1, j, k), at(i, j - 1, k), at(i, j + 1, k), at(i, j, k - 1), at(i, j, k + 1)].includes(background);
        if (!faces) continue;
        const d = Math.hypot((i + 0.5) * s.x - x, (j + 0.5) * s.y - y, (k + 0.5) * s.z - z);
        if (d < best.distance) best = { cell: id - 1, distance: d };
      }
  return best;
}

describe('a measured volume drawn in the page', () => {
  it('colours each triangle by the nearest voxel on its own surface (brute force), and each cell covers its measured share', () => {
    for (const [k, layer] of result.inputs.layers.entries()) {
      const surface = drawSurface(voxels, layer.name, layer.faces, layer.area);
      const triangles = surface.cells.length;
      expect(triangles).toBeGreaterThan(100);
      const background = layer.faces === 'outside' ? OUTSIDE : LUMEN;
      // A sample of triangles against the brute force (every 37th): the same cell, or a tie in distance.
      let checked = 0;
      for (let f = 0; f < triangles; f += 37) {
        const p = surface.positions;
        const c = [0, 1, 2].map((axis) => (p[9 * f + axis] + p[9 * f + 3 + axis] + p[9 * f + 6 + axis]) / 3);
        const brute = bruteForceCell(voxels, background, c[0], c[1], c[2]);
        if (brute.cell !== surface.cells[f]) {
          // A tie: the drawn cell's nearest surface voxel is as near.
          const other = result.cells[surface.cells[f]];
          expect(other.areas[k]).toBeGreaterThan(0);
        } else checked++;
      }
      expect(checked).toBeGreaterThan((0.9 * triangles) / 37);
      // Drawn area per cell against the measured area on that layer (voxel faces, up to ~1.5x too large, the same for all).
      const drawn = new Float64Array(result.cells.length);
      const p = surface.positions;
      for (let f = 0; f < triangles; f++) {
        const u = [0, 1, 2].map((a) => p[9 * f + 3 + a] - p[9 * f + a]);
        const w = [0, 1, 2].map((a) => p[9 * f + 6 + a] - p[9 * f + a]);
        drawn[surface.cells[f]] += 0.5 * Math.hypot(u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2], u[0] * w[1] - u[1] * w[0]);
      }
      const totalDrawn = drawn.reduce((a, b) => a + b, 0);
      const totalMeasured = result.cells.reduce((a, c) => a + c.areas[k], 0);
      for (const cell of result.cells) {
        const measuredShare = cell.areas[k] / totalMeasured;
        if (measuredShare < 0.5 / result.cells.length) continue;
        expect(drawn[cell.id] / totalDrawn).toBeGreaterThan(measuredShare / 1.6);
        expect(drawn[cell.id] / totalDrawn).toBeLessThan(measuredShare * 1.6);
      }
    }
  });

  it('keeps a large surface under the triangle budget by coarser blocks', () => {
    const layer = result.inputs.layers[0];
    const fine = drawSurface(voxels, layer.name, layer.faces, layer.area);
    const coarse = drawSurface(voxels, layer.name, layer.faces, layer.area, 1500);
    expect(coarse.spacing).toBeGreaterThan(fine.spacing);
    expect(coarse.cells.length).toBeLessThanOrEqual(1500);
    expect(coarse.cells.length).toBeLessThan(fine.cells.length);
  });

  it("draws a picked cell's own voxels as a closed surface enclosing its measured volume", () => {
    for (const cell of result.cells.filter((c) => c.valid).slice(0, 3)) {
      const shape = cellShape(voxels, cell.id);
      // Closed and oriented: each directed edge is used as often as its reverse (surface nets can
      // join four triangles at an edge where voxels touch along it).
      const edges = new Map<string, number>();
      for (let f = 0; f < shape.indices.length; f += 3)
        for (let e = 0; e < 3; e++) {
          const key = `${shape.indices[f + e]},${shape.indices[f + ((e + 1) % 3)]}`;
          edges.set(key, (edges.get(key) ?? 0) + 1);
        }
      for (const [key, count] of edges) {
        const [a, b] = key.split(',');
        expect(edges.get(`${b},${a}`)).toBe(count);
      }
      const enclosed = signedVolume(shape);
      expect(enclosed).toBeGreaterThan(0.75 * cell.volume);
      expect(enclosed).toBeLessThan(1.1 * cell.volume);
    }
  });
});
