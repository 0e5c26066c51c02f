import { ConfigError, inwardOffsetError, makeCubeGrid, minCurvatureRadius, type ClosedConfig } from '../core/config';
import { meshCurvatureRadii } from '../core/closed/geometry';
import { ellipsoidProjector, meshProjector, sphereProjector, type ClosedProjector } from '../core/closed/projector';
import { sampleSurface, type CubeGeometryImage } from '../core/cubemap/sample';
import { prepareMesh, type PreparedMesh } from './closedMesh';
import type { RunInputs } from './family';

/** A closed surface ready for Lloyd: its geometry image and closest-point projector. */
export interface ClosedSurface {
  readonly image: CubeGeometryImage;
  readonly projector: ClosedProjector;
  /** Smallest radius of curvature an inward offset must stay below (µm). */
  readonly convexRadius: number;
  /** Same for outward offsets (concave regions; Infinity on convex surfaces). */
  readonly concaveRadius: number;
  readonly mesh?: PreparedMesh;
  readonly nearestVertex?: (x: number, y: number, z: number) => number;
}

/** Samples (or checks and parameterizes the loaded mesh of) the closed surface of `config` on its cube map. */
export async function prepareClosedSurface(config: ClosedConfig, inputs: RunInputs = {}): Promise<ClosedSurface> {
  const { surface } = config;
  const n = makeCubeGrid(config).n;
  if (surface.kind === 'mesh') {
    // The pipeline reads no file: the host (CLI, page, worker, a library user) loads it.
    const file = inputs.meshFile;
    if (!file) {
      throw new ConfigError(
        'surface.src',
        `surface.src: "${surface.src}" is not loaded: the pipeline reads no files; load the mesh first (tissue-sheet/node loadMeshFile, or fetchMeshFile in a browser) and pass it as meshFile`,
      );
    }
    const mesh = prepareMesh(file, surface, n);
    const projector = meshProjector(mesh.mesh, mesh.parameterization.sphere);
    const radii = meshCurvatureRadii(mesh.mesh);
    return { image: mesh.image, projector, convexRadius: radii.convex, concaveRadius: radii.concave, mesh, nearestVertex: projector.nearestVertex };
  }
  const image = sampleSurface(surface, n);
  const projector = surface.kind === 'sphere' ? sphereProjector(surface.radius) : ellipsoidProjector(surface.a, surface.b, surface.c);
  return { image, projector, convexRadius: minCurvatureRadius(surface)!, concaveRadius: Infinity };
}

/** Refuses offsets that reach a focal point (the offset surface would fold over itself). */
export function checkOffsets(config: ClosedConfig, surface: ClosedSurface): void {
  const { thickness, direction, offset } = config.sheet;
  // "axes" offsets are ellipsoids again: no focal point to reach (checkMethods bounds inward ones).
  if (thickness <= 0 || offset === 'axes') return;
  const where = config.surface.kind === 'mesh' ? 'mesh (estimated from its vertex normals)' : config.surface.kind;
  if (direction === 'inward' && thickness >= surface.convexRadius) throw inwardOffsetError(thickness, surface.convexRadius, where);
  if (direction === 'outward' && thickness >= surface.concaveRadius) {
    throw new ConfigError(
      'sheet.thickness',
      `sheet.thickness: ${thickness} µm outward reaches the smallest radius of curvature of the concave parts of the ${where} (${surface.concaveRadius.toPrecision(4)} µm), where the offset surface folds over itself; use less or direction "inward"`,
    );
  }
}
