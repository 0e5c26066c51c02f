/**
 * The sweep spec: its JSON Schema and its validation, done before any run.
 *
 * { "base": config, "vary": { "dotted.path": [values] }, "realizations": n, "seed": s,
 *   "seedMode": "per-realization" | "per-run" }
 *
 * - The shape (types, ranges, enums, no unknown field) is checked by ajv against sweepSpecSchema.
 * - No key anywhere may be `__proto__`, `constructor` or `prototype` (they reach prototypes).
 * - `base` is validated against the config schema (validateConfig).
 * - Every varied path must name a field of the config schema (through either branch of a union:
 *   `surface.radius` exists for tubes and spheres), and every value is validated at its path
 *   by validating the base with that value set.
 * - The number of runs (product of the value counts x realizations) is computed and capped
 *   before anything is expanded.
 * Errors are SweepSpecErrors whose message is one line starting with the field
 * (`realizations`, `vary["sheet.layers"][1]`, `base.cells`).
 */
import type { ErrorObject } from 'ajv';
import { configSchema, ConfigError, validateConfig, type Config } from '../config';
import { countRuns, FORBIDDEN_KEYS, setPath, type SweepSpec } from './expand';
import { DEFAULT_MAX_RUNS, MAX_REALIZATIONS, MAX_VALUES_PER_FIELD, SEED_MODES, sweepSpecSchema } from './specSchema';
import { validate as validateSweepSpecShape } from './specValidator.generated';

/** What the shape check guarantees (base is checked against the config schema afterwards). */
interface SweepSpecShape {
  base: unknown;
  vary?: Record<string, readonly unknown[]>;
  realizations: number;
  seed?: number;
  seedMode: 'per-run' | 'per-realization';
}
/** A standalone ajv validator: true when valid, else `errors[0]` says why. */
type GeneratedValidator = ((data: unknown) => data is SweepSpecShape) & { errors?: ErrorObject[] | null };

/** A sweep-spec problem: a ConfigError whose `field` is a path in the spec (`vary["sheet.layers"][1]`). */
export class SweepSpecError extends ConfigError {
  constructor(field: string, message: string) {
    super(field, message);
    this.name = 'SweepSpecError';
  }
}

// The shape check is compiled ahead of time (npm run validators:write) from specSchema.ts: the
// page's Content-Security-Policy has no 'unsafe-eval', so ajv cannot compile it at run time.
const validateShape = validateSweepSpecShape as GeneratedValidator;

export type ValidSweepSpec = SweepSpec<Config & Record<string, unknown>> & { realizations: number; seedMode: 'per-run' | 'per-realization' };

export interface SweepSpecOptions {
  /** Largest number of runs accepted (default DEFAULT_MAX_RUNS). */
  maxRuns?: number;
  /** How to raise the run cap, appended to its error (e.g. "pass --max-runs N"). */
  raiseHint?: string;
}

export function validateSweepSpec(input: unknown, options: SweepSpecOptions = {}): ValidSweepSpec {
  if (typeof input !== 'object' || input === null || Array.isArray(input)) {
    throw new SweepSpecError('', 'sweep spec: must be a JSON object with "base" (a config) and usually "vary" and "realizations"');
  }
  const forbidden = findForbiddenKey(input, []);
  if (forbidden) {
    const key = [...FORBIDDEN_KEYS].find((k) => forbidden.includes(k)) ?? forbidden;
    throw new SweepSpecError(forbidden, `${forbidden}: "${key}" is not allowed as a key or path part (it would reach an object prototype); remove it`);
  }
  const spec: unknown = structuredClone(input);
  if (!validateShape(spec)) throw shapeError(validateShape.errors?.[0]);
  const vary = (spec.vary ?? {}) as Record<string, unknown[]>;

  let base: Config;
  try {
    base = validateConfig(spec.base);
  } catch (error) {
    if (error instanceof ConfigError) throw new SweepSpecError(`base.${error.field}`, `base.${error.message}`);
    throw error;
  }
  for (const path of Object.keys(vary)) checkVariedPath(path);
  for (const [path, values] of Object.entries(vary)) checkDistinctValues(path, values);

  const maxRuns = options.maxRuns ?? DEFAULT_MAX_RUNS;
  // A NaN cap would let every spec through (no count is above NaN): a caller's mistake, said.
  if (!(maxRuns >= 1)) throw new RangeError(`validateSweepSpec: maxRuns must be a number >= 1 (got ${String(maxRuns)})`);
  const runs = countRuns(spec);
  if (runs > maxRuns) {
    const sizes = Object.entries(vary).map(([p, v]) => `${v.length} ${p}`);
    throw new SweepSpecError(
      'vary',
      `vary: this spec expands to ${runs} runs (${[...sizes, `${spec.realizations} realizations`].join(' x ')}), above the limit of ${maxRuns}; use fewer values or realizations${options.raiseHint ? `, or ${options.raiseHint}` : ''}`,
    );
  }

  // Every value alone at its path: the error names the value, not a later grid point.
  for (const [path, values] of Object.entries(vary)) {
    values.forEach((value, index) => {
      const config = structuredClone(spec.base) as Record<string, unknown>;
      setPath(config, path, structuredClone(value));
      try {
        validateConfig(config);
      } catch (error) {
        if (!(error instanceof ConfigError)) throw error;
        const field = `vary["${path}"][${index}]`;
        const detail = error.field === path ? error.message.slice(path.length + 2) : error.message;
        throw new SweepSpecError(field, `${field}: ${detail}`);
      }
    });
  }
  void base;
  return spec as ValidSweepSpec;
}

/**
 * Each value of a varied field once: a grid point and its runs are keyed by the values' JSON
 * (expand.ts), so a repeated value would make two points of one key, whose runs could be neither
 * told apart nor resumed.
 */
function checkDistinctValues(path: string, values: readonly unknown[]): void {
  const first = new Map<string, number>();
  values.forEach((value, index) => {
    const text = JSON.stringify(value);
    const earlier = first.get(text);
    if (earlier !== undefined) {
      const field = `vary["${path}"][${index}]`;
      throw new SweepSpecError(field, `${field}: ${text} repeats vary["${path}"][${earlier}]; give each value once (realizations repeat a grid point)`);
    }
    first.set(text, index);
  });
}

/** The first key named __proto__, constructor or prototype, as a path; undefined when none. */
export function findForbiddenKey(value: unknown, path: string[]): string | undefined {
  if (value === null || typeof value !== 'object') return undefined;
  for (const key of Object.keys(value)) {
    const here = Array.isArray(value) ? `${path.join('.')}[${key}]` : [...path, key].join('.');
    if (!Array.isArray(value) && FORBIDDEN_KEYS.has(key)) return here;
    // vary's keys are dotted paths: check their parts too.
    if (path.length === 1 && path[0] === 'vary' && key.split('.').some((p) => FORBIDDEN_KEYS.has(p))) return `vary["${key}"]`;
    const found = findForbiddenKey((value as Record<string, unknown>)[key], Array.isArray(value) ? [`${path.join('.')}[${key}]`] : [...path, key]);
    if (found) return found;
  }
  return undefined;
}

type SchemaNode = { properties?: Record<string, SchemaNode>; oneOf?: readonly SchemaNode[] };

/** Refuses a varied path that names no field of the config schema, listing the fields there. */
function checkVariedPath(path: string): void {
  const field = `vary["${path}"]`;
  if (path === 'seed') {
    throw new SweepSpecError(field, `${field}: the seed is derived per run from "seed" and "seedMode"; vary "realizations" instead`);
  }
  let nodes: SchemaNode[] = [configSchema as SchemaNode];
  const parts = path.split('.');
  for (let k = 0; k < parts.length; k++) {
    const part = parts[k];
    const branches = nodes.flatMap((n) => [n, ...(n.oneOf ?? [])]);
    const next = branches.map((n) => n.properties?.[part]).filter((n): n is SchemaNode => n !== undefined);
    if (part === '' || next.length === 0) {
      const here = parts.slice(0, k).join('.');
      const allowed = [...new Set(branches.flatMap((n) => Object.keys(n.properties ?? {})))];
      const where = here === '' ? 'the config' : `"${here}"`;
      throw new SweepSpecError(
        field,
        allowed.length > 0
          ? `${field}: "${part}" is not a field of ${where}; fields there: ${allowed.join(', ')}`
          : `${field}: "${here}" has no fields inside; vary "${here}" itself`,
      );
    }
    nodes = next;
  }
}

function shapeError(error: { instancePath: string; keyword: string; params: Record<string, unknown>; message?: string } | undefined): SweepSpecError {
  if (!error) return new SweepSpecError('', 'sweep spec: invalid');
  const parts = error.instancePath
    .split('/')
    .slice(1)
    .map((p) => p.replace(/~1/g, '/').replace(/~0/g, '~'));
  const field = parts.length === 0 ? '' : parts[0] === 'vary' && parts.length > 1 ? `vary["${parts[1]}"]` : parts.join('.');
  const where = field === '' ? 'sweep spec' : field;
  switch (error.keyword) {
    case 'additionalProperties': {
      const extra = String(error.params.additionalProperty);
      return new SweepSpecError(extra, `${extra}: unknown field of a sweep spec; allowed: ${Object.keys(sweepSpecSchema.properties).join(', ')}`);
    }
    case 'required':
      return new SweepSpecError(String(error.params.missingProperty), `${String(error.params.missingProperty)}: required; add the base config object`);
    case 'enum':
      return new SweepSpecError(field, `${where}: must be one of ${SEED_MODES.map((m) => JSON.stringify(m)).join(', ')}`);
    case 'type':
      if (parts[0] === 'vary' && parts.length > 1) return new SweepSpecError(field, `${where}: must be an array of values`);
      return new SweepSpecError(field, `${where}: must be ${error.params.type === 'integer' ? 'an integer' : `of type ${String(error.params.type)}`}`);
    case 'minItems':
      return new SweepSpecError(field, `${where}: must list at least one value`);
    case 'maxItems':
      return new SweepSpecError(field, `${where}: lists more than ${MAX_VALUES_PER_FIELD} values; use fewer`);
    case 'minimum':
    case 'maximum':
      return new SweepSpecError(field, `${where}: must be an integer from ${field === 'seed' ? '0 to 4294967295' : `1 to ${MAX_REALIZATIONS}`}`);
    default:
      return new SweepSpecError(field, `${where}: ${error.message ?? 'invalid'}`);
  }
}
