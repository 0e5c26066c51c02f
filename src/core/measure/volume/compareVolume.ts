/**
 * The Voronoi model of a measured volume (`measure --volume --compare`, docs/measure.md).
 *
 * Open pieces (a lumen reaching the volume's faces: a gland or tube cut by the volume): the
 * model of the fitted tube (tubeFit.ts: axis, radii, length and thickness from the cells).
 * The model is the lab's tube: the inner surface unrolled (2 pi R_inner around, periodic, by
 * that length, open), as many sites as cells reach it, Voronoi k = 1..10 by k - 1 exact Lloyd
 * steps, the best k the one whose polygon distribution is nearest (L1) the measured one on the
 * lumen side; that k is then projected radially to the outer surface (ratio R_outer / R_inner),
 * exact neighbours, cells on the open ends excluded (compareWithModel, the layers mode's code).
 *
 * Closed shells (cysts, organoids; the lumen reaches no face): the model runs on the tissue's
 * own surfaces as triangle meshes (surfaceMesh.ts, from measureVolume's onSurfaceMeshes). The
 * seeded surface is the lumen side, with as many sites as cells reach it (random, the lab's
 * minimum spacing); Voronoi k = 1..10 by k - 1 sampled Lloyd steps on the mesh (meshModel.ts),
 * each diagram the exact restricted Voronoi diagram of the mesh; the best k's sites are carried
 * along the lumen surface's normal until they meet the outer surface (or, where the ray meets
 * nothing within three mean thicknesses, placed along it at the height of the measured cell
 * nearest: the parallel surface at the local thickness), and the outer diagram is the
 * restricted Voronoi diagram there. The result says how
 * many sites went each way.
 */
import { analyzeSurfaces } from '../../analysis';
import { meanInterval } from '../../analysis/realizations';
import { KdTree3 } from '../../closed/kdTree';
import { compareWithModel, LAB_MIN_SPACING_PIXELS, modelComparison, searchVoronoiK, type ModelComparison } from '../compare';
import type { Grid } from '../../grid';
import { carryAlongNormals, lloydStepOnMesh, meshSurface, prepareMesh, randomSitesOnMesh, type PreparedMesh } from './meshModel';
import type { SurfaceMesh } from './surfaceMesh';
import { fitTube, thicknessOf, type TubeGeometry } from './tubeFit';
import type { VolumeMeasuredResult } from './volumeResult';

interface ShellGeometry {
  readonly kind: 'mesh';
  /** Which measured layer is the seeded (lumen-side) surface. */
  readonly seededLayer: 'basal' | 'apical';
  readonly seededCells: number;
  /** Block size the meshes were extracted at (µm, about a fifth of a cell diameter). */
  readonly spacing: number;
  readonly seeded: { readonly vertices: number; readonly triangles: number; readonly area: number };
  readonly other: { readonly vertices: number; readonly triangles: number; readonly area: number };
  /** Sites (over all realizations) that met the other surface along their normal, and those put on the parallel surface. */
  readonly projection: { readonly alongNormal: number; readonly parallel: number };
  readonly thickness: { readonly mean: number; readonly sd: number; readonly cells: number };
}

export interface Interval {
  readonly mean: number;
  /** 95 % confidence interval of the mean over realizations (Student t), within the quantity's range; NaN with one realization. */
  readonly ci95: [number, number];
}

export interface VolumeComparison extends ModelComparison {
  /** The fitted tube of an open piece, or the meshes of a closed shell. */
  readonly geometry: TubeGeometry | ShellGeometry;
  /** The model's % scutoids, mean transitions and mean 3D neighbours over realizations, with 95 % CIs. */
  readonly model: { readonly percentScutoids: Interval; readonly transitions: Interval; readonly neighbours3D: Interval };
  /** The measured values beside them (valid cells). */
  readonly measured: { readonly percentScutoids: number; readonly transitions: number; readonly neighbours3D: number };
}

export interface CompareVolumeOptions {
  readonly realizations: number;
  readonly seed: number;
  readonly maxK?: number;
  readonly onProgress?: (line: string) => void;
}

/**
 * Mean and 95 % CI over realizations (realizations.ts's t interval), the interval clamped to the
 * quantity's range (a percentage to 0..100, counts to >= 0); NaN bounds with one realization.
 */
export function interval(values: number[], max = Number.POSITIVE_INFINITY): Interval {
  const { mean, ci95 } = meanInterval(values, 0, max);
  return { mean, ci95: ci95 ? [ci95[0], ci95[1]] : [NaN, NaN] };
}

/** The height of the measured cell whose lumen-side centroid is nearest a point (else `fallback`). */
function localThickness(result: VolumeMeasuredResult, inner: number, fallback: number): (x: number, y: number, z: number) => number {
  const cells = result.cells.filter((c) => c.height !== null && c.centroids[inner]);
  if (cells.length === 0) return () => fallback;
  const points = Float64Array.from(cells.flatMap((c) => c.centroids[inner]!));
  const tree = new KdTree3(points, cells.length);
  const ids = new Int32Array(1);
  const d2 = new Float64Array(1);
  return (x, y, z) => (tree.knn(x, y, z, 1, ids, d2) > 0 ? cells[ids[0]].height! : fallback);
}

/** What the model of a closed shell runs on: its meshes, cell count, spacing and thickness. */
export interface ShellSetup {
  /** Index of the lumen-side (seeded) layer in `result.inputs.layers`. */
  readonly inner: number;
  readonly layer: VolumeMeasuredResult['inputs']['layers'][number];
  readonly cells: number;
  readonly seeded: PreparedMesh;
  readonly other: PreparedMesh;
  readonly thickness: { readonly mean: number; readonly sd: number; readonly cells: number };
  /** The lab's minimum spacing of the random sites, µm. */
  readonly minSpacing: number;
  /** Sites carried to the other surface (see the module comment). */
  carry(sites: Float64Array): { sites: Float64Array; alongNormal: number; parallel: number };
}

export type ShellMeshes = { lumen: SurfaceMesh; outer: SurfaceMesh; spacing: number };

/** The closed shell's model set up on its meshes, or a note saying why there is none. */
export function shellSetup(result: VolumeMeasuredResult, meshes: ShellMeshes): ShellSetup | { note: string } {
  const inner = result.inputs.layers.findIndex((l) => l.faces === 'lumen');
  const layer = result.inputs.layers[inner];
  const cells = layer.cells;
  if (cells < 4) return { note: `no model: ${cells} cells reach the lumen; a model needs at least 4` };
  if (meshes.lumen.indices.length === 0 || meshes.outer.indices.length === 0) return { note: 'no model: a surface mesh came out empty' };
  const seeded = prepareMesh(meshes.lumen);
  const other = prepareMesh(meshes.outer);
  const thickness = thicknessOf(result);
  const reach = Number.isFinite(thickness.mean) ? thickness.mean : 5 * meshes.spacing;
  const thicknessAt = localThickness(result, inner, reach);
  const minSpacing = (LAB_MIN_SPACING_PIXELS * Math.sqrt(seeded.area / cells)) / Math.sqrt((512 * 4096) / 200);
  return {
    inner,
    layer,
    cells,
    seeded,
    other,
    thickness,
    minSpacing,
    carry: (sites) => carryAlongNormals(seeded, sites, other, 3 * reach, thicknessAt),
  };
}

/** The model of a closed shell on its own surface meshes (see the module comment). */
function compareShell(result: VolumeMeasuredResult, meshes: ShellMeshes, options: CompareVolumeOptions): { comparison: VolumeComparison | null; note: string } {
  const setup = shellSetup(result, meshes);
  if ('note' in setup) return { comparison: null, note: setup.note };
  const { inner, layer, cells, seeded, other, thickness, minSpacing } = setup;
  const maxK = options.maxK ?? 10;
  const { realizations, seed } = options;
  const summary = result.analyses[0].summary;
  const distribution = summary.perSurface[inner].polygonDistribution.map((f) => (Number.isNaN(f) ? 0 : f));

  const initial = Array.from({ length: realizations }, (_, r) => randomSitesOnMesh(seeded, cells, minSpacing, seed + r));
  const search = searchVoronoiK(
    distribution,
    initial,
    maxK,
    (s) => lloydStepOnMesh(seeded, s),
    (s) => analyzeSurfaces([meshSurface(seeded, s, 'seeded')]).summary.perSurface[0].polygonDistribution,
    options.onProgress,
  );
  let alongNormal = 0;
  let parallel = 0;
  const summaries = search.atK[search.best.k - 1].map((s) => {
    const carried = setup.carry(s);
    alongNormal += carried.alongNormal;
    parallel += carried.parallel;
    return analyzeSurfaces([meshSurface(seeded, s, 'lumen side'), meshSurface(other, carried.sites, 'outer side')]).summary;
  });
  const stack = modelComparison({ cells, realizations, seed, minSpacing, surfaceRatio: other.area / seeded.area }, search, summaries);
  const meshInfo = (m: SurfaceMesh, prepared: { area: number }) => ({ vertices: m.positions.length / 3, triangles: m.indices.length / 3, area: prepared.area });
  return {
    comparison: {
      ...stack,
      geometry: {
        kind: 'mesh',
        seededLayer: layer.name,
        seededCells: cells,
        spacing: meshes.spacing,
        seeded: meshInfo(meshes.lumen, seeded),
        other: meshInfo(meshes.outer, other),
        projection: { alongNormal, parallel },
        thickness,
      },
      model: {
        percentScutoids: interval(stack.percentScutoids, 100),
        transitions: interval(stack.meanTransitions),
        neighbours3D: interval(stack.meanNeighbours3D),
      },
      measured: { percentScutoids: summary.percentScutoids, transitions: summary.meanTransitions, neighbours3D: summary.meanNeighbours3D },
    },
    note: '',
  };
}

/**
 * The unrolled inner surface of a fitted tube at the lab's resolution (102.4 px per mean cell
 * diameter): periodic around, open along; `cells` sites.
 */
export function tubeGrid(result: VolumeMeasuredResult, geometry: TubeGeometry): Grid {
  const inner = result.inputs.layers.findIndex((l) => l.faces === 'lumen');
  const cellDiameter = Math.sqrt(result.inputs.layers[inner].area / geometry.seededCells);
  const pixel = cellDiameter / Math.sqrt((512 * 4096) / 200);
  const width = Math.max(8, Math.round((2 * Math.PI * geometry.innerRadius) / pixel));
  const height = Math.max(8, Math.round(geometry.length / pixel));
  const size = (2 * Math.PI * geometry.innerRadius) / width;
  return { width, height, texelX: size, texelY: size, periodicX: true, periodicY: false };
}

/**
 * The model of the same tissue, or null with a note saying why there is none. Closed shells
 * need `meshes` (measureVolume's onSurfaceMeshes).
 */
export function compareVolume(
  result: VolumeMeasuredResult,
  options: CompareVolumeOptions,
  meshes?: ShellMeshes,
): { comparison: VolumeComparison | null; note: string } {
  if (!result.inputs.background.lumenReachesFaces) {
    if (!meshes) return { comparison: null, note: 'no model: a closed shell is modelled on its own surface meshes; measure it with onSurfaceMeshes' };
    return compareShell(result, meshes, options);
  }
  const { geometry, note } = fitTube(result);
  if (!geometry) return { comparison: null, note: `no model: ${note}` };
  const inner = result.inputs.layers.findIndex((l) => l.faces === 'lumen');
  const summary = result.analyses[0].summary;
  const grid = tubeGrid(result, geometry);
  const base = compareWithModel({
    width: grid.width,
    height: grid.height,
    pixelSize: grid.texelX,
    periodicX: true,
    cells: geometry.seededCells,
    distribution: summary.perSurface[inner].polygonDistribution.map((f) => (Number.isNaN(f) ? 0 : f)),
    layers: 2,
    surfaceRatio: geometry.outerRadius / geometry.innerRadius,
    realizations: options.realizations,
    seed: options.seed,
    maxK: options.maxK,
    onProgress: options.onProgress,
  });
  return {
    comparison: {
      ...base,
      geometry,
      model: {
        percentScutoids: interval(base.percentScutoids, 100),
        transitions: interval(base.meanTransitions),
        neighbours3D: interval(base.meanNeighbours3D),
      },
      measured: { percentScutoids: summary.percentScutoids, transitions: summary.meanTransitions, neighbours3D: summary.meanNeighbours3D },
    },
    note: '',
  };
}
