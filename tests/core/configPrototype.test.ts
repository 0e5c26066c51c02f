/**
 * Issue 19: `__proto__`, `constructor` and `prototype` are refused anywhere in a config with one
 * line naming the path, and validation never reaches Object.prototype. Inputs come from
 * JSON.parse, which keeps "__proto__" as an own key (as a link or a file does).
 */
import { afterEach, describe, expect, it } from 'vitest';
import { ConfigError, validateConfig } from '../../src/core/config';

/** The ConfigError validateConfig throws for `input`, checked to name `field`. */
function refusedAt(input: unknown, field: string): ConfigError {
  let error: unknown;
  try {
    validateConfig(input);
  } catch (e) {
    error = e;
  }
  expect(error, field).toBeInstanceOf(ConfigError);
  expect((error as ConfigError).field).toBe(field);
  return error as ConfigError;
}

const POLLUTED = ['polluted', 'cells', 'layers', 'radius'];

afterEach(() => {
  for (const key of POLLUTED) delete (Object.prototype as Record<string, unknown>)[key];
});

function refusal(json: string): ConfigError {
  try {
    validateConfig(JSON.parse(json));
  } catch (error) {
    expect(error).toBeInstanceOf(ConfigError);
    return error as ConfigError;
  }
  throw new Error(`expected ${json} to be refused`);
}

describe('prototype keys in a config', () => {
  const cases: [json: string, field: string][] = [];
  for (const key of ['__proto__', 'constructor', 'prototype']) {
    cases.push([`{"${key}": {"polluted": 1}}`, key]);
    cases.push([`{"cells": 20, "sheet": {"${key}": {"layers": 3}}}`, `sheet.${key}`]);
    cases.push([`{"surface": {"kind": "tube", "radius": 10, "length": 100, "${key}": {"polluted": true}}}`, `surface.${key}`]);
    cases.push([`{"density": {"kind": "gaussian", "center": [1, {"${key}": 2}]}}`, `density.center[1].${key}`]);
  }
  it.each(cases)('%s is refused naming %s', (json, field) => {
    const error = refusal(json);
    expect(error.field).toBe(field);
    const key = field
      .split(/[.[\]]/)
      .filter(Boolean)
      .pop()!;
    expect(error.message).toBe(`${field}: "${key}" is not allowed as a key (it would reach an object prototype); remove it`);
    expect(error.message).not.toContain('\n');
    for (const name of POLLUTED) expect(Object.prototype.hasOwnProperty.call(Object.prototype, name), name).toBe(false);
    expect(({} as Record<string, unknown>).polluted).toBeUndefined();
  });

  it('a valid config is returned with plain objects whose keys are own properties', () => {
    const config = validateConfig(JSON.parse('{"cells": 30, "sheet": {"layers": 2}}')) as unknown as Record<string, Record<string, unknown>>;
    expect(Object.getPrototypeOf(config.sheet)).toBe(Object.prototype);
    expect(Object.keys(config.sheet)).toContain('layers');
    expect(config.sheet.layers).toBe(2);
  });

  it('a key that merely contains the words is accepted by the prototype check (the schema decides)', () => {
    const error = refusal('{"cells": 20, "sheet": {"my__proto__": 1}}');
    expect(error.message).toMatch(/^sheet\.my__proto__: unknown field/);
  });
  it('a value JSON cannot carry is refused naming its path, wherever it is (the walk restores the path it extends)', () => {
    const cases: [unknown, string][] = [
      [{ cells: NaN }, 'cells'],
      [{ density: { kind: 'gaussian', center: [1, Infinity] } }, 'density.center[1]'],
      [{ cells: 20, density: { kind: 'gaussian', center: [1, 2], sigma: -Infinity } }, 'density.sigma'],
      [{ sheet: { layers: 2 }, surface: { kind: 'tube', radius: 10, length: () => 1 } }, 'surface.length'],
    ];
    for (const [input, field] of cases) {
      const error = refusedAt(input, field);
      expect(error.message.startsWith(`${field}: must be `)).toBe(true);
    }
  });

  it('an object that contains itself, a throwing getter or Proxy trap: a ConfigError naming the field, not the caller error', () => {
    const cyclic: Record<string, unknown> = { cells: 20 };
    cyclic.sheet = cyclic;
    const getter = {
      surface: {
        kind: 'tube',
        radius: 10,
        get length(): number {
          throw new Error('boom');
        },
      },
    };
    const keys = {
      cells: 20,
      sheet: new Proxy(
        {},
        {
          ownKeys: () => {
            throw new Error('no keys');
          },
        },
      ),
    };
    const prototype = {
      cells: 20,
      lloyd: new Proxy(
        {},
        {
          getPrototypeOf: () => {
            throw new Error('no prototype');
          },
        },
      ),
    };
    const cases: [unknown, string, RegExp][] = [
      [cyclic, 'sheet.sheet.sheet', /nested more than 32 levels deep \(an object that contains itself\?\)/],
      [getter, 'surface.length', /^surface\.length: could not be read \(boom\)/],
      [keys, 'sheet', /^sheet: could not be read \(no keys\)/],
      [prototype, 'lloyd', /^lloyd: could not be read \(no prototype\)/],
    ];
    for (const [input, field, message] of cases) expect(refusedAt(input, field).message).toMatch(message);
  });
});
