import { analyzeSurfaces, withMinBoundaryLength, type SurfaceAdjacency } from '../core/analysis';
import {
  checkClosedFeasible,
  ConfigError,
  inwardOffsetError,
  makeCubeGrid,
  minCurvatureRadius,
  type ClosedConfig,
  type Config,
} from '../core/config';
import {
  cubeLabelAdjacency,
  meshCurvatureRadii,
  offsetSurface,
  placeClosedSites,
  texelNeighbours,
  type ClosedSites,
  type CubeLabelAdjacency,
  type CubeSurfaceSample,
} from '../core/closed/geometry';
import { ellipsoidProjector, meshProjector, sphereProjector, type ClosedProjector } from '../core/closed/projector';
import { sphericalVoronoi } from '../core/closed/sphericalDelaunay';
import { directionToTexel, texelIndex } from '../core/cubemap/cubemap';
import { sampleSurface, type CubeGeometryImage } from '../core/cubemap/sample';
import type { Grid } from '../core/grid';
import { HeatGeodesics, geodesicVoronoi } from '../core/mesh/heat';
import type { GpuContext } from '../gpu/context';
import { CubeCcvtEngine } from '../gpu/cubeEngine';
import { ClosedLloydRun } from '../gpu/cubeLloyd';
import { version } from '../version';
import { prepareMesh, readMeshSource, type MeshFile, type PreparedMesh } from './closedMesh';
import { analysisRecord } from './analysisRecord';
import type { AnalysisRecord, CellRecord, ClosedSurfaceRecord, LabelImage, SheetOutput, SurfaceRecord } from './result';
import { throwIfAborted, yieldToEventLoop, type RunCallbacks } from './seededSurface';

export interface ClosedRunCallbacks extends RunCallbacks {
  /** The mesh file itself (e.g. a user's File read in the browser) instead of fetching surface.src. */
  meshFile?: MeshFile;
}

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

/** Samples (or loads, checks and parameterizes) the closed surface of `config` on its cube map. */
export async function prepareClosedSurface(config: ClosedConfig, callbacks: ClosedRunCallbacks = {}): Promise<ClosedSurface> {
  const { surface } = config;
  const n = makeCubeGrid(config).n;
  if (surface.kind === 'mesh') {
    const file = callbacks.meshFile ?? (await readMeshSource(surface.src));
    const mesh = prepareMesh(file, surface, n);
    const projector = meshProjector(mesh.mesh, mesh.parameterization.sphere);
    const radii = meshCurvatureRadii(mesh.mesh);
    return { image: mesh.image, projector, convexRadius: radii.convex, concaveRadius: radii.concave, mesh, nearestVertex: projector.nearestVertex };
  }
  const image = sampleSurface(surface, n);
  const projector = surface.kind === 'sphere' ? sphereProjector(surface.radius) : ellipsoidProjector(surface.a, surface.b, surface.c);
  return { image, projector, convexRadius: minCurvatureRadius(surface)!, concaveRadius: Infinity };
}

/** Offsets of the stack [seeded, layers..., other], signed along the outward normal (µm). */
export function closedStackOffsets(config: ClosedConfig): { name: string; role: 'seeded' | 'layer' | 'other'; offset: number }[] {
  const { sheet } = config;
  const other = sign(sheet.direction) * sheet.thickness;
  const count = sheet.layers + 2;
  return Array.from({ length: count }, (_, k) => {
    const role = k === 0 ? 'seeded' : k === count - 1 ? 'other' : 'layer';
    const name = role === 'seeded' ? sheet.seeded : role === 'other' ? (sheet.seeded === 'basal' ? 'apical' : 'basal') : `layer ${k}`;
    return { name, role, offset: (other * k) / (count - 1) };
  });
}

const sign = (direction: 'outward' | 'inward') => (direction === 'outward' ? 1 : -1);

/** Refuses offsets that reach a focal point (the offset surface would fold over itself). */
function checkOffsets(config: ClosedConfig, surface: ClosedSurface): void {
  const { thickness, direction } = config.sheet;
  if (thickness <= 0) return;
  const where = config.surface.kind === 'mesh' ? 'mesh (estimated from its vertex normals)' : config.surface.kind;
  if (direction === 'inward' && thickness >= surface.convexRadius) throw inwardOffsetError(thickness, surface.convexRadius, where);
  if (direction === 'outward' && thickness >= surface.concaveRadius) {
    throw new ConfigError(
      'sheet.thickness',
      `sheet.thickness: ${thickness} µm outward reaches the smallest radius of curvature of the concave parts of the ${where} (${surface.concaveRadius.toPrecision(4)} µm), where the offset surface folds over itself; use less or direction "inward"`,
    );
  }
}

/**
 * The whole computation on a closed surface (sphere, ellipsoid, genus-0 mesh): cube-map
 * geometry image -> random sites (uniform in area) -> constrained Lloyd on the GPU -> sites
 * projected along their normals onto the offset surfaces (layers, other side) -> a jump flood
 * per surface -> label adjacency across face edges -> scutoid statistics (labels; on a sphere
 * also exact, from the convex hull) -> the documented result (docs/closed-surfaces.md).
 */
export async function runClosedSheet(config: ClosedConfig, context: GpuContext, callbacks: ClosedRunCallbacks = {}): Promise<SheetOutput> {
  const start = performance.now();
  const cube = makeCubeGrid(config);
  checkClosedFeasible(config, cube);
  const surface = await prepareClosedSurface(config, callbacks);
  checkOffsets(config, surface);
  const { image, projector } = surface;
  const n = image.n;
  const count = config.cells;
  const neighbours = texelNeighbours(n);
  const spacing = minTexelSpacing(image, neighbours);
  const sites = placeClosedSites(image, projector, count, config.seed, config.minSpacing);

  const engine = new CubeCcvtEngine(context, n, count, { variant: config.jumpFlood.variant, centroidPath: config.centroidPath });
  try {
    engine.setGeometry(image.position, image.area);
    const run = new ClosedLloydRun(engine, projector, sites, config.lloyd, spacing);
    const setupMs = performance.now() - start;
    while (!run.done) {
      throwIfAborted(callbacks.signal);
      const record = run.step();
      callbacks.onIteration?.(record, config.lloyd.maxIterations);
      await yieldToEventLoop();
    }
    const final = run.finish();
    const seededLabels = engine.readLabels();
    const lloydMs = performance.now() - start - setupMs;

    // The stack of surfaces.
    const adjacencyStart = performance.now();
    const stack = closedStackOffsets(config);
    const samples: CubeSurfaceSample[] = [];
    const labelImages: LabelImage[] = [];
    const adjacencies: CubeLabelAdjacency[] = [];
    const projected: Float64Array[] = [];
    const grid: Grid = { width: n, height: 6 * n, texelX: Math.sqrt(image.totalArea / (6 * n * n)), texelY: Math.sqrt(image.totalArea / (6 * n * n)), periodicX: false, periodicY: false };
    for (const layer of stack) {
      throwIfAborted(callbacks.signal);
      const sample = offsetSurface(image, layer.offset, neighbours);
      const positions = offsetSites(sites, layer.offset);
      let labels = seededLabels;
      if (layer.role !== 'seeded') {
        engine.setGeometry(sample.position, sample.area);
        engine.setSites(positions, sites.texels);
        engine.floodLabels();
        labels = engine.readLabels();
        await yieldToEventLoop();
      }
      samples.push(sample);
      projected.push(positions);
      labelImages.push({ name: layer.name, grid: { ...grid, texelX: Math.sqrt(sample.totalArea / (6 * n * n)), texelY: Math.sqrt(sample.totalArea / (6 * n * n)) }, labels });
      adjacencies.push(cubeLabelAdjacency(sample, labels, count, neighbours));
    }

    const analyses: AnalysisRecord[] = [];
    const { adjacency } = config.sheet;
    if (adjacency !== 'exact') {
      const minContactLength = config.sheet.minContactLength ?? (6 / 102.4) * Math.sqrt(image.totalArea / count);
      // Every surface has the same cube map (n² texels per face), so the threshold, like the
      // lab's pixels, scales with each surface's linear size (sqrt of its area ratio).
      const inputs = adjacencies.map((a, k) =>
        withMinBoundaryLength(fromLabels(a, stack[k].name), minContactLength * Math.sqrt(samples[k].totalArea / image.totalArea)),
      );
      analyses.push(analysisRecord('labels', minContactLength, analyzeSurfaces(inputs)));
    }
    if (adjacency !== 'labels' && config.surface.kind === 'sphere') {
      const R = config.surface.radius;
      const inputs = stack.map((layer) => {
        const v = sphericalVoronoi(sites.directions, count, R + layer.offset);
        return { count, adjacency: v.adjacency, areas: v.areas, touchesBorder: v.touchesBorder, label: layer.name } satisfies SurfaceAdjacency;
      });
      analyses.push(analysisRecord('exact', 0, analyzeSurfaces(inputs)));
    }
    const adjacencyMs = performance.now() - adjacencyStart;

    // Last use of the engine: it re-floods the seeded surface to time the GPU Voronoi.
    const geodesic = config.surface.kind === 'mesh' && config.surface.geodesic && surface.mesh ? compareGeodesic(surface, sites, engine) : undefined;

    const cellsOf = (k: number) => cellRecords(projected[k], sites, adjacencies[k]);
    const surfaces: SurfaceRecord[] = stack.slice(1).map((layer, index) => ({
      name: layer.name,
      role: layer.role as 'layer' | 'other',
      offset: layer.offset,
      ratio: Math.sqrt(samples[index + 1].totalArea / image.totalArea),
      grid: { ...labelImages[index + 1].grid },
      cells: cellsOf(index + 1),
    }));
    const closed: ClosedSurfaceRecord = {
      kind: config.surface.kind,
      n,
      area: image.totalArea,
      centroidPath: engine.centroidPath,
      minCurvatureRadius: config.sheet.direction === 'inward' ? surface.convexRadius : Math.min(surface.convexRadius, surface.concaveRadius),
      ...(surface.mesh
        ? {
            mesh: {
              src: config.surface.kind === 'mesh' ? config.surface.src : '',
              vertices: surface.mesh.mesh.positions.length / 3,
              faces: surface.mesh.mesh.indices.length / 3,
              flipped: surface.mesh.parameterization.flipped,
              areaDistortion: { ...surface.mesh.parameterization.areaDistortion },
              parameterizationMs: surface.mesh.parameterizationMs,
              samplingMs: surface.mesh.samplingMs,
              curvatureRadius: { convex: finiteOrNull(surface.convexRadius), concave: finiteOrNull(surface.concaveRadius) },
            },
          }
        : {}),
      ...(geodesic ? { geodesic } : {}),
    };
    return {
      result: {
        software: { name: 'tissue-sheet', version },
        // SheetResult.config is typed for planar configs; a closed run records its own config.
        config: config as unknown as Config,
        seed: config.seed,
        grid: { ...grid },
        gpu: {
          renderer: context.capabilities.renderer,
          centroidPath: engine.centroidPath,
          jumpFloodVariant: config.jumpFlood.variant,
        },
        lloyd: { iterations: run.iterations, converged: run.converged, finalEnergy: final.energy, emptyCells: final.emptyCells },
        adjacency: { method: 'labels' },
        timings: { setupMs, lloydMs, adjacencyMs, totalMs: performance.now() - start },
        cells: cellsOf(0),
        surfaces,
        analyses,
        closed,
      },
      labelImages,
    };
  } finally {
    engine.dispose();
  }
}

const finiteOrNull = (x: number): number | null => (Number.isFinite(x) ? x : null);

/** Smallest distance between edge-neighbouring texel centres (µm), > 0. */
function minTexelSpacing(image: CubeGeometryImage, neighbours: Int32Array): number {
  const P = image.position;
  let min = Infinity;
  const count = 6 * image.n * image.n;
  for (let k = 0; k < count; k++) {
    for (let s = 1; s < 4; s += 2) {
      const l = neighbours[4 * k + s];
      const d = Math.hypot(P[3 * k] - P[3 * l], P[3 * k + 1] - P[3 * l + 1], P[3 * k + 2] - P[3 * l + 2]);
      if (d > 0 && d < min) min = d;
    }
  }
  return Number.isFinite(min) ? min : 1;
}

/** Sites moved t along their normals (the projection onto the offset surface). */
function offsetSites(sites: ClosedSites, t: number): Float64Array {
  const out = new Float64Array(3 * sites.count);
  for (let k = 0; k < out.length; k++) out[k] = sites.positions[k] + t * sites.normals[k];
  return out;
}

/**
 * Heat-method geodesic Voronoi of the final sites (each snapped to its nearest mesh vertex) on
 * the mesh vertices, timed, against the GPU Voronoi of the same sites (a cold flood, timed):
 * the GPU label of a vertex is the label of the texel its parameter direction falls in.
 */
function compareGeodesic(surface: ClosedSurface, sites: ClosedSites, engine: CubeCcvtEngine): ClosedSurfaceRecord['geodesic'] {
  const prepared = surface.mesh!;
  const mesh = prepared.mesh;
  const nv = mesh.positions.length / 3;
  const setupStart = performance.now();
  const solver = new HeatGeodesics(mesh);
  const setupMs = performance.now() - setupStart;
  const vertexIds = Array.from({ length: sites.count }, (_, i) =>
    surface.nearestVertex!(sites.positions[3 * i], sites.positions[3 * i + 1], sites.positions[3 * i + 2]),
  );
  const solveStart = performance.now();
  const geodesic = geodesicVoronoi(mesh, vertexIds, solver);
  const solveMs = performance.now() - solveStart;

  const gpuStart = performance.now();
  engine.setGeometry(prepared.image.position, prepared.image.area);
  engine.setSites(sites.positions, sites.texels);
  engine.floodLabels();
  const gpuLabels = engine.readLabels();
  const gpuVoronoiMs = performance.now() - gpuStart;
  const s = prepared.parameterization.sphere;
  const n = engine.n;
  let same = 0;
  for (let v = 0; v < nv; v++) {
    const t = directionToTexel([s[3 * v], s[3 * v + 1], s[3 * v + 2]], n);
    if (gpuLabels[texelIndex(t.face, t.i, t.j, n)] === geodesic.labels[v]) same++;
  }
  return { sites: sites.count, vertices: nv, setupMs, solveMs, msPerSite: solveMs / sites.count, gpuVoronoiMs, agreement: same / nv };
}

function fromLabels(adjacency: CubeLabelAdjacency, label: string): SurfaceAdjacency {
  return {
    count: adjacency.count,
    adjacency: { offsets: adjacency.offsets, neighbours: adjacency.neighbours, lengths: adjacency.lengths },
    areas: adjacency.area,
    touchesBorder: adjacency.touchesBorder,
    label,
  };
}

/** Cell records of one surface: `surface` holds [longitude, latitude] (degrees) of the site's parameter direction. */
function cellRecords(positions: Float64Array, sites: ClosedSites, adjacency: CubeLabelAdjacency): CellRecord[] {
  const cells: CellRecord[] = [];
  const deg = 180 / Math.PI;
  for (let id = 0; id < adjacency.count; id++) {
    const neighbours = [];
    for (let k = adjacency.offsets[id]; k < adjacency.offsets[id + 1]; k++) neighbours.push({ id: adjacency.neighbours[k], length: adjacency.lengths[k] });
    const dx = sites.directions[3 * id], dy = sites.directions[3 * id + 1], dz = sites.directions[3 * id + 2];
    cells.push({
      id,
      position: [positions[3 * id], positions[3 * id + 1], positions[3 * id + 2]],
      surface: [Math.atan2(dy, dx) * deg, Math.asin(Math.max(-1, Math.min(1, dz))) * deg],
      area: adjacency.area[id],
      neighbours,
      touchesBorder: false,
    });
  }
  return cells;
}
