/**
 * The sweep spec's JSON Schema and its limits, apart from spec.ts so that
 * scripts/validators.ts can compile it into specValidator.generated.ts without importing the
 * validator that uses the generated module (the page's Content-Security-Policy forbids compiling
 * a schema at run time: docs/app.md, "Security").
 */
export const DEFAULT_MAX_RUNS = 100_000;
export const MAX_REALIZATIONS = 1_000_000;
export const MAX_VALUES_PER_FIELD = 100_000;
export const SEED_MODES = ['per-realization', 'per-run'] as const;

export const sweepSpecSchema = {
  $schema: 'http://json-schema.org/draft-07/schema#',
  title: 'tissue-sheet sweep spec',
  type: 'object',
  additionalProperties: false,
  required: ['base'],
  properties: {
    base: { type: 'object', description: 'The configuration every run starts from (docs/config.md).' },
    vary: {
      type: 'object',
      description: 'Dotted config paths, each with a non-empty array of values; the runs are their Cartesian product.',
      additionalProperties: { type: 'array', minItems: 1, maxItems: MAX_VALUES_PER_FIELD },
    },
    realizations: {
      type: 'integer',
      minimum: 1,
      maximum: MAX_REALIZATIONS,
      default: 1,
      description: `Runs per grid point with different seeds, integer 1..${MAX_REALIZATIONS}. Default 1.`,
    },
    seed: { type: 'integer', minimum: 0, maximum: 4294967295, description: 'Base seed, integer 0..4294967295. Default: base.seed.' },
    seedMode: {
      type: 'string',
      enum: SEED_MODES,
      default: 'per-realization',
      description: '"per-realization": every grid point of a realization shares its sites; "per-run": every run its own. Default "per-realization".',
    },
  },
} as const;
