/** Validation of a configuration against the schema, with one-line errors naming the field. */
import type { ErrorObject } from 'ajv';
import { validate as generatedValidate } from './configValidator.generated';
import { ConfigError } from './configError';
import { defaultResolution } from './surfaceLayout';
import type { Config } from './types';

// ---------------------------------------------------------------------------------------------
// Validation
// ---------------------------------------------------------------------------------------------

export { ConfigError } from './configError';

type SchemaNode = Record<string, unknown>;

/** What the schema validates: an Config whose resolution may still be null. */
type Unresolved<T> = T extends unknown ? Omit<T, 'resolution'> & { resolution: number | null } : never;
/**
 * A valid configuration with every default filled in except a resolution left null ("the
 * default": defaultResolution of the surface, the cells and the contact rule). Forms and links
 * keep this form, so the default follows later changes of the fields it depends on until the
 * user sets a resolution; validateConfig gives the number a run records.
 */
export type ConfigDraft = Unresolved<Config>;
/**
 * The schema's validator, compiled ahead of time from configSchema by scripts/validators.ts
 * (npm run validators:write; `npm test` checks it is current): the page's Content-Security-Policy
 * has no 'unsafe-eval', so ajv cannot compile it at run time. It fills defaults in place, stops at
 * the first error and gives verbose errors (their schema node is where messages find ranges and
 * units).
 */
const validate = generatedValidate as ((data: unknown) => data is Unresolved<Config>) & { errors?: ErrorObject[] | null };

/**
 * Checks `input`, fills every default and returns a fresh object (the input is never modified).
 * Throws ConfigError with a one-line message naming the field, the problem, the value given
 * and what to change.
 */
export function validateConfig(input: unknown): Config {
  const data = validateConfigDraft(input);
  // The resolution a null asks for depends on the surface and the cells: fill it in, so the
  // returned config (and every result) records the number that ran.
  return { ...data, resolution: data.resolution ?? defaultResolution(data) };
}

/** validateConfig, keeping a null (or missing) resolution null: see ConfigDraft. */
export function validateConfigDraft(input: unknown): ConfigDraft {
  // Clone first: ajv writes defaults into the object it validates, and NaN/Infinity (which
  // JSON cannot carry but JS objects can) must be caught with their path before ajv sees them.
  const data = cloneJson(input, []);
  if (!validate(data)) {
    const error = validate.errors?.[0];
    if (!error) throw new ConfigError('', 'config: invalid');
    throw toConfigError(error);
  }
  return data;
}

/** Keys that reach an object's prototype when assigned or walked: refused anywhere in a config. */
const PROTOTYPE_KEYS: ReadonlySet<string> = new Set(['__proto__', 'constructor', 'prototype']);

/**
 * `value` as plain JSON data (a copy), or a ConfigError naming the first bad value's path.
 * `path` is the value's path, extended and restored in place as the walk goes down and up (no
 * path array per value: a sweep's threads validate every run's config).
 */
function cloneJson(value: unknown, path: (string | number)[]): unknown {
  if (value === null || typeof value === 'string' || typeof value === 'boolean') return value;
  // A config is a few levels deep: deeper is an object that refers to itself (or a crafted one).
  if (path.length > MAX_DEPTH) {
    const field = formatPath(path.slice(0, 3));
    throw new ConfigError(field, `${label(field)}: nested more than ${MAX_DEPTH} levels deep (an object that contains itself?); give plain JSON data`);
  }
  if (typeof value === 'number') {
    if (!Number.isFinite(value)) {
      const field = formatPath(path);
      throw new ConfigError(field, `${label(field)}: must be a finite number (got ${String(value)}); give a finite value`);
    }
    return value;
  }
  if (Array.isArray(value)) {
    const out = new Array<unknown>(value.length);
    for (let index = 0; index < value.length; index++) {
      path.push(index);
      out[index] = cloneJson(value[index], path);
      path.pop();
    }
    return out;
  }
  if (typeof value === 'object' && isPlainObject(value, path)) {
    const out: Record<string, unknown> = {};
    // A getter or a Proxy may throw: said as the field it is, not as the caller's error.
    const unreadable = (key: string | null, error: unknown): ConfigError => {
      const field = formatPath(key === null ? path : [...path, key]);
      return new ConfigError(field, `${label(field)}: could not be read (${error instanceof Error ? error.message : String(error)}); give plain JSON data`);
    };
    let keys: string[];
    try {
      keys = Object.keys(value);
    } catch (error) {
      throw unreadable(null, error);
    }
    for (const key of keys) {
      let item: unknown;
      try {
        item = (value as Record<string, unknown>)[key];
      } catch (error) {
        throw unreadable(key, error);
      }
      // JSON.parse keeps "__proto__" as an own key; `out[key] = ...` would then set the
      // prototype. Refuse these keys: any other key assigned below is an own data property
      // (Object.prototype's one accessor is __proto__), as defineProperty made it, at a fraction
      // of its cost.
      if (PROTOTYPE_KEYS.has(key)) {
        const field = formatPath([...path, key]);
        throw new ConfigError(field, `${field}: "${key}" is not allowed as a key (it would reach an object prototype); remove it`);
      }
      if (item === undefined) continue; // `{radius: undefined}` means "not given", as in JSON.
      path.push(key);
      const copy = cloneJson(item, path);
      path.pop();
      out[key] = copy;
    }
    return out;
  }
  const field = formatPath(path);
  throw new ConfigError(field, `${label(field)}: must be JSON data (got a ${describeType(value)}); use numbers, strings, booleans, arrays and plain objects`);
}

/** An object whose prototype is Object.prototype or null (a Proxy's trap may throw: said as its field). */
function isPlainObject(value: object, path: (string | number)[]): boolean {
  let prototype: unknown;
  try {
    prototype = Object.getPrototypeOf(value);
  } catch (error) {
    const field = formatPath(path);
    throw new ConfigError(field, `${label(field)}: could not be read (${error instanceof Error ? error.message : String(error)}); give plain JSON data`);
  }
  return prototype === Object.prototype || prototype === null;
}

/** How deep a config's data may nest (the schema's deepest field is 4 levels down). */
const MAX_DEPTH = 32;

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
      const what = missing === 'kind' ? kindChoices(schema) : properties[missing] ? expectation(properties[missing], true) : 'a value';
      return new ConfigError(field, `${field}: required${where}; add ${what}`);
    }
    case 'discriminator': {
      const field = formatPath([...path, 'kind']);
      const value = formatValue((error.params as { tagValue?: unknown }).tagValue);
      return new ConfigError(field, `${field}: must be ${kindChoices(schema)} (got ${value})`);
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

/** `one of "plane", "tube"`: the kinds of the union `schema` (surface or density), from its branches. */
function kindChoices(schema: SchemaNode): string {
  const branches = Array.isArray(schema.oneOf) ? (schema.oneOf as SchemaNode[]) : [];
  const kinds = branches.map((branch) => JSON.stringify(((branch.properties ?? {}) as Record<string, SchemaNode>).kind?.const));
  return `one of ${kinds.join(', ')}`;
}
