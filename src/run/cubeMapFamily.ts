import { labMinBoundaryLength } from '../core/analysis';
import { checkClosedFeasible, checkClosedSheet, makeCubeGrid, type ClosedConfig } from '../core/config';
import { sheetOffsets } from '../core/sheetGeometry';
import { KdTree3 } from '../core/closed/kdTree';
import { ellipsoidProjector, PROJECTION_STRIDE } from '../core/closed/projector';
import { sampleSurface } from '../core/cubemap/sample';
import {
  allocateSites,
  storeProjection,
  cubeLabelAdjacency,
  offsetSurface,
  placeClosedSites,
  texelNeighbours,
  type ClosedSites,
  type CubeSurfaceSample,
} from '../core/closed/geometry';
import type { Grid } from '../core/grid';
import type { EngineChoice } from './enginePolicy';
import type { CentroidPath } from '../gpu/centroidPolicy';
import type { GpuContext } from '../gpu/context';
import { GpuEngine } from '../gpu/engine';
import { cubeLayout } from '../gpu/layout';
import { closedSites, GpuLloydRun } from '../gpu/lloyd';
import { closedExactAdjacency } from './closedExact';
import { closedSection } from './closedRecord';
import { checkOffsets, prepareClosedSurface } from './closedSurface';
import type { CubeMapGeometry, CubeMapLayer, CubeMapProjected } from './cubeMapTypes';
import type { Labeller, SurfaceFamily } from './family';
import { engineRelaxation } from './relax';

export type { CubeMapGeometry, CubeMapLayer, CubeMapProjected } from './cubeMapTypes';

/**
 * Sphere, ellipsoid and genus-0 meshes on a cube-map geometry image (docs/closed-surfaces.md):
 * 6 n² texels holding the surface's 3D points and area elements; a jump flood with 3D distances
 * across face edges; Lloyd moves each site to the closest surface point of its cell's centroid.
 * Other surfaces of the stack are the parallel surfaces, sampled on the same cube map. Every
 * closed surface has an exact method: the restricted Voronoi diagram (closedExact.ts).
 */
export const cubeMapFamily: SurfaceFamily<ClosedConfig, CubeMapGeometry, ClosedSites, CubeMapLayer, CubeMapProjected> = {
  name: 'cube map',

  async prepare(config, callbacks) {
    checkClosedFeasible(config, makeCubeGrid(config));
    const surface = await prepareClosedSurface(config, callbacks);
    return { ...surface, neighbours: texelNeighbours(surface.image.n) };
  },

  checkSheet(config, geometry) {
    checkClosedSheet(config);
    checkOffsets(config, geometry);
  },

  relax(context, config, geometry, choice) {
    const { image, projector } = geometry;
    const centroidPath = gpuPath(choice);
    const sites = placeClosedSites(image, projector, config.cells, config.seed, config.minSpacing);
    const engine = new GpuEngine(context, cubeLayout(image.n), config.cells, { variant: config.jumpFlood.variant, centroidPath });
    const relaxation = engineRelaxation(engine, () => {
      engine.setGeometry(image.area, image.position);
      return new GpuLloydRun(engine, closedSites(projector, sites, minTexelSpacing(geometry)), config.lloyd);
    });
    return { sites, relaxation };
  },

  stack(config, geometry) {
    const { sheet } = config;
    const offsets = sheetOffsets(config);
    const count = offsets.length;
    return offsets.map((offset, k) => {
      const role = k === 0 ? 'seeded' : k === count - 1 ? 'other' : 'layer';
      const name = role === 'seeded' ? sheet.seeded : role === 'other' ? (sheet.seeded === 'basal' ? 'apical' : 'basal') : `layer ${k}`;
      const ratioOf = (sample: CubeSurfaceSample) => Math.sqrt(sample.totalArea / geometry.image.totalArea);
      if (sheet.offset === 'axes' && offset !== 0) {
        const [a, b, c] = semiAxes(config);
        const axes = [a + offset, b + offset, c + offset] as const;
        const sample = sampleSurface({ kind: 'ellipsoid', a: axes[0], b: axes[1], c: axes[2] }, geometry.image.n);
        return { name, role, offset, axes, sample, ratio: ratioOf(sample) };
      }
      const sample = offsetSurface(geometry.image, offset, geometry.neighbours);
      return { name, role, offset, sample, ratio: ratioOf(sample) };
    });
  },

  project(geometry, layer, sites) {
    if (layer.axes) return closestPointsOn(layer.axes, sites, geometry.image.n);
    const positions = new Float64Array(3 * sites.count);
    for (let k = 0; k < positions.length; k++) positions[k] = sites.positions[k] + layer.offset * sites.normals[k];
    return { positions, texels: sites.texels };
  },

  labeller: (context, config, geometry, choice) => cubeMapLabeller(context, config, geometry.image.n, choice),

  // Only the exact method asked for: a layer's label image (for views) is each texel's nearest
  // site in 3D, the jump flood's own definition, computed on the CPU when a view reads it.
  exactLabels(_geometry, layer, projected) {
    const count = projected.positions.length / 3;
    const tree = new KdTree3(projected.positions, count);
    const ids = new Int32Array(1);
    const d2 = new Float64Array(1);
    const P = layer.sample.position;
    const labels = new Int32Array(P.length / 3);
    for (let k = 0; k < labels.length; k++) labels[k] = tree.nearest(P[3 * k], P[3 * k + 1], P[3 * k + 2], ids, d2);
    return labels;
  },

  // The lab protocol is refused on closed surfaces (no open ends): validity is the stack's.
  protocolInvalid: () => null,

  labelFrame: (geometry, layer) => ({
    name: layer.name,
    grid: atlasGrid(geometry.image.n, layer.sample.totalArea),
    positions: layer.sample.position,
  }),

  labelAdjacency: (_config, geometry, layer, labels, count) => cubeLabelAdjacency(layer.sample, labels, count, geometry.neighbours, 'true', layer.name),

  // True contact lengths: the same thresholds for both methods, per surface.
  minContactLengths(config, geometry, layers) {
    const { totalArea } = geometry.image;
    const length = config.sheet.minContactLength ?? labMinBoundaryLength(totalArea, config.cells);
    // Every surface has the same cube map (n² texels per face), so the threshold, like the
    // lab's pixels, scales with each surface's linear size (sqrt of its area ratio).
    return { reported: length, perLayer: layers.map((layer) => length * Math.sqrt(layer.sample.totalArea / totalArea)) };
  },

  exactAdjacency: (config, geometry, layer, sites) => closedExactAdjacency(config, geometry, sites, layer.offset, config.sheet.offset, layer.name),

  cellPlacements(_config, _layer, sites, projected, position, coordinates) {
    const deg = 180 / Math.PI;
    position.set(projected.positions.subarray(0, position.length));
    for (let id = 0; 2 * id < coordinates.length; id++) {
      // [longitude, latitude] (degrees) of the site's parameter direction.
      const d = sites.directions;
      coordinates[2 * id] = Math.atan2(d[3 * id + 1], d[3 * id]) * deg;
      coordinates[2 * id + 1] = Math.asin(Math.max(-1, Math.min(1, d[3 * id + 2]))) * deg;
    }
  },

  gridRecord: (geometry) => ({ ...atlasGrid(geometry.image.n, geometry.image.totalArea) }),

  resultSection: (config, geometry, seeded, labeller) => ({ closed: closedSection(config, geometry, seeded, labeller) }),
};

/** Semi-axes of a sphere or ellipsoid (the surfaces "axes" offsets apply to). */
function semiAxes(config: ClosedConfig): [number, number, number] {
  const { surface } = config;
  if (surface.kind === 'sphere') return [surface.radius, surface.radius, surface.radius];
  if (surface.kind === 'ellipsoid') return [surface.a, surface.b, surface.c];
  throw new Error('sheet.offset: "axes" needs a sphere or an ellipsoid');
}

/** Each site moved to its closest point on the ellipsoid `axes`, with the texel it falls in there. */
function closestPointsOn(axes: readonly [number, number, number], sites: ClosedSites, n: number): CubeMapProjected {
  const projector = ellipsoidProjector(axes[0], axes[1], axes[2]);
  const moved = allocateSites(sites.count);
  const buffer = new Float64Array(PROJECTION_STRIDE);
  for (let i = 0; i < sites.count; i++) {
    projector.project(sites.positions[3 * i], sites.positions[3 * i + 1], sites.positions[3 * i + 2], buffer, 0);
    storeProjection(moved, i, buffer, n);
  }
  return { positions: moved.positions, texels: moved.texels };
}

/** The n x 6n atlas as a grid record: square texels of the mean texel area. */
function atlasGrid(n: number, totalArea: number): Grid {
  const texel = Math.sqrt(totalArea / (6 * n * n));
  return { width: n, height: 6 * n, texelX: texel, texelY: texel, periodicX: false, periodicY: false };
}

/** Smallest distance between edge-neighbouring texel centres (µm), > 0. */
function minTexelSpacing(geometry: CubeMapGeometry): number {
  const P = geometry.image.position;
  const neighbours = geometry.neighbours;
  let min = Infinity;
  const count = 6 * geometry.image.n * geometry.image.n;
  for (let k = 0; k < count; k++) {
    for (let s = 1; s < 4; s += 2) {
      const l = neighbours[4 * k + s];
      const d = Math.hypot(P[3 * k] - P[3 * l], P[3 * k + 1] - P[3 * l + 1], P[3 * k + 2] - P[3 * l + 2]);
      if (d > 0 && d < min) min = d;
    }
  }
  return Number.isFinite(min) ? min : 1;
}

/** The cube map runs on the GPU engine only (the engine policy never chooses another here). */
function gpuPath(choice: EngineChoice): CentroidPath {
  if (choice.name !== 'gpu') throw new Error(`the cube-map family runs on the GPU engine, not "${choice.name}"`);
  return choice.centroidPath;
}

/** Every surface of the stack has the same cube map: one engine labels them all (setGeometry). */
function cubeMapLabeller(context: GpuContext, config: ClosedConfig, n: number, choice: EngineChoice): Labeller<CubeMapLayer, CubeMapProjected> {
  const engine = new GpuEngine(context, cubeLayout(n), config.cells, { variant: config.jumpFlood.variant, centroidPath: gpuPath(choice) });
  return {
    label(layer, sites) {
      engine.setGeometry(layer.sample.area, layer.sample.position);
      engine.setSites(sites.positions, sites.texels);
      engine.floodLabels();
      return engine.readLabels();
    },
    dispose: () => engine.dispose(),
  };
}
