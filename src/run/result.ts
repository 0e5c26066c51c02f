import type { ByConstruction } from '../core/analysis/byConstruction';
import type { Headline } from '../core/analysis/headline';
import type { AnalysisRecord } from '../core/analysis/record';
import type { Config } from '../core/config';
import type { Grid } from '../core/grid';
import type { Vec3 } from '../core/surface';
import type { IterationRecord } from '../gpu/lloyd';
import type { ResultCellTables } from './cellTables';
import type { EngineChoice } from './enginePolicy';

/** A neighbour of a cell and the length (µm) of the boundary they share. */
export interface NeighbourContact {
  readonly id: number;
  readonly length: number;
}

/** One cell on one surface. */
export interface CellRecord {
  readonly id: number;
  /** Site position in 3D, µm. */
  readonly position: Vec3;
  /** Site position on the unrolled surface, µm (u around/along x, v along y). */
  readonly surface: [number, number];
  /** Cell area, µm². */
  readonly area: number;
  readonly neighbours: NeighbourContact[];
  /** The cell touches an open edge of the domain (the ends of a tube). */
  readonly touchesBorder: boolean;
}

export type GridRecord = Pick<Grid, 'width' | 'height' | 'texelX' | 'texelY' | 'periodicX' | 'periodicY'>;

/** A surface other than the seeded one: an intermediate layer or the other side of the sheet. */
export interface SurfaceRecord {
  /** "basal", "apical", or "layer k" (k = 1 next to the seeded surface). */
  readonly name: string;
  readonly role: 'layer' | 'other';
  /** Signed distance from the seeded surface along its normal, µm (outward > 0 on a tube). */
  readonly offset: number;
  /** Size of this surface relative to the seeded one around the tube (R / R_seeded); 1 on a plane. */
  readonly ratio: number;
  readonly grid: GridRecord;
  /** Labels-based cells of the projected sites on this surface. */
  readonly cells: CellRecord[];
}

export type { AnalysisRecord, CellStatisticsRecord } from '../core/analysis/record';
export type { Headline } from '../core/analysis/headline';

/** The documented output of `tissue-sheet run` (see README, "Result JSON"). */
export interface SheetResult {
  readonly software: { readonly name: 'tissue-sheet'; readonly version: string };
  /** The configuration with every default filled in: rerunning it reproduces this result. */
  readonly config: Config;
  readonly seed: number;
  readonly grid: GridRecord;
  /** The GPU engine's context and passes; null when the exact engine ran (see `engine`). */
  readonly gpu: {
    readonly renderer: string;
    readonly centroidPath: 'blend' | 'gather' | 'readback';
    readonly jumpFloodVariant: string;
  } | null;
  /** The engine that ran, chosen by the engine policy (src/run/enginePolicy.ts), and why. */
  readonly engine: EngineChoice;
  readonly lloyd: {
    readonly iterations: IterationRecord[];
    readonly converged: boolean;
    /** CVT energy of the final sites. */
    readonly finalEnergy: number;
    /** Cells that own no texel (never expected; non-zero means the grid is too coarse). */
    readonly emptyCells: number;
  };
  /** How the cells' neighbours (cells[], surfaces[].cells) were found: adjacent texels of the label textures, or exactly (exact engine). */
  readonly adjacency: { readonly method: 'labels' | 'exact' };
  readonly timings: { readonly setupMs: number; readonly lloydMs: number; readonly adjacencyMs: number; readonly totalMs: number };
  /** Cells of the seeded surface. */
  readonly cells: CellRecord[];
  /** Intermediate layers (seeded side first), then the other surface. */
  readonly surfaces: SurfaceRecord[];
  /** Statistics per adjacency method (core/config/analysisMethods.ts: labels and/or exact). */
  readonly analyses: AnalysisRecord[];
  /**
   * The number the page shows and `tissue-sheet run` prints: % scutoids of the headline method
   * (exact wherever it ran), with its counts, Voronoi k, uncertainty and by-construction note.
   */
  readonly headline: Headline | null;
  /** Why % scutoids is 0 whatever the sites (parallel planes, concentric spheres, ...), or null. */
  readonly byConstruction: ByConstruction | null;
  /** Closed surfaces only (sphere, ellipsoid, mesh): see docs/closed-surfaces.md. */
  readonly closed?: ClosedSurfaceRecord;
  /**
   * The files the config points to (mesh, density image) as the host read them, where it says
   * (the CLI does): a path in `config` names a file, not its contents.
   */
  readonly inputFiles?: readonly InputFileRecord[];
}

/** A file a run read for its config: which field named it, its size and SHA-256 digest. */
export interface InputFileRecord {
  readonly field: 'surface.src' | 'density.src';
  /** As the config gives it (a path relative to the config, or a URL). */
  readonly src: string;
  readonly bytes: number;
  /** Lower-case hexadecimal. */
  readonly sha256: string;
}

/** What a closed-surface run adds to the result (docs/closed-surfaces.md). */
export interface ClosedSurfaceRecord {
  readonly kind: 'sphere' | 'ellipsoid' | 'mesh';
  /** Texels per cube-face edge; the label images are n x 6n atlases (face f in rows f n .. f n + n - 1). */
  readonly n: number;
  /** Area of the seeded surface from the geometry image, µm². */
  readonly area: number;
  /** Centroid sums: "blend" (GPU additive blending) or "readback" (labels read back, reduced on the CPU in float64). */
  readonly centroidPath: 'blend' | 'readback';
  /** Smallest radius of curvature an offset was checked against (µm): R, c²/a, or the mesh estimate. */
  readonly minCurvatureRadius: number;
  /** Meshes: size, parameterization quality. */
  readonly mesh?: {
    readonly src: string;
    readonly vertices: number;
    readonly faces: number;
    readonly flipped: number;
    readonly areaDistortion: { readonly min: number; readonly max: number; readonly meanAbsLog: number };
    readonly parameterizationMs: number;
    readonly samplingMs: number;
    /** Set when the file's triangles were oriented inward and were flipped to point outward: says so in words. */
    readonly reoriented: string | null;
    /** 1 / (max edge curvature) of convex and concave regions, µm; null: no edge bends that way. */
    readonly curvatureRadius: { readonly convex: number | null; readonly concave: number | null };
  };
  /** `surface.geodesic`: heat-method geodesic Voronoi of the final sites on the mesh vertices. */
  readonly geodesic?: {
    readonly sites: number;
    readonly vertices: number;
    /** Heat-method setup (two sparse Cholesky factorizations), ms. */
    readonly setupMs: number;
    /** One heat-method distance field per site, all sites, ms. */
    readonly solveMs: number;
    readonly msPerSite: number;
    /** One cold jump flood of the same sites on the geometry image plus the readback, ms. */
    readonly gpuVoronoiMs: number;
    /** Fraction of mesh vertices whose geodesic label equals the geometry-image (3D distance) label. */
    readonly agreement: number;
  };
}

/** Label image of one surface, for views (not part of the JSON). */
export interface LabelImage {
  readonly name: string;
  readonly grid: Grid;
  /** Site id per texel, row-major (index y * width + x), -1 for none. */
  readonly labels: Int32Array;
  /**
   * Closed surfaces: the geometry image of this surface, x, y, z (µm) per texel in the order of
   * `labels` (the n x 6n cube-map atlas), so views draw the cells without re-deriving geometry.
   */
  readonly positions?: Float32Array;
}

/** What runSheet returns: the JSON result and, for views, the label image of every surface. */
export interface SheetOutput {
  readonly result: SheetResult;
  /** [seeded, layers..., other]. */
  readonly labelImages: LabelImage[];
  /** With RunOptions.cellTables: every per-cell list as columns (the result's lists are then empty). */
  readonly tables?: ResultCellTables;
}
