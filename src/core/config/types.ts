/**
 * The run configuration's TypeScript types, computed from configSchema (schema.ts): a field
 * added, removed or retyped there changes these types with no second edit. `Config` (a
 * `PlanarConfig` or a `ClosedConfig`) and its parts are what `validateConfig` returns, every
 * default filled in; `ConfigInput` is what a user may write.
 */
import type { FromSchema } from './fromSchema';
import type { configSchema } from './schema';

/** Any validated configuration, its surface any kind (the schema's own reading). */
type SchemaConfig = FromSchema<typeof configSchema>;

/** Every surface kind the schema knows. */
export type AnySurfaceConfig = SchemaConfig['surface'];
type PlaneSurface = Extract<AnySurfaceConfig, { kind: 'plane' }>;
type TubeSurface = Extract<AnySurfaceConfig, { kind: 'tube' }>;
/** Surfaces unrolled to a rectangle (the planar pipeline: plane, tube). */
export type SurfaceConfig = PlaneSurface | TubeSurface;

/** A closed genus-0 triangle mesh (OBJ, PLY, STL), coordinates times `scale` in µm. */
export type MeshSurface = Extract<AnySurfaceConfig, { kind: 'mesh' }>;
/** Closed surfaces, sampled on a cube-map geometry image: every kind that is not unrolled. */
export type ClosedSurfaceConfig = Exclude<AnySurfaceConfig, SurfaceConfig>;

export type DensitySpec = SchemaConfig['density'];
export type LinearDensity = Extract<DensitySpec, { kind: 'linear' }>;
export type GaussianDensity = Extract<DensitySpec, { kind: 'gaussian' }>;
export type StripesDensity = Extract<DensitySpec, { kind: 'stripes' }>;

export type LloydConfig = SchemaConfig['lloyd'];
/** The sheet: which surface is seeded, and where the other surface and the layers lie. */
export type SheetConfig = SchemaConfig['sheet'];

/** A validated configuration on a plane or a tube: every field present, every default filled in. */
export interface PlanarConfig extends Omit<SchemaConfig, 'surface' | 'resolution'> {
  surface: SurfaceConfig;
  /** Always a number once validated: validation resolves null (see defaultResolution). */
  resolution: number;
}
/** A validated configuration on a closed surface (sphere, ellipsoid, mesh). */
export interface ClosedConfig extends Omit<SchemaConfig, 'surface' | 'resolution'> {
  surface: ClosedSurfaceConfig;
  /** Always a number once validated: validation resolves null (see defaultResolution). */
  resolution: number;
}
/** Any validated configuration: planar (PlanarConfig) or closed (ClosedConfig). */
export type Config = PlanarConfig | ClosedConfig;

/** The closed kinds as a value (for runtime checks); the compiler keeps it equal to ClosedSurfaceConfig's kinds. */
const CLOSED_SURFACE_KINDS = ['sphere', 'ellipsoid', 'mesh'] as const satisfies readonly ClosedSurfaceConfig['kind'][];
// A closed kind added to the schema but missing from the list above fails to compile here.
const closedKindsListed: Exclude<ClosedSurfaceConfig['kind'], (typeof CLOSED_SURFACE_KINDS)[number]> extends never ? true : never = true;
void closedKindsListed;

export function isClosedConfig(config: Config): config is ClosedConfig {
  return isClosedKind(config.surface.kind);
}

/** Whether a surface kind is closed (sphere, ellipsoid, mesh: a cube map) rather than planar (plane, tube). */
export function isClosedKind(kind: string): boolean {
  return (CLOSED_SURFACE_KINDS as readonly string[]).includes(kind);
}

/** What a user may write: any field with a default may be left out. */
export type ConfigInput = FromSchema<typeof configSchema, 'input'>;
