import type { SurfaceAdjacency } from '../core/analysis';
import type { Config } from '../core/config';
import type { SurfaceLayoutName } from '../core/config/surfaceLayout';
import type { GrayImage } from '../core/density';
import type { GpuContext } from '../gpu/context';
import type { IterationRecord } from '../gpu/lloyd';
import type { MeshFile } from './closedMesh';
import type { EngineChoice } from './enginePolicy';
import type { ClosedSurfaceRecord, GridRecord, LabelImage } from './result';

/** What a caller can hand the pipeline besides the config. */
/** What a host decoded for the run (the pipeline reads no file and fetches nothing). */
export interface RunInputs {
  /** A decoded grayscale image for `density.kind = "image"`. */
  densityImage?: GrayImage;
  /** The mesh file for `surface.kind = "mesh"` (read by the CLI, or a user's File in the browser). */
  meshFile?: MeshFile;
}

/** runSheet's options: the decoded inputs, and how the run reports progress and what it returns. */
export interface RunOptions extends RunInputs {
  /** Called after each Lloyd iteration. */
  onIteration?(record: IterationRecord, maxIterations: number): void;
  /** Aborting stops the run between iterations with an AbortError; nothing is half-written. */
  signal?: AbortSignal;
  /**
   * false: the caller needs the result only, not the label images for views (a sweep): a worker
   * then sends none back, and lazily drawn images are never drawn.
   */
  views?: boolean;
  /**
   * true: every per-cell list of the result (`cells`, `surfaces[].cells`, `analyses[].cells`) is
   * left empty and given as columns in SheetOutput.tables instead (src/run/cellTables.ts): a
   * million cells without millions of objects. `tissue-sheet run` asks for it on large runs.
   */
  cellTables?: boolean;
}

/** One surface of the sheet's stack: the seeded surface, a layer, or the other surface. */
export interface StackLayer {
  /** "basal", "apical" or "layer k" (k = 1 next to the seeded surface). */
  readonly name: string;
  readonly role: 'seeded' | 'layer' | 'other';
  /** Signed distance from the seeded surface along its normal, µm (outward > 0). */
  readonly offset: number;
  /** Size relative to the seeded surface: R / R_seeded on a tube, 1 on a plane, √(area ratio) on a closed surface. */
  readonly ratio: number;
}

/** Lloyd's method on the seeded surface, one iteration at a time (GPU passes, CPU moves). */
export interface Relaxation {
  readonly done: boolean;
  readonly converged: boolean;
  readonly iterations: IterationRecord[];
  step(): IterationRecord;
  /** The final sites' CVT energy, empty cells and label image (site id per texel; null from the exact engine). */
  finish(): { energy: number; emptyCells: number; labels: Int32Array | null };
  dispose(): void;
}

/** Labels surfaces of the stack with a jump flood each (no Lloyd: the sites stay put). */
export interface Labeller<Layer, Projected> {
  label(layer: Layer, sites: Projected): Int32Array;
  dispose(): void;
}

/**
 * A surface family: how one layout of geometry image (a planar grid for planes and tubes, a
 * cube map for closed surfaces) is sampled, relaxed, stacked and measured. The pipeline
 * (runSheet) runs the same steps over either; a family only answers its own questions.
 *
 * C: the configs it runs; Geometry: the prepared seeded surface; Sites: the seeded sites as the family keeps them;
 * Layer: one surface of the stack; Projected: the sites moved onto a layer.
 */
export interface SurfaceFamily<C extends Config, Geometry, Sites, Layer extends StackLayer, Projected> {
  readonly name: SurfaceLayoutName;
  /** Checks what can be checked before any work, then builds the seeded surface. */
  prepare(config: C, inputs: RunInputs): Promise<Geometry>;
  /** Checks the sheet (offsets, thickness) against the prepared surface; throws ConfigError. */
  checkSheet(config: C, geometry: Geometry): void;
  /** Places the initial sites and sets up Lloyd on the chosen engine. */
  relax(context: GpuContext, config: C, geometry: Geometry, engine: EngineChoice): { sites: Sites; relaxation: Relaxation };
  /** The stack [seeded, layers..., other]. */
  stack(config: C, geometry: Geometry): Layer[];
  /** The seeded sites moved along the normal onto a layer. */
  project(geometry: Geometry, layer: Layer, sites: Sites): Projected;
  labeller(context: GpuContext, config: C, geometry: Geometry, engine: EngineChoice): Labeller<Layer, Projected>;
  /**
   * A layer's label image without a jump flood, for views only (no statistic reads it): the exact
   * engine's cells drawn on the texels, or on a cube map each texel's nearest site.
   */
  exactLabels(geometry: Geometry, layer: Layer, projected: Projected): Int32Array;
  /** A layer's label image less its labels: its name, grid and (closed surfaces) texel positions. */
  labelFrame(geometry: Geometry, layer: Layer): Omit<LabelImage, 'labels'>;
  /** Neighbours, contact lengths (µm), areas and border contacts from a layer's label image. */
  labelAdjacency(config: C, geometry: Geometry, layer: Layer, labels: Int32Array, count: number): SurfaceAdjacency;
  /** The shortest contact (µm) a method counts on each layer and the value reported, or null: every contact counts. */
  minContactLengths(config: C, geometry: Geometry, layers: Layer[], method: 'labels' | 'exact'): { reported: number; perLayer: number[] } | null;
  /** The protocol's invalid cells beyond those touching an open end of the stack (lab: any validity layer), or null. */
  protocolInvalid(config: C, geometry: Geometry, sites: Sites): Uint8Array | null;
  /** The exact adjacency of a layer (every surface has one: planar Delaunay, restricted Voronoi). */
  exactAdjacency(config: C, geometry: Geometry, layer: Layer, sites: Sites, projected: Projected): SurfaceAdjacency;
  /**
   * Where every cell's site lies, into columns: position (x, y, z, µm) at 3·id; surface
   * coordinates at 2·id (unrolled µm on planes and tubes; [longitude, latitude] in degrees on closed surfaces).
   */
  cellPlacements(config: C, layer: Layer, sites: Sites, projected: Projected, position: Float64Array, coordinates: Float64Array): void;
  /** The texel grid of the seeded surface, as the result reports it. */
  gridRecord(geometry: Geometry): GridRecord;
  /** What this family adds to the result (the `closed` section), computed last. */
  resultSection(
    config: C,
    geometry: Geometry,
    seeded: { sites: Sites; engine: EngineChoice },
    labeller: Labeller<Layer, Projected>,
  ): { closed?: ClosedSurfaceRecord };
}
