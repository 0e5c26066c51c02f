/**
 * The run configuration's JSON Schema: the single source of truth for fields, defaults and
 * ranges. The same document drives validation, default filling (ajv `useDefaults`) and the
 * reference in docs/config.md, so they cannot drift apart. Unions (`surface`, `density`) use
 * ajv's `discriminator` on `kind`, so an error inside a union names the branch the user meant
 * instead of "must match exactly one schema".
 */
// ---------------------------------------------------------------------------------------------
// Schema
// ---------------------------------------------------------------------------------------------

/** Circumference 512 µm: the published tube (512 x 4096 px at 1 µm per px). */
export const DEFAULT_TUBE_RADIUS = 512 / (2 * Math.PI);

/**
 * `unit` is an annotation keyword of ours (registered with ajv below): error messages print it
 * after numbers. Everything else is plain draft-07.
 */
const positiveUm = (description: string) => ({ type: 'number', exclusiveMinimum: 0, unit: 'µm', description }) as const;
const positive = (description: string) => ({ type: 'number', exclusiveMinimum: 0, description }) as const;
const axis = (description: string) => ({ type: 'string', enum: ['x', 'y'], description }) as const;
const kindConst = <K extends string>(kind: K, description: string) => ({ type: 'string', const: kind, description }) as const;

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
              unit: 'µm per mesh unit',
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
      enum: ['auto', 'blend', 'gather', 'readback'],
      default: 'auto',
      description:
        'Centroid sums: "blend" (additive float blending, needs EXT_float_blend), "gather" (portable GPU pass), "readback" (site ids read back and summed on the CPU) or "auto" (blend on a GPU with EXT_float_blend, gather on one without, readback on software renderers). Default "auto".',
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
