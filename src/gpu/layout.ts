import type * as THREE from 'three';
import { LAYOUTS, maxResolution, type SurfaceLayoutName } from '../core/config/surfaceLayout';
import { cubeFaceHops, texelEdgeTable } from '../core/cubemap/cubemap';
import type { Grid } from '../core/grid';
import { accumulateCentroidRows } from '../core/labels';
import cubeMetric from '../shaders/cubeMetric.glsl';
import gridMetric from '../shaders/gridMetric.glsl';

/**
 * Values per site in GpuEngine.sums: w·dx, w·dy, w·dz, w, w·|d|², with d the metric's offset
 * from the site to a texel's point (texel units on a grid, dz = 0; µm on a cube map) and |d|²
 * in µm².
 */
export const SUMS_STRIDE = 5;

/**
 * How a surface's geometry image is laid out for the GPU engine, as data: the atlas size, the
 * metric (a GLSL chunk with its defines and uniforms, which gives every pass the surface's
 * texel points, weights, offsets, distances and neighbour steps with their wraps and seams),
 * the site coordinates and the CPU's reduction of read-back ids. The planar grid and the cube
 * map are its two instances; the engine never asks which one it has.
 */
export interface TexelLayout {
  readonly family: SurfaceLayoutName;
  readonly width: number;
  readonly height: number;
  /** Coordinates per site: 2 (grid, texel units) or 3 (cube map, µm; plus its atlas texel). */
  readonly dimensions: 2 | 3;
  /** The sides a cold flood must span (the grid; one cube face). */
  readonly floodWidth: number;
  readonly floodHeight: number;
  /** Steps of floodWidth a cold flood of these sites (GpuEngine's siteData) needs first (cube map: cubeFaceHops). */
  floodHops?(sites: Float32Array, count: number): number;
  readonly metric: string;
  readonly defines: Record<string, number>;
  readonly uniforms: Record<string, THREE.IUniform>;
  /** Floats per texel of the geometry: 1 (weight; the grid's points are its texel centres) or 4 (point xyz, weight). */
  readonly geometryChannels: 1 | 4;
  /** The grid, where the layout is one (sizes the gather path's windows; null on a cube map). */
  readonly grid: Grid | null;
  /** Factor from summed energy to the CVT energy (µm⁴ x density): the grid's weights are per texel. */
  readonly energyScale: number;
  /** Why this GPU cannot hold the atlas (null when it can). */
  tooLarge(maxTextureSize: number): string | null;
  /**
   * Adds one band of read-back ids (rows firstRow .. firstRow + rows - 1) to `sums`
   * (SUMS_STRIDE, float64), against the float32 sites (stride 4) and geometry the GPU used;
   * `geometry` null means every weight is 1.
   */
  accumulate(ids: Int32Array, firstRow: number, rows: number, sites: Float32Array, geometry: Float32Array | null, count: number, sums: Float64Array): void;
}

/** A planar-family grid (plane, tube, torus): texel centres, minimum image on periodic axes. */
export function gridLayout(grid: Grid): TexelLayout {
  let band = new Float64Array(0);
  return {
    family: 'planar grid',
    width: grid.width,
    height: grid.height,
    dimensions: 2,
    floodWidth: grid.width,
    floodHeight: grid.height,
    metric: gridMetric,
    defines: { PERIODIC_X: grid.periodicX ? 1 : 0, PERIODIC_Y: grid.periodicY ? 1 : 0, SPLIT_ENERGY: 0 },
    uniforms: { texelSize: { value: { x: grid.texelX, y: grid.texelY } }, aspect: { value: grid.texelY / grid.texelX } },
    geometryChannels: 1,
    grid,
    energyScale: grid.texelX * grid.texelY,
    tooLarge: (max) =>
      grid.width > max || grid.height > max
        ? `resolution: the grid is ${grid.width} x ${grid.height} texels but this GPU allows at most ${max} per side; lower resolution`
        : null,
    accumulate(ids, firstRow, rows, sites, geometry, count, sums) {
      // accumulateCentroidRows sums runs of equal ids (4 values a site); spread them to SUMS_STRIDE.
      if (band.length !== 4 * count) band = new Float64Array(4 * count);
      else band.fill(0);
      accumulateCentroidRows(grid, ids, firstRow, rows, sites, count, geometry, band);
      for (let i = 0; i < count; i++) {
        const o = SUMS_STRIDE * i;
        sums[o] += band[4 * i];
        sums[o + 1] += band[4 * i + 1];
        sums[o + 3] += band[4 * i + 2];
        sums[o + 4] += band[4 * i + 3];
      }
    },
  };
}

/** A cube-map geometry image of n x n texels per face (a closed surface), n x 6n atlas. */
export function cubeLayout(n: number): TexelLayout {
  return {
    family: 'cube map',
    width: n,
    height: 6 * n,
    dimensions: 3,
    floodWidth: n,
    floodHeight: n,
    floodHops: (sites, count) => cubeFaceHops(n, sites, count),
    metric: cubeMetric,
    defines: { SPLIT_ENERGY: 1 },
    uniforms: { edgeTable: { value: Array.from(texelEdgeTable(n)) } },
    geometryChannels: 4,
    grid: null,
    energyScale: 1,
    tooLarge: (max) =>
      6 * n > max
        ? `resolution: the cube map is ${n} x ${6 * n} texels (6 faces of ${n}²) but this GPU allows at most ${max} per side; lower resolution to at most ${maxResolution(LAYOUTS['cube map'], max)}`
        : null,
    accumulate(ids, firstRow, rows, sites, geometry, count, sums) {
      const g = geometry!;
      for (let t = 0, k = firstRow * n; t < rows * n; t++, k++) {
        const id = ids[t];
        if (id < 0) continue;
        const w = g[4 * k + 3];
        const dx = g[4 * k] - sites[4 * id];
        const dy = g[4 * k + 1] - sites[4 * id + 1];
        const dz = g[4 * k + 2] - sites[4 * id + 2];
        const o = SUMS_STRIDE * id;
        sums[o] += w * dx;
        sums[o + 1] += w * dy;
        sums[o + 2] += w * dz;
        sums[o + 3] += w;
        sums[o + 4] += w * (dx * dx + dy * dy + dz * dz);
      }
    },
  };
}
