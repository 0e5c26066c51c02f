/** The run configuration's TypeScript types: what `validateAnyConfig` returns, fully defaulted. */
// ---------------------------------------------------------------------------------------------
// Types
// ---------------------------------------------------------------------------------------------

export interface PlaneSurface {
  kind: 'plane';
  width: number;
  height: number;
  periodicX: boolean;
  periodicY: boolean;
}
export interface TubeSurface {
  kind: 'tube';
  radius: number;
  length: number;
}
/** Surfaces unrolled to a rectangle (the planar pipeline: plane, tube). */
export type SurfaceConfig = PlaneSurface | TubeSurface;

/** A sphere of the given radius (µm), centred at the origin. */
export interface SphereSurface {
  kind: 'sphere';
  radius: number;
}
/** An ellipsoid x²/a² + y²/b² + z²/c² = 1 (semi-axes in µm), centred at the origin. */
export interface EllipsoidSurface {
  kind: 'ellipsoid';
  a: number;
  b: number;
  c: number;
}
/** A closed genus-0 triangle mesh (OBJ, PLY, STL), coordinates times `scale` in µm. */
export interface MeshSurface {
  kind: 'mesh';
  src: string;
  scale: number;
  geodesic: boolean;
}
/** Closed surfaces, sampled on a cube-map geometry image (src/run/closedSheet.ts). */
export type ClosedSurfaceConfig = SphereSurface | EllipsoidSurface | MeshSurface;

export type Axis = 'x' | 'y';
export interface UniformDensity {
  kind: 'uniform';
}
export interface LinearDensity {
  kind: 'linear';
  axis: Axis;
  from: number;
  to: number;
}
export interface GaussianDensity {
  kind: 'gaussian';
  center: [number, number];
  sigma: number;
  peak: number;
}
export interface StripesDensity {
  kind: 'stripes';
  axis: Axis;
  period: number;
  low: number;
  high: number;
}
export interface ImageDensity {
  kind: 'image';
  src: string;
  low: number;
  high: number;
  invert: boolean;
}
export type DensitySpec = UniformDensity | LinearDensity | GaussianDensity | StripesDensity | ImageDensity;

export interface LloydConfig {
  maxIterations: number;
  tolerance: number;
  overRelaxation: number;
  warmStart: boolean;
}
export type JumpFloodVariantName = 'jfa+2' | '1+jfa' | 'jfa';
export interface JumpFloodConfig {
  variant: JumpFloodVariantName;
}
export type CentroidPathName = 'auto' | 'blend' | 'gather' | 'readback';

/** The sheet: which surface is seeded, and where the other surface and the layers lie. */
export interface SheetConfig {
  seeded: 'basal' | 'apical';
  direction: 'outward' | 'inward';
  thickness: number;
  surfaceRatio: number | null;
  layers: number;
  adjacency: 'labels' | 'exact' | 'both';
  minContactLength: number | null;
}

/** A validated configuration: every field present, every default filled in. */
export interface Config {
  surface: SurfaceConfig;
  resolution: number;
  cells: number;
  seed: number;
  minSpacing: number;
  density: DensitySpec;
  lloyd: LloydConfig;
  jumpFlood: JumpFloodConfig;
  centroidPath: CentroidPathName;
  sheet: SheetConfig;
}

/** A validated configuration on a closed surface (sphere, ellipsoid, mesh). */
export interface ClosedConfig extends Omit<Config, 'surface'> {
  surface: ClosedSurfaceConfig;
}
/** Any validated configuration: planar (Config) or closed (ClosedConfig). */
export type AnyConfig = Config | ClosedConfig;

export const CLOSED_SURFACE_KINDS = ['sphere', 'ellipsoid', 'mesh'] as const;

export function isClosedConfig(config: AnyConfig): config is ClosedConfig {
  return (CLOSED_SURFACE_KINDS as readonly string[]).includes(config.surface.kind);
}

type Optional<T, K extends keyof T> = Omit<T, K> & Partial<Pick<T, K>>;

/** What a user may write: any field with a default may be left out. */
export interface ConfigInput {
  surface?:
    | Optional<PlaneSurface, 'periodicX' | 'periodicY'>
    | TubeSurface
    | SphereSurface
    | EllipsoidSurface
    | Optional<MeshSurface, 'scale' | 'geodesic'>;
  resolution?: number;
  cells?: number;
  seed?: number;
  minSpacing?: number;
  density?:
    | UniformDensity
    | LinearDensity
    | GaussianDensity
    | StripesDensity
    | Optional<ImageDensity, 'low' | 'high' | 'invert'>;
  lloyd?: Partial<LloydConfig>;
  jumpFlood?: Partial<JumpFloodConfig>;
  centroidPath?: CentroidPathName;
  sheet?: Partial<SheetConfig>;
}
