/**
 * The run configuration's JSON Schema: the single source of truth for every field's type,
 * unit, range, default and description. The same document drives validation and default
 * filling (ajv `useDefaults`, validate.ts), the TypeScript types (types.ts), the app's panel
 * fields and the element's attributes (through schemaFields.ts) and docs/config.md
 * (`npm run docs:write`; `npm run docs:check` fails when the committed page differs), so they
 * cannot drift apart. Descriptions say what a field means; its unit, range and default are
 * keywords, not prose. Unions (`surface`, `density`) use ajv's `discriminator` on `kind`, so
 * an error inside a union names the branch the user meant instead of "must match exactly one
 * schema".
 */
// ---------------------------------------------------------------------------------------------
// Schema
// ---------------------------------------------------------------------------------------------

/** Circumference 512 µm: the published tube (512 x 4096 px at 1 µm per px). */
export const DEFAULT_TUBE_RADIUS = 512 / (2 * Math.PI);

/**
 * `unit` is an annotation keyword of ours (registered with ajv in validate.ts): error messages print it
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
        'The surface the sheet lies on, chosen by "kind": "plane" or "tube" (unrolled to a rectangle: x across, y along), or the closed surfaces "sphere", "ellipsoid" and "mesh" (sampled on a cube map). The default is the published tube: circumference 512 µm, length 4096 µm.',
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
            kind: kindConst('plane', 'A flat rectangle, optionally periodic along x and/or y.'),
            width: positiveUm('Extent along x.'),
            height: positiveUm('Extent along y.'),
            periodicX: { type: 'boolean', default: false, description: 'Whether x wraps around.' },
            periodicY: { type: 'boolean', default: false, description: 'Whether y wraps around (both: a flat torus).' },
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'radius', 'length'],
          properties: {
            kind: kindConst('tube', 'A cylinder: x runs around it and wraps, y runs along its axis and has two open ends.'),
            radius: positiveUm('Radius of the seeded surface; the x extent is the circumference 2π·radius.'),
            length: positiveUm('Length along the axis (the y extent).'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'radius'],
          properties: {
            kind: kindConst('sphere', 'A sphere centred at the origin (closed: no border cells).'),
            radius: positiveUm('Radius of the seeded surface.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'a', 'b', 'c'],
          properties: {
            kind: kindConst('ellipsoid', 'The ellipsoid x²/a² + y²/b² + z²/c² = 1 centred at the origin (closed; a spheroid when two semi-axes are equal).'),
            a: positiveUm('Semi-axis along x.'),
            b: positiveUm('Semi-axis along y.'),
            c: positiveUm('Semi-axis along z.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'src'],
          properties: {
            kind: kindConst('mesh', 'A closed, manifold, genus-0 triangle mesh (OBJ, PLY or STL), mapped to the sphere and sampled on a cube map.'),
            src: {
              type: 'string',
              minLength: 1,
              description:
                "An .obj, .ply or .stl file. The pipeline reads no file: the CLI reads a path (relative to the config file, else the working directory, else a sample of public/meshes/ by name), the page a URL or a user's uploaded file by its name; a library caller loads it (tissue-sheet/node loadMeshFile, or fetchMeshFile) and passes it to runSheet as meshFile.",
            },
            scale: {
              type: 'number',
              exclusiveMinimum: 0,
              unit: 'µm per mesh unit',
              default: 1,
              description: 'Multiplies the mesh coordinates: µm per mesh coordinate unit.',
            },
            geodesic: {
              type: 'boolean',
              default: false,
              description:
                'Also compute the heat-method geodesic Voronoi of the final sites on the mesh vertices; the result reports its time and the fraction of vertices it labels like the GPU Voronoi.',
            },
          },
        },
      ],
    },
    resolution: {
      type: ['integer', 'null'],
      minimum: 16,
      maximum: 16384,
      default: null,
      description:
        'Texels along the longer side of the unrolled domain; closed surfaces: texels along each cube-face edge (6·resolution² texels in all). null: 512 on planes and tubes; on closed surfaces chosen from the number of cells and the minimum contact length, so that a texel edge is at most half the shortest counted contact (docs/closed-surfaces.md). Validation replaces null by the number, so results record it.',
    },
    cells: { type: 'integer', minimum: 1, default: 200, description: 'Number of cells (sites).' },
    seed: {
      type: 'integer',
      minimum: 0,
      maximum: 4294967295,
      default: 1,
      description: 'Seed of the random site placement: same configuration and seed, same sites.',
    },
    minSpacing: {
      type: 'number',
      minimum: 0,
      unit: 'µm',
      default: 0,
      description: 'Minimum distance between the initial sites, measured across periodic seams (0: no constraint).',
    },
    density: {
      description:
        'Relative cell density over the unrolled domain, chosen by "kind": cells are smaller where it is higher (in 2D, cell diameter ~ density^(-1/4)), and the initial sites follow it too. Densities are relative and unitless.',
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
            kind: kindConst('linear', 'Density varying linearly along one axis: from at coordinate 0, to at its end.'),
            axis: axis('Axis along which the density varies.'),
            from: positive('Density at the start (coordinate 0) of the axis.'),
            to: positive('Density at the end of the axis.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'center', 'sigma', 'peak'],
          properties: {
            kind: kindConst('gaussian', 'Density 1 + (peak - 1)·exp(-r²/2σ²), r the distance to the centre (measured across periodic seams).'),
            center: {
              type: 'array',
              items: { type: 'number' },
              minItems: 2,
              maxItems: 2,
              unit: 'µm',
              description: 'Centre [u, v] in the unrolled domain, inside it: 0 <= u <= x extent, 0 <= v <= y extent.',
            },
            sigma: positiveUm('Standard deviation σ of the bump.'),
            peak: positive('Density at the centre (< 1 gives a dip).'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'axis', 'period', 'low', 'high'],
          properties: {
            kind: kindConst('stripes', 'Square wave along one axis from coordinate 0: low on the first half of each period, high on the second.'),
            axis: axis('Axis across which the stripes alternate.'),
            period: positiveUm('Period of the stripes (the axis length gives two halves: low, then high).'),
            low: positive('Density on the first half of each period.'),
            high: positive('Density on the second half of each period.'),
          },
        },
        {
          type: 'object',
          additionalProperties: false,
          required: ['kind', 'src'],
          properties: {
            kind: kindConst('image', 'A grayscale PNG stretched over the unrolled domain: black -> low, white -> high, linear in luminance between.'),
            src: {
              type: 'string',
              minLength: 1,
              description: 'Path of a PNG file (the CLI resolves it relative to the configuration file).',
            },
            low: { type: 'number', exclusiveMinimum: 0, default: 1, description: 'Density for black.' },
            high: { type: 'number', exclusiveMinimum: 0, default: 16, description: 'Density for white.' },
            invert: { type: 'boolean', default: false, description: 'Swap black and white.' },
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
          description: 'Lloyd iterations at most (0: random Voronoi, "Voronoi 1"; k-1 iterations give "Voronoi k").',
        },
        tolerance: {
          type: 'number',
          minimum: 0,
          unit: 'µm',
          default: 0,
          description: 'Stop once no site moves farther than this in one iteration (0: run all iterations).',
        },
        overRelaxation: {
          type: 'number',
          minimum: 1,
          maximum: 1.95,
          default: 1,
          description: 'Over-relaxation factor ω: each site moves to site + ω·(centroid - site); 1 is plain Lloyd (energy never increases).',
        },
        warmStart: {
          type: 'boolean',
          default: true,
          description: "Start each jump flood from the previous iteration's labels.",
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
          description: 'Pass schedule: "jfa" (plain: steps N/2 ... 1), "jfa+2" (with extra steps 2 and 1) or "1+jfa" (one step 1 first).',
        },
      },
    },
    centroidPath: {
      type: 'string',
      enum: ['auto', 'blend', 'gather', 'readback'],
      default: 'auto',
      description:
        'How the centroid sums are computed: "blend" (additive float blending, needs EXT_float_blend), "gather" (portable GPU pass), "readback" (site ids read back and summed on the CPU) or "auto" (blend on a GPU with EXT_float_blend, gather on one without, readback on software renderers).',
    },
    engine: {
      type: 'string',
      enum: ['auto', 'gpu', 'exact'],
      default: 'auto',
      description:
        'Which engine runs Lloyd and finds the neighbours: "gpu" (jump flood and centroid passes in WebGL2), "exact" (planes and tubes only: Lloyd on the exact Voronoi diagram on the CPU, every analysis exact, no label textures) or "auto" (exact on planes and tubes where the renderer is software, e.g. SwiftShader or llvmpipe, and sheet.adjacency is not "labels" alone (with "both", the labels method is then left out and the result says so under headline.omittedMethods); the GPU otherwise). The result records which engine ran and why.',
    },
    sheet: {
      description: 'The sheet: the seeded surface (where Lloyd runs), the other surface at a thickness along the normal, and layers between them.',
      type: 'object',
      default: {},
      additionalProperties: false,
      properties: {
        seeded: {
          type: 'string',
          enum: ['basal', 'apical'],
          default: 'basal',
          description: 'Which surface the sites are seeded and relaxed on; the other one gets the projected sites.',
        },
        direction: {
          type: 'string',
          enum: ['outward', 'inward'],
          default: 'outward',
          description: 'Side of the seeded surface the other surface lies on, along its normal: "outward" is +z on a plane, away from the axis on a tube.',
        },
        thickness: {
          type: 'number',
          minimum: 0,
          unit: 'µm',
          default: 0,
          description:
            "Distance between the two surfaces along the normal (closed surfaces: the outward normal). Inward, it must stay below a tube's radius and below a closed surface's smallest radius of curvature.",
        },
        surfaceRatio: {
          type: ['number', 'null'],
          minimum: 1,
          default: null,
          description: 'Tube only, instead of thickness: s = R_outer / R_inner (outward: the other radius is radius·s; inward: radius/s). null: use thickness.',
        },
        offset: {
          type: 'string',
          enum: ['normal', 'axes'],
          default: 'normal',
          description:
            'Closed surfaces: how the other surface and the layers are made. "normal": the parallel surface, each site moved along its normal by the thickness. "axes" (sphere and ellipsoid; the lab\'s spheroid model): the ellipsoid with semi-axes a + t, b + t, c + t at thickness t, each site moved to its closest point on it. With lloyd.maxIterations 0 and minSpacing, the sites are random with a minimum distance, as the lab seeds them.',
        },
        layers: {
          type: 'integer',
          minimum: 0,
          maximum: 64,
          default: 0,
          description: 'Intermediate surfaces evenly spaced (in radius) between the two, each with its own Voronoi diagram.',
        },
        adjacency: {
          type: 'string',
          enum: ['labels', 'exact', 'both'],
          default: 'both',
          description:
            'How neighbours are found on every surface: "labels" (adjacent texels of the label textures), "exact" (Delaunay of the unrolled sites with periodic copies) or "both".',
        },
        protocol: {
          type: 'string',
          enum: ['default', 'lab'],
          default: 'default',
          description:
            'Which rules the statistics follow (docs/protocols.md): "default" (valid cells decided on the analysed surfaces, layers as given) or "lab" (tubes with a surface ratio, outward: the published protocol of Gómez-Gálvez et al.: layers every sheet.layerStep of s, a cell is valid only if it touches no open end on any layer s = 1 : layerStep : validityMaxRatio, intercalations accumulated over the layers, the pixel contact rule for the labels method).',
        },
        layerStep: {
          type: ['number', 'null'],
          exclusiveMinimum: 0,
          default: null,
          description:
            'Layers at a fixed step instead of sheet.layers: in surface-ratio units on a tube (s = 1, 1 + step, ..., the other surface), in µm of thickness elsewhere. null: sheet.layers evenly spaced; 0.25 under protocol "lab".',
        },
        validityMaxRatio: {
          type: 'number',
          minimum: 1,
          maximum: 100,
          default: 10,
          description: 'Protocol "lab": a cell is valid only if it touches no open end on any layer from s = 1 up to this ratio (in steps of sheet.layerStep).',
        },
        minContactPixels: {
          type: ['number', 'null'],
          minimum: 0,
          maximum: 64,
          default: null,
          description:
            'Labels method: ignore contacts shorter than this many texel edges of an image 512 px around the seeded tube (the lab\'s pixel rule; scaled to this grid). null: sheet.minContactLength; 6 under protocol "lab".',
        },
        minContactLength: {
          type: ['number', 'null'],
          minimum: 0,
          unit: 'µm',
          default: null,
          description:
            "Labels method: ignore contacts shorter than this. null: the lab's 6 px for cells 102.4 px across (200 cells on 512 x 4096 px), scaled to this sheet: 6/102.4 x sqrt(seeded area / cells), exactly 6 µm on the published tube.",
        },
      },
    },
  },
} as const;
