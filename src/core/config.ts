/**
 * The run configuration: its JSON Schema (the single source of truth for fields, defaults and
 * ranges), the TypeScript types, validation with one-line errors, and the grid it implies.
 *
 * Why a schema and not hand-written checks: the same document drives validation, default
 * filling (ajv `useDefaults`) and the reference in docs/config.md, so they cannot drift apart.
 * Unions (`surface`, `density`) use ajv's `discriminator` on `kind`, so an error inside a union
 * names the branch the user meant instead of "must match exactly one schema".
 */
import Ajv, { type ErrorObject } from 'ajv';
import type { Grid } from './grid';

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
export type CentroidPathName = 'auto' | 'blend' | 'gather';

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

// ---------------------------------------------------------------------------------------------
// Schema
// ---------------------------------------------------------------------------------------------

/** Circumference 512 µm: the published tube (512 x 4096 px at 1 µm per px). */
export const DEFAULT_TUBE_RADIUS = 512 / (2 * Math.PI);

/**
 * `unit` is an annotation keyword of ours (registered with ajv below): error messages print it
 * after numbers. Everything else is plain draft-07.
 */
const positiveUm = (description: string) => ({ type: 'number', exclusiveMinimum: 0, unit: 'µm', description });
const positive = (description: string) => ({ type: 'number', exclusiveMinimum: 0, description });
const axis = (description: string) => ({ type: 'string', enum: ['x', 'y'], description });
const kindConst = (kind: string, description: string) => ({ type: 'string', const: kind, description });

export const configSchema = {
  $schema: 'http://json-schema.org/draft-07/schema#',
  $id: 'https://tissue-sheet.example/config.schema.json',
  title: 'tissue-sheet run configuration',
  type: 'object',
  additionalProperties: false,
  properties: {
    surface: {
      description:
        'The surface the sheet lies on. Chosen by "kind": "plane" or "tube" (unrolled to a rectangle: x across, y along), or the closed surfaces "sphere", "ellipsoid" and "mesh" (sampled on a cube map). Default: the published tube (circumference 512 µm, length 4096 µm).',
      type: 'object',
      default: { kind: 'tube', radius: DEFAULT_TUBE_RADIUS, length: 4096 },
      required: ['kind'],
      discriminator: { propertyName: 'kind' },
      oneOf: [
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'width', 'height'],
          properties: {
            kind: kindConst('plane', 'A flat rectangle, optionally periodic along x and/or y (a flat torus).'),
            width: positiveUm('Extent along x, µm, > 0.'),
            height: positiveUm('Extent along y, µm, > 0.'),
            periodicX: { type: 'boolean', default: false, description: 'Whether x wraps around (true/false). Default false.' },
            periodicY: { type: 'boolean', default: false, description: 'Whether y wraps around (true/false). Default false.' },
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'radius', 'length'],
          properties: {
            kind: kindConst('tube', 'A cylinder: x runs around it (periodic), y along its axis (open ends).'),
            radius: positiveUm('Radius of the seeded surface, µm, > 0. Circumference 2π·radius is the x extent.'),
            length: positiveUm('Length along the axis, µm, > 0 (the y extent).'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'radius'],
          properties: {
            kind: kindConst('sphere', 'A sphere centred at the origin (closed: no border cells).'),
            radius: positiveUm('Radius of the seeded surface, µm, > 0.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'a', 'b', 'c'],
          properties: {
            kind: kindConst('ellipsoid', 'An ellipsoid x²/a² + y²/b² + z²/c² = 1 centred at the origin (closed).'),
            a: positiveUm('Semi-axis along x, µm, > 0.'),
            b: positiveUm('Semi-axis along y, µm, > 0.'),
            c: positiveUm('Semi-axis along z, µm, > 0.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'src'],
          properties: {
            kind: kindConst('mesh', 'A closed genus-0 triangle mesh (OBJ, PLY or STL), mapped to the sphere and sampled on a cube map.'),
            src: {
              type: 'string',
              minLength: 1,
              description: 'Path (Node: relative to the working directory, or public/meshes/NAME) or URL (browser) of an .obj, .ply or .stl file, non-empty.',
            },
            scale: {
              type: 'number',
              exclusiveMinimum: 0,
              default: 1,
              description: 'µm per mesh coordinate unit, > 0. Default 1.',
            },
            geodesic: {
              type: 'boolean',
              default: false,
              description:
                'Also compute the heat-method geodesic Voronoi of the final sites on the mesh vertices and report its time and its agreement with the GPU Voronoi (true/false). Default false.',
            },
          },
        },
      ],
    },
    resolution: {
      type: 'integer',
      minimum: 16,
      maximum: 16384,
      default: 512,
      description:
        'Texels along the longer side of the unrolled domain, integer 16..16384; closed surfaces: texels along each cube-face edge (6 x resolution² texels). Default 512.',
    },
    cells: { type: 'integer', minimum: 1, default: 200, description: 'Number of cells (sites), integer >= 1. Default 200.' },
    seed: {
      type: 'integer',
      minimum: 0,
      maximum: 4294967295,
      default: 1,
      description: 'Seed of the random site placement, integer 0..4294967295. Default 1.',
    },
    minSpacing: {
      type: 'number',
      minimum: 0,
      unit: 'µm',
      default: 0,
      description: 'Minimum distance between initial sites, µm, >= 0 (0: no constraint). Default 0.',
    },
    density: {
      description:
        'Cell density (relative, unitless, > 0) over the unrolled domain; cells are smaller where it is higher (diameter ~ density^-1/4). Chosen by "kind". Default uniform.',
      type: 'object',
      default: { kind: 'uniform' },
      required: ['kind'],
      discriminator: { propertyName: 'kind' },
      oneOf: [
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind'],
          properties: { kind: kindConst('uniform', 'Density 1 everywhere.') },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'axis', 'from', 'to'],
          properties: {
            kind: kindConst('linear', 'Density varying linearly along one axis.'),
            axis: axis('Axis along which density varies: "x" or "y".'),
            from: positive('Density at the start (coordinate 0) of the axis, unitless, > 0.'),
            to: positive('Density at the end of the axis, unitless, > 0.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'center', 'sigma', 'peak'],
          properties: {
            kind: kindConst('gaussian', 'Density 1 + (peak - 1)·exp(-r²/2σ²), r measured with wrap on periodic axes.'),
            center: {
              type: 'array',
              items: { type: 'number' },
              minItems: 2,
              maxItems: 2,
              unit: 'µm',
              description: 'Centre [u, v] in µm in the unrolled domain, 0 <= u <= x extent, 0 <= v <= y extent.',
            },
            sigma: positiveUm('Standard deviation, µm, > 0.'),
            peak: positive('Density at the centre, unitless, > 0 (< 1 gives a dip).'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'axis', 'period', 'low', 'high'],
          properties: {
            kind: kindConst('stripes', 'Square wave along one axis: low on the first half of each period, high on the second.'),
            axis: axis('Axis across which the stripes alternate: "x" or "y".'),
            period: positiveUm('Period, µm, > 0, starting at coordinate 0 (the axis length gives two halves: low, then high).'),
            low: positive('Density on the first half of each period, unitless, > 0.'),
            high: positive('Density on the second half of each period, unitless, > 0.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'src'],
          properties: {
            kind: kindConst('image', 'A grayscale PNG stretched over the unrolled domain: black -> low, white -> high.'),
            src: {
              type: 'string',
              minLength: 1,
              description: 'Path of a PNG file (relative to the config file for the CLI), non-empty.',
            },
            low: { type: 'number', exclusiveMinimum: 0, default: 1, description: 'Density for black, unitless, > 0. Default 1.' },
            high: { type: 'number', exclusiveMinimum: 0, default: 16, description: 'Density for white, unitless, > 0. Default 16.' },
            invert: { type: 'boolean', default: false, description: 'Swap black and white (true/false). Default false.' },
          },
        },
      ],
    },
    lloyd: {
      description: "Lloyd's iterations (Voronoi, move each site to its cell's centroid, repeat).",
      type: 'object',
      default: {},
      additionalProperties: false,
      properties: {
        maxIterations: {
          type: 'integer',
          minimum: 0,
          maximum: 100000,
          default: 50,
          description: 'Number of Lloyd iterations at most, integer 0..100000 (0: random Voronoi). Default 50.',
        },
        tolerance: {
          type: 'number',
          minimum: 0,
          unit: 'µm',
          default: 0,
          description: 'Stop once no site moves farther than this, µm, >= 0 (0: run all iterations). Default 0.',
        },
        overRelaxation: {
          type: 'number',
          minimum: 1,
          maximum: 1.95,
          default: 1,
          description: 'Over-relaxation factor ω, 1..1.95 (1: plain Lloyd, energy never increases). Default 1.',
        },
        warmStart: {
          type: 'boolean',
          default: true,
          description: "Start each jump flood from the previous iteration's labels (true/false). Default true.",
        },
      },
    },
    jumpFlood: {
      description: 'Jump flooding (GPU nearest-site labelling).',
      type: 'object',
      default: {},
      additionalProperties: false,
      properties: {
        variant: {
          type: 'string',
          enum: ['jfa+2', '1+jfa', 'jfa'],
          default: 'jfa+2',
          description: 'Pass schedule: "jfa+2" (extra steps 2, 1), "1+jfa" (step 1 first) or "jfa" (plain). Default "jfa+2".',
        },
      },
    },
    centroidPath: {
      type: 'string',
      enum: ['auto', 'blend', 'gather'],
      default: 'auto',
      description:
        'Centroid pass: "blend" (additive float blending, needs EXT_float_blend), "gather" (portable) or "auto" (blend when available). Default "auto".',
    },
    sheet: {
      description:
        'The sheet: the seeded surface (where Lloyd runs), the other surface at a thickness along the normal, and layers between them.',
      type: 'object',
      default: {},
      additionalProperties: false,
      properties: {
        seeded: {
          type: 'string',
          enum: ['basal', 'apical'],
          default: 'basal',
          description: 'Which surface the sites are seeded and relaxed on: "basal" or "apical"; the other one gets the projected sites. Default "basal".',
        },
        direction: {
          type: 'string',
          enum: ['outward', 'inward'],
          default: 'outward',
          description:
            'Side of the seeded surface the other surface lies on, along its normal: "outward" (plane: +z; tube: away from the axis) or "inward". Default "outward".',
        },
        thickness: {
          type: 'number',
          minimum: 0,
          unit: 'µm',
          default: 0,
          description: 'Distance between the two surfaces along the normal, µm, >= 0 (inward on a tube: less than the radius). Default 0.',
        },
        surfaceRatio: {
          type: ['number', 'null'],
          minimum: 1,
          default: null,
          description:
            'Tube only: R_outer / R_inner, >= 1, instead of thickness (outward: the other radius is radius·s; inward: radius/s). null: use thickness. Default null.',
        },
        layers: {
          type: 'integer',
          minimum: 0,
          maximum: 64,
          default: 0,
          description: 'Intermediate surfaces evenly spaced between the two, integer 0..64, each with its own Voronoi diagram. Default 0.',
        },
        adjacency: {
          type: 'string',
          enum: ['labels', 'exact', 'both'],
          default: 'both',
          description:
            'How neighbours are found on every surface: "labels" (adjacent texels of the label textures), "exact" (Delaunay of the unrolled sites with periodic copies) or "both". Default "both".',
        },
        minContactLength: {
          type: ['number', 'null'],
          minimum: 0,
          unit: 'µm',
          default: null,
          description:
            "Labels method: ignore contacts shorter than this, µm, >= 0. null: the lab's 6 px for cells 102.4 px across, scaled to this sheet: 6/102.4 x sqrt(area / cells) (6 µm on the published tube). Default null.",
        },
      },
    },
  },
} as const;

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

/** A configuration problem. `field` is a dotted path (`surface.radius`, `density.center[1]`). */
export class ConfigError extends Error {
  readonly field: string;
  constructor(field: string, message: string) {
    super(message);
    this.name = 'ConfigError';
    this.field = field;
  }
}

type SchemaNode = Record<string, unknown>;

// One compiled validator per module: compiling is the slow part, validating is cheap.
// verbose: errors carry their schema node, which is where messages find ranges and units.
const ajv = new Ajv({ useDefaults: true, allErrors: false, discriminator: true, verbose: true, strict: true, strictRequired: false });
// strictRequired is off because the discriminator's `required: ['kind']` is defined in the branches.
ajv.addVocabulary(['unit']);
const validate = ajv.compile(configSchema as unknown as SchemaNode);

/**
 * Checks `input`, fills every default and returns a fresh object (the input is never modified).
 * Throws ConfigError with a one-line message naming the field, the problem, the value given
 * and what to change.
 */
export function validateAnyConfig(input: unknown): AnyConfig {
  // Clone first: ajv writes defaults into the object it validates, and NaN/Infinity (which
  // JSON cannot carry but JS objects can) must be caught with their path before ajv sees them.
  const data = cloneJson(input, []);
  if (!validate(data)) {
    const error = validate.errors?.[0];
    if (!error) throw new ConfigError('', 'config: invalid');
    throw toConfigError(error);
  }
  return data as AnyConfig;
}

/**
 * validateAnyConfig for the planar pipeline: a closed surface (sphere, ellipsoid, mesh) is
 * refused here, because callers of this function read planar fields (width, radius, length);
 * entry points that run closed surfaces too call validateAnyConfig and runSheet.
 */
export function validateConfig(input: unknown): Config {
  const config = validateAnyConfig(input);
  if (isClosedConfig(config)) {
    throw new ConfigError(
      'surface.kind',
      `surface.kind: "${config.surface.kind}" is a closed surface, which this entry point does not run; use one of "plane", "tube" here (closed surfaces run through validateAnyConfig and runSheet)`,
    );
  }
  return config;
}

function cloneJson(value: unknown, path: (string | number)[]): unknown {
  if (value === null || typeof value === 'string' || typeof value === 'boolean') return value;
  if (typeof value === 'number') {
    if (!Number.isFinite(value)) {
      const field = formatPath(path);
      throw new ConfigError(field, `${label(field)}: must be a finite number (got ${String(value)}); give a finite value`);
    }
    return value;
  }
  if (Array.isArray(value)) return value.map((item, index) => cloneJson(item, [...path, index]));
  if (typeof value === 'object' && (Object.getPrototypeOf(value) === Object.prototype || Object.getPrototypeOf(value) === null)) {
    const out: Record<string, unknown> = {};
    for (const [key, item] of Object.entries(value as Record<string, unknown>)) {
      if (item === undefined) continue; // `{radius: undefined}` means "not given", as in JSON.
      out[key] = cloneJson(item, [...path, key]);
    }
    return out;
  }
  const field = formatPath(path);
  throw new ConfigError(field, `${label(field)}: must be JSON data (got a ${describeType(value)}); use numbers, strings, booleans, arrays and plain objects`);
}

function describeType(value: unknown): string {
  if (typeof value === 'object' && value !== null) return (value as object).constructor?.name ?? 'object';
  return typeof value;
}

function formatPath(path: (string | number)[]): string {
  let out = '';
  for (const part of path) {
    if (typeof part === 'number') out += `[${part}]`;
    else out += out === '' ? part : `.${part}`;
  }
  return out;
}

function label(field: string): string {
  return field === '' ? 'config' : field;
}

/** ajv's JSON Pointer (`/surface/radius`, `/density/center/1`) as a path array. */
function parsePointer(pointer: string): (string | number)[] {
  if (pointer === '') return [];
  return pointer
    .slice(1)
    .split('/')
    .map((part) => part.replace(/~1/g, '/').replace(/~0/g, '~'))
    .map((part) => (/^\d+$/.test(part) ? Number(part) : part));
}

function formatValue(value: unknown): string {
  const text = typeof value === 'number' ? String(value) : JSON.stringify(value);
  if (text === undefined) return String(value);
  return text.length > 60 ? `${text.slice(0, 57)}...` : text;
}

/** "an integer from 16 to 16384", "a number > 0 µm", "one of "x", "y"": what a field accepts. */
function expectation(schema: SchemaNode, withType: boolean): string {
  // A nullable number (type ["number", "null"]): describe the number, and say null is allowed.
  if (Array.isArray(schema.type) && schema.type.includes('null')) {
    const type = schema.type.find((t) => t !== 'null');
    return `${expectation({ ...schema, type }, withType)} or null`;
  }
  if (Array.isArray(schema.enum)) return `one of ${schema.enum.map((v) => JSON.stringify(v)).join(', ')}`;
  if (schema.const !== undefined) return JSON.stringify(schema.const);
  switch (schema.type) {
    case 'boolean':
      return 'true or false';
    case 'string':
      return schema.minLength ? 'a non-empty string' : 'a string';
    case 'array':
      return `an array of ${String(schema.minItems)} numbers${schema.unit ? ` (${String(schema.unit)})` : ''}`;
    case 'object':
      return 'an object';
    case 'number':
    case 'integer': {
      const unit = schema.unit ? ` ${String(schema.unit)}` : '';
      const lo = schema.minimum as number | undefined;
      const hi = schema.maximum as number | undefined;
      const base = schema.type === 'integer' ? 'an integer' : 'a number';
      let range: string;
      if (lo !== undefined && hi !== undefined) range = `from ${lo} to ${hi}${unit}`;
      else if (schema.exclusiveMinimum !== undefined) range = `> ${String(schema.exclusiveMinimum)}${unit}`;
      else if (lo !== undefined) range = `>= ${lo}${unit}`;
      else if (hi !== undefined) range = `<= ${hi}${unit}`;
      else return `${base}${unit ? ` in${unit}` : ''}`;
      // "must be > 0 µm" reads better than "must be a number > 0 µm" once the type is right,
      // except for integers, whose range alone would hide the integer requirement.
      return withType || schema.type === 'integer' ? `${base} ${range}` : range;
    }
    default:
      return 'valid';
  }
}

function toConfigError(error: ErrorObject): ConfigError {
  const path = parsePointer(error.instancePath);
  const schema = (error.parentSchema ?? {}) as SchemaNode;
  const got = formatValue(error.data);
  switch (error.keyword) {
    case 'additionalProperties': {
      const extra = (error.params as { additionalProperty: string }).additionalProperty;
      const field = formatPath([...path, extra]);
      const allowed = Object.keys((schema.properties ?? {}) as object).join(', ');
      return new ConfigError(field, `${field}: unknown field; allowed: ${allowed}`);
    }
    case 'required': {
      const missing = (error.params as { missingProperty: string }).missingProperty;
      const field = formatPath([...path, missing]);
      const properties = (schema.properties ?? {}) as Record<string, SchemaNode>;
      const kind = (properties.kind?.const as string | undefined) ?? undefined;
      const where = kind !== undefined && missing !== 'kind' ? ` for kind ${JSON.stringify(kind)}` : '';
      const what = missing === 'kind' ? kindChoices(path) : properties[missing] ? expectation(properties[missing], true) : 'a value';
      return new ConfigError(field, `${field}: required${where}; add ${what}`);
    }
    case 'discriminator': {
      const field = formatPath([...path, 'kind']);
      const value = formatValue((error.params as { tagValue?: unknown }).tagValue);
      return new ConfigError(field, `${field}: must be ${kindChoices(path)} (got ${value})`);
    }
    case 'type': {
      const field = formatPath(path);
      return new ConfigError(field, `${label(field)}: must be ${expectation(schema, true)} (got ${got})`);
    }
    case 'minItems':
    case 'maxItems': {
      const field = formatPath(path);
      return new ConfigError(field, `${field}: must be ${expectation(schema, true)} (got ${got})`);
    }
    default: {
      // minimum, maximum, exclusiveMinimum, enum, const, minLength: the field's expectation says it all.
      const field = formatPath(path);
      return new ConfigError(field, `${label(field)}: must be ${expectation(schema, false)} (got ${got})`);
    }
  }
}

/** `one of "plane", "tube"` for the union at `path` (surface or density). */
function kindChoices(path: (string | number)[]): string {
  const top = path[0];
  const union = (configSchema.properties as Record<string, { oneOf?: readonly { properties: { kind: { const: string } } }[] }>)[
    String(top)
  ];
  const kinds = union?.oneOf?.map((branch) => JSON.stringify(branch.properties.kind.const)) ?? [];
  return `one of ${kinds.join(', ')}`;
}

// ---------------------------------------------------------------------------------------------
// Grid and feasibility
// ---------------------------------------------------------------------------------------------

/** The unrolled domain of a surface: its extents in µm and which axes wrap. */
export interface UnrolledDomain {
  lengthX: number;
  lengthY: number;
  periodicX: boolean;
  periodicY: boolean;
}

export function unrolledDomain(surface: SurfaceConfig): UnrolledDomain {
  if (surface.kind === 'tube') {
    return { lengthX: 2 * Math.PI * surface.radius, lengthY: surface.length, periodicX: true, periodicY: false };
  }
  return { lengthX: surface.width, lengthY: surface.height, periodicX: surface.periodicX, periodicY: surface.periodicY };
}

/**
 * The sampling grid: the longer side gets `resolution` texels, the other as many texels of the
 * same size as fit (rounded, at least 1). Texel sizes are then recomputed from the texel counts
 * so both lengths are exact; texels are square up to that rounding.
 */
export function makeGrid(config: Pick<Config, 'surface' | 'resolution'>): Grid {
  const domain = unrolledDomain(config.surface);
  const texel = Math.max(domain.lengthX, domain.lengthY) / config.resolution;
  const width = domain.lengthX >= domain.lengthY ? config.resolution : Math.max(1, Math.round(domain.lengthX / texel));
  const height = domain.lengthX >= domain.lengthY ? Math.max(1, Math.round(domain.lengthY / texel)) : config.resolution;
  return {
    width,
    height,
    texelX: domain.lengthX / width,
    texelY: domain.lengthY / height,
    periodicX: domain.periodicX,
    periodicY: domain.periodicY,
  };
}

/** Texels a cell needs at least for its centroid to mean something. */
export const MIN_TEXELS_PER_CELL = 16;

/** Area per point of the densest packing of points `spacing` apart (hexagonal lattice). */
function hexagonalAreaPerPoint(spacing: number): number {
  return (Math.sqrt(3) / 2) * spacing * spacing;
}

/**
 * Rejects configurations that validate but cannot run sensibly on this grid. These checks need
 * the grid (or several fields at once), which is why they are not in the schema.
 */
export function checkFeasible(config: Config, grid: Grid): void {
  const texels = grid.width * grid.height;
  if (config.cells * MIN_TEXELS_PER_CELL > texels) {
    const need = config.cells * MIN_TEXELS_PER_CELL;
    throw new ConfigError(
      'cells',
      `cells: ${config.cells} cells need at least ${need} texels (${MIN_TEXELS_PER_CELL} per cell) but the grid has ${texels}; lower cells or raise resolution`,
    );
  }

  const domain = unrolledDomain(config.surface);
  const d = config.minSpacing;
  if (d > 0 && config.cells > 1) {
    // Disks of diameter d around the sites do not overlap and stay within the domain grown by
    // d/2 on each open side; their packing density is at most that of the hexagonal lattice.
    // This is a necessary condition only: random dart throwing saturates well before it.
    const areaX = domain.lengthX + (domain.periodicX ? 0 : d);
    const areaY = domain.lengthY + (domain.periodicY ? 0 : d);
    const available = areaX * areaY;
    const needed = config.cells * hexagonalAreaPerPoint(d);
    if (needed > available) {
      const area = domain.lengthX * domain.lengthY;
      const largest = Math.sqrt(area / (config.cells * (Math.sqrt(3) / 2)));
      throw new ConfigError(
        'minSpacing',
        `minSpacing: ${config.cells} cells at least ${d} µm apart need ${fmt(needed)} µm² (hexagonal packing) but the surface has ${fmt(area)} µm²; lower minSpacing to at most ${fmt(largest)} µm or lower cells`,
      );
    }
  }

  checkSheet(config);

  if (config.density.kind === 'gaussian') {
    const [u, v] = config.density.center;
    if (u < 0 || u > domain.lengthX || v < 0 || v > domain.lengthY) {
      throw new ConfigError(
        'density.center',
        `density.center: [${u}, ${v}] µm is outside the domain [0, ${fmt(domain.lengthX)}] x [0, ${fmt(domain.lengthY)}] µm; move the centre inside`,
      );
    }
  }
}

/** The other surface must exist: a ratio only on a tube, an inward offset short of the axis. */
function checkSheet(config: Config): void {
  const { sheet, surface } = config;
  if (sheet.surfaceRatio !== null) {
    if (surface.kind !== 'tube') {
      throw new ConfigError(
        'sheet.surfaceRatio',
        `sheet.surfaceRatio: only a tube has a surface ratio (surface.kind is "${surface.kind}"); give sheet.thickness in µm instead`,
      );
    }
    if (sheet.thickness !== 0) {
      throw new ConfigError(
        'sheet.thickness',
        `sheet.thickness: give either sheet.thickness (${sheet.thickness} µm) or sheet.surfaceRatio (${sheet.surfaceRatio}), not both`,
      );
    }
  }
  if (surface.kind === 'tube' && sheet.direction === 'inward' && sheet.thickness >= surface.radius) {
    throw new ConfigError(
      'sheet.thickness',
      `sheet.thickness: ${sheet.thickness} µm inward reaches the tube's axis (radius ${fmt(surface.radius)} µm); use less than ${fmt(surface.radius)} µm or direction "outward"`,
    );
  }
}

function fmt(value: number): string {
  return Number(value.toPrecision(6)).toString();
}

// ---------------------------------------------------------------------------------------------
// Closed surfaces: cube-map size and feasibility
// ---------------------------------------------------------------------------------------------

/** The cube-map geometry image of a closed surface: n x n texels per face, 6 faces. */
export interface CubeGrid {
  /** Texels along each face edge (= config.resolution). */
  readonly n: number;
  readonly texels: number;
}

export function makeCubeGrid(config: Pick<ClosedConfig, 'resolution'>): CubeGrid {
  return { n: config.resolution, texels: 6 * config.resolution * config.resolution };
}

/** Surface area of an ellipsoid (Knud Thomsen's formula, relative error below 1.1 %). */
export function ellipsoidArea(a: number, b: number, c: number): number {
  const p = 1.6075;
  return 4 * Math.PI * (((a * b) ** p + (a * c) ** p + (b * c) ** p) / 3) ** (1 / p);
}

/**
 * Smallest principal radius of curvature of an analytic closed surface (µm): R for a sphere;
 * (smallest semi-axis)² / (largest semi-axis) for an ellipsoid (at the tips of the longest
 * axis). null for a mesh (estimated from the mesh at run time).
 */
export function minCurvatureRadius(surface: ClosedSurfaceConfig): number | null {
  if (surface.kind === 'sphere') return surface.radius;
  if (surface.kind === 'ellipsoid') {
    const lo = Math.min(surface.a, surface.b, surface.c);
    const hi = Math.max(surface.a, surface.b, surface.c);
    return (lo * lo) / hi;
  }
  return null;
}

/** The refusal of an inward offset that reaches a focal point of the surface. */
export function inwardOffsetError(thickness: number, radius: number, where: string): ConfigError {
  return new ConfigError(
    'sheet.thickness',
    `sheet.thickness: ${fmt(thickness)} µm inward reaches the smallest radius of curvature of the ${where} (${fmt(radius)} µm), where the offset surface folds over itself; use less than ${fmt(radius)} µm or direction "outward"`,
  );
}

/**
 * checkFeasible for closed surfaces: at most one cell per 16 texels of the 6 n² cube map,
 * uniform density only, minSpacing within hexagonal packing of the surface area (analytic
 * surfaces), no surfaceRatio, exact adjacency only on the sphere, and no inward offset at or
 * beyond the smallest radius of curvature (sphere, ellipsoid; a mesh is checked once loaded).
 */
export function checkClosedFeasible(config: ClosedConfig, grid: CubeGrid = makeCubeGrid(config)): void {
  if (config.cells * MIN_TEXELS_PER_CELL > grid.texels) {
    const need = config.cells * MIN_TEXELS_PER_CELL;
    throw new ConfigError(
      'cells',
      `cells: ${config.cells} cells need at least ${need} texels (${MIN_TEXELS_PER_CELL} per cell) but the cube map has ${grid.texels} (6 x ${grid.n}²); lower cells or raise resolution`,
    );
  }
  if (config.density.kind !== 'uniform') {
    throw new ConfigError(
      'density.kind',
      `density.kind: closed surfaces support only "uniform" density for now (got "${config.density.kind}")`,
    );
  }
  const { surface, sheet } = config;
  const d = config.minSpacing;
  if (d > 0 && config.cells > 1 && surface.kind !== 'mesh') {
    const area = surface.kind === 'sphere' ? 4 * Math.PI * surface.radius ** 2 : ellipsoidArea(surface.a, surface.b, surface.c);
    const needed = config.cells * hexagonalAreaPerPoint(d);
    if (needed > area) {
      const largest = Math.sqrt(area / (config.cells * (Math.sqrt(3) / 2)));
      throw new ConfigError(
        'minSpacing',
        `minSpacing: ${config.cells} cells at least ${d} µm apart need ${fmt(needed)} µm² (hexagonal packing) but the surface has ${fmt(area)} µm²; lower minSpacing to at most ${fmt(largest)} µm or lower cells`,
      );
    }
  }
  if (sheet.surfaceRatio !== null) {
    throw new ConfigError(
      'sheet.surfaceRatio',
      `sheet.surfaceRatio: only a tube has a surface ratio (surface.kind is "${surface.kind}"); give sheet.thickness in µm instead`,
    );
  }
  if (sheet.adjacency === 'exact' && surface.kind !== 'sphere') {
    throw new ConfigError(
      'sheet.adjacency',
      `sheet.adjacency: "exact" exists only on a sphere (the spherical Delaunay); use "labels" or "both" on a ${surface.kind}`,
    );
  }
  const radius = minCurvatureRadius(surface);
  if (radius !== null && sheet.direction === 'inward' && sheet.thickness >= radius) {
    throw inwardOffsetError(sheet.thickness, radius, surface.kind);
  }
}
