import type { ClosedConfig } from '../core/config';
import type { ClosedSites } from '../core/closed/geometry';
import { directionToTexel, texelIndex } from '../core/cubemap/cubemap';
import { HeatGeodesics, geodesicVoronoi } from '../core/mesh/heat';
import type { EngineChoice } from './enginePolicy';
import type { CubeMapGeometry, CubeMapLayer, CubeMapProjected } from './cubeMapTypes';
import type { Labeller } from './family';
import type { ClosedSurfaceRecord } from './result';

/** What a closed-surface run adds to the result: the surface, its mesh, the geodesic check. */
export function closedSection(
  config: ClosedConfig,
  geometry: CubeMapGeometry,
  seeded: { sites: ClosedSites; engine: EngineChoice },
  labeller: Labeller<CubeMapLayer, CubeMapProjected>,
): ClosedSurfaceRecord {
  const { surface } = config;
  const mesh = geometry.mesh;
  const geodesic = surface.kind === 'mesh' && surface.geodesic && mesh ? compareGeodesic(geometry, seeded.sites, labeller) : undefined;
  return {
    kind: surface.kind,
    n: geometry.image.n,
    area: geometry.image.totalArea,
    // The cube map has no gather pass: its paths are blend and readback.
    centroidPath: seeded.engine.centroidPath === 'blend' ? 'blend' : 'readback',
    minCurvatureRadius: config.sheet.direction === 'inward' ? geometry.convexRadius : Math.min(geometry.convexRadius, geometry.concaveRadius),
    ...(mesh
      ? {
          mesh: {
            src: surface.kind === 'mesh' ? surface.src : '',
            vertices: mesh.mesh.positions.length / 3,
            faces: mesh.mesh.indices.length / 3,
            flipped: mesh.parameterization.flipped,
            areaDistortion: { ...mesh.parameterization.areaDistortion },
            parameterizationMs: mesh.parameterizationMs,
            samplingMs: mesh.samplingMs,
            reoriented: mesh.reoriented,
            curvatureRadius: { convex: finiteOrNull(geometry.convexRadius), concave: finiteOrNull(geometry.concaveRadius) },
          },
        }
      : {}),
    ...(geodesic ? { geodesic } : {}),
  };
}

const finiteOrNull = (x: number): number | null => (Number.isFinite(x) ? x : null);

/**
 * Heat-method geodesic Voronoi of the final sites (each snapped to its nearest mesh vertex) on
 * the mesh vertices, timed, against the GPU Voronoi of the same sites (a cold flood, timed):
 * the GPU label of a vertex is the label of the texel its parameter direction falls in.
 */
function compareGeodesic(geometry: CubeMapGeometry, sites: ClosedSites, labeller: Labeller<CubeMapLayer, CubeMapProjected>): ClosedSurfaceRecord['geodesic'] {
  const prepared = geometry.mesh!;
  const mesh = prepared.mesh;
  const nv = mesh.positions.length / 3;
  const setupStart = performance.now();
  const solver = new HeatGeodesics(mesh);
  const setupMs = performance.now() - setupStart;
  const vertexIds = Array.from({ length: sites.count }, (_, i) =>
    geometry.nearestVertex!(sites.positions[3 * i], sites.positions[3 * i + 1], sites.positions[3 * i + 2]),
  );
  const solveStart = performance.now();
  const geodesic = geodesicVoronoi(mesh, vertexIds, solver);
  const solveMs = performance.now() - solveStart;

  const gpuStart = performance.now();
  const { image } = prepared;
  const seededLayer: CubeMapLayer = {
    name: 'seeded',
    role: 'seeded',
    offset: 0,
    ratio: 1,
    sample: { n: image.n, position: image.position, area: image.area, totalArea: image.totalArea },
  };
  const gpuLabels = labeller.label(seededLayer, { positions: sites.positions, texels: sites.texels });
  const gpuVoronoiMs = performance.now() - gpuStart;
  const s = prepared.parameterization.sphere;
  const n = image.n;
  let same = 0;
  for (let v = 0; v < nv; v++) {
    const t = directionToTexel([s[3 * v], s[3 * v + 1], s[3 * v + 2]], n);
    if (gpuLabels[texelIndex(t.face, t.i, t.j, n)] === geodesic.labels[v]) same++;
  }
  return { sites: sites.count, vertices: nv, setupMs, solveMs, msPerSite: solveMs / sites.count, gpuVoronoiMs, agreement: same / nv };
}
