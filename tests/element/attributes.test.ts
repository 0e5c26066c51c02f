import { describe, expect, it } from 'vitest';
import { configFromAttributes } from '../../src/element/attributes';
import { ConfigError, validateConfig, type ConfigInput } from '../../src/core/config';
import { surfaceOfKind } from '../../src/core/config/presets';

/**
 * The element's attributes onto a configuration (no page: an element is its attributes here). A
 * surface attribute of another kind starts from that kind's own defaults, the same surface
 * whatever the kind before it, and a change of layout drops the resolution to the new default.
 */

const element = (attributes: Record<string, string>) =>
  ({
    getAttribute: (name: string) => attributes[name] ?? null,
    hasAttribute: (name: string) => name in attributes,
  }) as unknown as Element;

describe('configFromAttributes', () => {
  it('gives the schema defaults without attributes', () => {
    expect(configFromAttributes(element({}), null)).toEqual(validateConfig({}));
  });

  it('starts a new kind from its defaults, whatever the kind before', () => {
    for (const kind of ['plane', 'tube', 'sphere', 'ellipsoid', 'mesh']) {
      const fromTube = configFromAttributes(element({ surface: kind }), null);
      const fromSphere = configFromAttributes(element({ surface: kind }), { surface: { kind: 'sphere', radius: 70 }, resolution: 64 });
      expect(fromTube.surface.kind).toBe(kind);
      if (kind !== 'sphere') expect(fromSphere.surface).toEqual(fromTube.surface);
      // A closed kind's surface is its preset's; a planar kind keeps the default tube's unrolled size.
      expect(fromTube.surface).toEqual(validateConfig({ surface: surfaceOfKind(validateConfig({}).surface, kind) }).surface);
    }
  });

  it('drops the resolution across layouts, keeps it within one, and an attribute overrides both', () => {
    const base: ConfigInput = { surface: { kind: 'sphere', radius: 70 }, resolution: 64 };
    expect(configFromAttributes(element({ surface: 'ellipsoid' }), base).resolution).toBe(64);
    expect(configFromAttributes(element({ surface: 'tube' }), base).resolution).toBe(validateConfig({}).resolution);
    expect(configFromAttributes(element({ surface: 'tube', resolution: '256' }), base).resolution).toBe(256);
  });

  it('refuses a density that is not a preset, naming the attribute and the kinds (never uniform in silence)', () => {
    for (const value of ['evil', 'gausian', '']) {
      let error: unknown = null;
      try {
        configFromAttributes(element({ density: value }), null);
      } catch (e) {
        error = e;
      }
      expect(error).toBeInstanceOf(ConfigError);
      expect((error as ConfigError).field).toBe('density.kind');
      expect((error as Error).message).toBe(`density: must be one of "uniform", "linear", "gaussian", "stripes", "image" (got "${value}")`);
    }
    expect(configFromAttributes(element({ density: 'gaussian' }), null).density.kind).toBe('gaussian');
    expect(configFromAttributes(element({ density: ' stripes ' }), null).density.kind).toBe('stripes');
  });
});
