import { describe, expect, it } from 'vitest';
import { FIELDS } from '../../src/app/panels/fields';
import { configSchema, validateConfig, type Config } from '../../src/core/config';
import { APP_START, densityPreset, surfaceOfKind } from '../../src/core/config/presets';
import { schemaField } from '../../src/core/config/schemaFields';
import { ATTRIBUTES } from '../../src/element/attributes';

type Node = Record<string, unknown>;

/** Every leaf of the raw schema document: [path, union kind or null, node], read independently of schemaFields. */
function rawFields(): [string, string | null, Node][] {
  const out: [string, string | null, Node][] = [];
  const visit = (node: Node, path: string, kind: string | null) => {
    for (const [name, child] of Object.entries((node.properties ?? {}) as Record<string, Node>)) {
      const childPath = path ? `${path}.${name}` : name;
      if (Array.isArray(child.oneOf)) {
        for (const branch of child.oneOf as Node[]) {
          visit(branch, childPath, String(((branch.properties as Record<string, Node>).kind as Node).const));
        }
      } else if (child.type === 'object') visit(child, childPath, kind);
      else out.push([childPath, kind, child]);
    }
  };
  visit(configSchema, '', null);
  return out;
}

describe('schemaField', () => {
  it('reads every leaf of the schema as written there', () => {
    const raw = rawFields();
    expect(raw.length).toBeGreaterThan(40);
    for (const [path, kind, node] of raw) {
      const field = schemaField(path, kind ?? undefined);
      expect(field.description, path).toBe(node.description);
      expect(field.unit, path).toBe(node.unit ?? null);
      expect(field.minimum, path).toBe(node.minimum);
      expect(field.maximum, path).toBe(node.maximum);
      expect(field.exclusiveMinimum, path).toBe(node.exclusiveMinimum);
      expect(field.default, path).toEqual(node.default);
      expect(field.nullable, path).toBe(Array.isArray(node.type) && node.type.includes('null'));
    }
  });

  it('refuses a path the schema does not have', () => {
    expect(() => schemaField('lloyd.maxIter')).toThrow(/lloyd\.maxIter/);
    expect(() => schemaField('surface.radius', 'plane')).toThrow(/plane/);
  });
});

describe('the app panel and the element follow the schema', () => {
  const raw = rawFields();
  const nodesAt = (path: string) => raw.filter(([p]) => p === path);

  /** One validated config per surface kind and per density kind. */
  const base = validateConfig(APP_START);
  const configs: Config[] = [
    ...['plane', 'tube', 'sphere', 'ellipsoid', 'mesh'].map((kind) =>
      validateConfig({ ...base, surface: surfaceOfKind(base.surface, kind), sheet: { ...base.sheet, surfaceRatio: null } }),
    ),
    ...['uniform', 'linear', 'gaussian', 'stripes', 'image'].map((kind) => ({ ...base, density: densityPreset(kind, base) }) as Config),
  ];

  it('takes units, lower and upper bounds and choices of every schema field it shows from the schema', () => {
    let checked = 0;
    for (const spec of FIELDS) {
      const nodes = nodesAt(spec.path);
      if (nodes.length === 0) continue; // a panel-only field (mesh sample, surface-ratio-or-thickness)
      checked++;
      const [, , node] = nodes[0];
      expect(spec.unit, spec.path).toBe(node.unit);
      expect(spec.min, spec.path).toBe(node.minimum ?? node.exclusiveMinimum);
      if (node.maximum !== undefined) expect(spec.max, spec.path).toBe(node.maximum);
      if (Array.isArray(node.enum)) expect(spec.options?.map((o) => o.value).sort(), spec.path).toEqual([...node.enum].sort());
      if (spec.path.endsWith('.kind')) {
        const kinds = (((configSchema.properties as Record<string, Node>)[spec.path.split('.')[0]].oneOf ?? []) as Node[]).map((b) =>
          String(((b.properties as Record<string, Node>).kind as Node).const),
        );
        expect(spec.options?.map((o) => o.value).sort(), spec.path).toEqual(kinds.sort());
      }
    }
    expect(checked).toBeGreaterThan(30);
  });

  it('shows a surface or density field exactly for the kinds whose schema branch has it', () => {
    for (const spec of FIELDS) {
      const nodes = nodesAt(spec.path);
      if (spec.path.endsWith('.kind') || nodes.length === 0 || nodes[0][1] === null) continue;
      const kinds = nodes.map(([, kind]) => kind);
      for (const c of configs) {
        const kind = spec.path.startsWith('surface.') ? c.surface.kind : c.density.kind;
        expect(spec.show?.(c), `${spec.path} on ${kind}`).toBe(kinds.includes(kind));
      }
    }
  });

  it('parses each element attribute as its schema type', () => {
    for (const [attribute, [path, kind]] of Object.entries(ATTRIBUTES)) {
      const nodes = nodesAt(path);
      const node = nodes[0]?.[2] ?? ((configSchema.properties as Record<string, Node>)[path.split('.')[0]] as Node | undefined);
      expect(node, attribute).toBeDefined();
      if (path.endsWith('.kind')) {
        expect(kind, attribute).toBe('string');
        continue;
      }
      const types = [node?.type].flat();
      const expected = types.includes('boolean') ? 'boolean' : types.includes('string') ? 'string' : types.includes('null') ? 'nullable-number' : 'number';
      expect(kind, attribute).toBe(expected);
    }
  });
});
