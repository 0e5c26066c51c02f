/**
 * The small surfaces the GPU check floods, each with its independent CPU references: the exact
 * nearest site of every texel (tests/oracles: bucketed brute force in float64 over the float32
 * sites the GPU sees), the centroid sums of any label image, and the float64 distance from a
 * texel to a site (to tell a tie from an error). Planar grids (plane, tube) and cube maps
 * (sphere, ellipsoid, a mesh).
 */
import { readFileSync } from 'node:fs';
import { placeClosedSites } from '../../src/core/closed/geometry';
import { ellipsoidProjector, meshProjector, sphereProjector, type ClosedProjector } from '../../src/core/closed/projector';
import { sampleSurface, type CubeGeometryImage } from '../../src/core/cubemap/sample';
import type { Grid } from '../../src/core/grid';
import { placeSites } from '../../src/core/sites';
import { SUMS_STRIDE, type GpuEngine } from '../../src/gpu/engine';
import { cubeLayout, gridLayout, type TexelLayout } from '../../src/gpu/layout';
import { prepareMesh } from '../../src/run/closedMesh';
import { cubeBruteForceLabels, cubeReduceCentroids } from '../../tests/oracles/cubeMap';
import { bruteForceLabels, reduceCentroids } from '../../tests/oracles/labels';

/** One flood case: a surface, its sites, and what the GPU's labels and sums are compared with. */
export interface FloodCase {
  readonly name: string;
  readonly family: 'planar' | 'cube';
  readonly layout: TexelLayout;
  readonly texels: number;
  readonly sites: number;
  /** Largest |coordinate| (µm) a float32 distance is computed from: sets the tie tolerance. */
  readonly scale: number;
  /** A texel's edge (µm): the unit of the worst label error. */
  readonly texelEdge: number;
  /** Uploads the case's geometry (weights; cube-map points) and sites. */
  upload(engine: GpuEngine): void;
  /** Exact nearest-site labels (ties: smaller id). */
  reference(): Int32Array;
  /** Float64 distance (µm) from texel k's point to site `id` (its float32 coordinates). */
  distance(k: number, id: number): number;
  /** Centroid sums of a label image, SUMS_STRIDE per site (the engine's order), float64. */
  sums(labels: Int32Array): Float64Array;
  /** A cell's size for relative centroid errors: sqrt of its texels (grid, texel units) or of its area (cube map, µm). */
  cellSize(sums: Float64Array, texels: number, id: number): number;
}

// Two sites in one texel cannot both be splatted (one owns the texel, the other no texel at all):
// keep sites 1.5 texels apart, as tests/gpu does, so that every error counted is the flood's.
const MIN_SPACING_TEXELS = 1.5;

/** A smooth positive weight (density) in [0.5, 1.5], for the weighted centroid cases. */
function wavyWeights(grid: Grid): Float32Array {
  const w = new Float32Array(grid.width * grid.height);
  for (let j = 0; j < grid.height; j++)
    for (let i = 0; i < grid.width; i++)
      w[j * grid.width + i] = 1 + 0.5 * Math.sin((2 * Math.PI * (i + 0.5)) / grid.width) * Math.cos((Math.PI * (j + 0.5)) / grid.height);
  return w;
}

/** A planar-grid case; `weighted` adds a density (the engine's setGeometry path). */
export function planarCase(kind: 'plane' | 'tube', width: number, height: number, count: number, seed: number, weighted: boolean): FloodCase {
  // The tube's texels are a little anisotropic (circumference and length resolved differently).
  const grid: Grid =
    kind === 'tube'
      ? { width, height, texelX: 0.98, texelY: 1, periodicX: true, periodicY: false }
      : { width, height, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
  const sites = placeSites(grid, count, seed, MIN_SPACING_TEXELS * grid.texelX);
  const weights = weighted ? wavyWeights(grid) : null;
  const image = (x: number, length: number, periodic: boolean) => (periodic ? x - length * Math.round(x / length) : x);
  return {
    name: `${kind} ${width}x${height}${weighted ? ' weighted' : ''}`,
    family: 'planar',
    layout: gridLayout(grid),
    texels: width * height,
    sites: count,
    scale: Math.max(width * grid.texelX, height * grid.texelY),
    texelEdge: Math.min(grid.texelX, grid.texelY),
    upload(engine) {
      if (weights) engine.setGeometry(weights);
      engine.setSites(sites);
    },
    reference: () => bruteForceLabels(grid, sites),
    distance(k, id) {
      const dx = image((k % width) + 0.5 - sites[2 * id], width, grid.periodicX) * grid.texelX;
      const dy = image(Math.floor(k / width) + 0.5 - sites[2 * id + 1], height, grid.periodicY) * grid.texelY;
      return Math.hypot(dx, dy);
    },
    sums(labels) {
      const four = reduceCentroids(grid, labels, sites, weights);
      const out = new Float64Array(SUMS_STRIDE * count);
      for (let i = 0; i < count; i++) [0, 1, 3, 4].forEach((to, from) => (out[SUMS_STRIDE * i + to] = four[4 * i + from]));
      return out;
    },
    cellSize: (_sums, texels) => Math.sqrt(texels),
  };
}

export type ClosedKind = 'sphere' | 'ellipsoid' | 'mesh';

/** The closed surfaces of the check: a sphere R 50 µm, a 2:1:1 ellipsoid, the egg-chamber mesh × 45. */
function closedSurface(kind: ClosedKind, n: number, meshPath: string): { image: CubeGeometryImage; projector: ClosedProjector } {
  if (kind === 'sphere') return { image: sampleSurface({ kind: 'sphere', radius: 50 }, n), projector: sphereProjector(50) };
  if (kind === 'ellipsoid') return { image: sampleSurface({ kind: 'ellipsoid', a: 60, b: 30, c: 30 }, n), projector: ellipsoidProjector(60, 30, 30) };
  const bytes = readFileSync(meshPath);
  const data = bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer;
  const mesh = prepareMesh({ data, name: meshPath }, { kind: 'mesh', src: meshPath, scale: 45, geodesic: false }, n);
  return { image: mesh.image, projector: meshProjector(mesh.mesh, mesh.parameterization.sphere) };
}

/** A cube-map case: n texels per face edge; the geometry is the surface's points and texel areas. */
export function cubeCase(kind: ClosedKind, n: number, count: number, seed: number, meshPath: string): FloodCase {
  const { image, projector } = closedSurface(kind, n, meshPath);
  let largestArea = 0;
  let scale = 0;
  for (const a of image.area) largestArea = Math.max(largestArea, a);
  for (const p of image.position) scale = Math.max(scale, Math.abs(p));
  // Sites apart by 1.5 times the largest texel's edge, so no two share a texel (see MIN_SPACING_TEXELS).
  const placed = placeClosedSites(image, projector, count, seed, MIN_SPACING_TEXELS * Math.sqrt(largestArea));
  const sites = Float32Array.from(placed.positions);
  const { position, area } = image;
  return {
    name: `${kind} n ${n}`,
    family: 'cube',
    layout: cubeLayout(n),
    texels: 6 * n * n,
    sites: count,
    scale,
    texelEdge: Math.sqrt(image.totalArea / (6 * n * n)),
    upload(engine) {
      engine.setGeometry(area, position);
      engine.setSites(placed.positions, placed.texels);
    },
    reference: () => cubeBruteForceLabels(position, sites, count),
    distance: (k, id) => Math.hypot(position[3 * k] - sites[3 * id], position[3 * k + 1] - sites[3 * id + 1], position[3 * k + 2] - sites[3 * id + 2]),
    sums: (labels) => cubeReduceCentroids(position, area, labels, sites, count),
    cellSize: (sums, _texels, id) => Math.sqrt(sums[SUMS_STRIDE * id + 3]),
  };
}
