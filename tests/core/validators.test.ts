/**
 * The precompiled validators (scripts/validatorsCode.ts) against ajv compiling the same schemas
 * at run time, the reference they replace: on a corpus of configs and sweep specs with every
 * field mutated, both must agree on validity, the first error (keyword, path, params, schema
 * node, data) and the defaults they fill in. And the committed modules must be what the schemas
 * give today (the same check as `npm run validators:check`).
 */
import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import Ajv from 'ajv';
import { describe, expect, it } from 'vitest';
import { configSchema } from '../../src/core/config';
import { validate as generatedConfig } from '../../src/core/config/configValidator.generated';
import { sweepSpecSchema } from '../../src/core/sweep/specSchema';
import { validate as generatedSpec } from '../../src/core/sweep/specValidator.generated';
import { renderValidators } from '../../scripts/validatorsCode';

type Validator = ((data: unknown) => boolean) & { errors?: unknown[] | null };
type Json = null | boolean | number | string | Json[] | { [key: string]: Json };
type SchemaNode = {
  type?: unknown;
  properties?: Record<string, SchemaNode>;
  oneOf?: SchemaNode[];
  required?: string[];
  minimum?: number;
  exclusiveMinimum?: number;
  minItems?: number;
  enum?: unknown[];
  const?: unknown;
};

const root = fileURLToPath(new URL('../../', import.meta.url));

function runtimeConfigValidator(): Validator {
  const ajv = new Ajv({ useDefaults: true, allErrors: false, discriminator: true, verbose: true, strict: true, strictRequired: false });
  ajv.addVocabulary(['unit']);
  return ajv.compile(configSchema) as Validator;
}

/** A value `node` accepts, as a first guess (ranges from the schema; combinations may still fail). */
function sample(node: SchemaNode): Json {
  if (node.const !== undefined) return node.const as Json;
  if (Array.isArray(node.enum)) return node.enum[0] as Json;
  const type = Array.isArray(node.type) ? node.type[0] : node.type;
  switch (type) {
    case 'number':
    case 'integer':
      return node.minimum ?? (node.exclusiveMinimum !== undefined ? node.exclusiveMinimum + 1 : 1);
    case 'string':
      return 'a.png';
    case 'boolean':
      return true;
    case 'array':
      return Array.from({ length: node.minItems ?? 1 }, () => 0.5);
    default:
      return {};
  }
}

/** One config per surface kind and per density kind: each branch's required fields filled in. */
function baseConfigs(): Json[] {
  const props = (configSchema as unknown as SchemaNode).properties ?? {};
  const branch = (b: SchemaNode) => Object.fromEntries((b.required ?? []).map((key) => [key, sample(b.properties?.[key] ?? {})]));
  const surfaces = (props.surface.oneOf ?? []).map((b) => ({ surface: branch(b), cells: 50 }));
  const densities = (props.density.oneOf ?? []).map((b) => ({ density: branch(b), cells: 50 }));
  return [{}, ...surfaces, ...densities];
}

/** Every path (array of keys) inside `value`, the root included. */
function paths(value: Json, at: (string | number)[] = []): (string | number)[][] {
  const out = [at];
  if (Array.isArray(value)) value.forEach((item, i) => out.push(...paths(item, [...at, i])));
  else if (value !== null && typeof value === 'object') for (const [key, item] of Object.entries(value)) out.push(...paths(item, [...at, key]));
  return out;
}

function withValue(value: Json, path: (string | number)[], replacement: Json | undefined): Json {
  if (path.length === 0) return replacement as Json;
  const copy = structuredClone(value) as Record<string | number, Json>;
  let node = copy;
  for (const key of path.slice(0, -1)) node = node[key] as Record<string | number, Json>;
  if (replacement === undefined) delete node[path[path.length - 1]];
  else node[path[path.length - 1]] = replacement;
  return copy as Json;
}

const MUTATIONS: (Json | undefined)[] = [undefined, 'x', '', -1, 0, 0.5, 3, 1e12, null, true, [], [1], [1, 2, 3], {}, { kind: 'nope' }, { extra: 1 }];

/** Every input and its mutations, each through both validators: validity, first error, filled data. */
function compare(reference: Validator, generated: Validator, bases: Json[], extraKeys: Json[] = []): number {
  let compared = 0;
  for (const base of bases) {
    // Fill the defaults first so that the mutations reach every field the schema knows.
    const filled = structuredClone(base);
    reference(filled);
    for (const path of paths(filled)) {
      for (const mutation of [...MUTATIONS, ...extraKeys]) {
        const input = withValue(filled, path, mutation);
        const a = structuredClone(input);
        const b = structuredClone(input);
        const okA = reference(a);
        const okB = generated(b);
        expect(okB, JSON.stringify(input)).toBe(okA);
        expect(b).toEqual(a);
        if (!okA) expect(generated.errors?.[0], JSON.stringify(input)).toEqual(reference.errors?.[0]);
        compared++;
      }
    }
  }
  return compared;
}

describe('precompiled validators', () => {
  it('are the modules the schemas give today (npm run validators:write regenerates them)', () => {
    const files = renderValidators();
    expect(files.map((f) => f.path).sort()).toEqual(['src/core/config/configValidator.generated.ts', 'src/core/sweep/specValidator.generated.ts']);
    for (const file of files) expect(readFileSync(`${root}${file.path}`, 'utf8'), file.path).toBe(file.text);
  });

  it('compile nothing at run time: no eval, no Function constructor, no import', () => {
    for (const file of renderValidators()) {
      expect(file.text).not.toMatch(/\bnew Function\b|\beval\(|\brequire\(|^import /m);
    }
  });

  it('the config validator agrees with ajv compiling the schema at run time on every field mutated', () => {
    const count = compare(runtimeConfigValidator(), generatedConfig as unknown as Validator, baseConfigs());
    expect(count).toBeGreaterThan(1000);
  });

  it('the sweep-spec validator agrees with ajv compiling its schema at run time', () => {
    const ajv = new Ajv({ useDefaults: true, allErrors: false, strict: true });
    const reference = ajv.compile(sweepSpecSchema) as Validator;
    const bases: Json[] = [
      JSON.parse(readFileSync(`${root}examples/sweep-small.json`, 'utf8')) as Json,
      { base: {}, vary: { cells: [10, 20] }, realizations: 3, seed: 5, seedMode: 'per-run' },
      {},
    ];
    const count = compare(reference, generatedSpec as unknown as Validator, bases);
    expect(count).toBeGreaterThan(100);
  });
});
