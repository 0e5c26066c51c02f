/**
 * The fields of configSchema as plain records (path, type, unit, range, default, description),
 * read from the schema document itself. The app's panel, the element's attributes and
 * docs/config.md are built from these, so a field's unit, range, default and description are
 * written once, in schema.ts.
 */
import { configSchema } from './schema';

export type SchemaNode = Record<string, unknown>;

type FieldType = 'number' | 'integer' | 'string' | 'boolean' | 'array' | 'object';

export interface SchemaField {
  /** Dotted config path: `resolution`, `surface.radius`, `density.kind`. */
  path: string;
  /** The union branch (`"tube"`, `"gaussian"`) the field belongs to; null outside unions. */
  kind: string | null;
  type: FieldType;
  /** Whether null is accepted too (type ["number", "null"]). */
  nullable: boolean;
  unit: string | null;
  minimum?: number;
  maximum?: number;
  exclusiveMinimum?: number;
  /** The accepted values of a string field (enum), or the one value of a union's `kind`. */
  values?: readonly string[];
  /** Length of a fixed-length array, and the type of its items. */
  items?: number;
  itemType?: FieldType;
  minLength?: number;
  /** Whether the field must be given (within its union branch); false when it has a default. */
  required: boolean;
  hasDefault: boolean;
  default?: unknown;
  description: string;
  /** Fields of an object field, in schema order (lloyd, sheet, jumpFlood); empty otherwise. */
  children: SchemaField[];
}

/** A union of objects chosen by `kind` (surface, density): one branch per kind. */
export interface SchemaUnion {
  path: string;
  description: string;
  default: unknown;
  branches: { kind: string; description: string; fields: SchemaField[] }[];
}

function propertiesOf(node: SchemaNode): [string, SchemaNode][] {
  return Object.entries((node.properties ?? {}) as Record<string, SchemaNode>);
}

function requiredOf(node: SchemaNode): readonly string[] {
  return Array.isArray(node.required) ? (node.required as string[]) : [];
}

function readField(path: string, node: SchemaNode, required: boolean, kind: string | null): SchemaField {
  const types = (Array.isArray(node.type) ? node.type : [node.type]) as string[];
  const type = types.find((t) => t !== 'null') as FieldType | undefined;
  if (type === undefined) throw new Error(`config schema: field "${path}" has no type`);
  const values = Array.isArray(node.enum) ? (node.enum as string[]) : node.const !== undefined ? [String(node.const)] : undefined;
  const field: SchemaField = {
    path,
    kind,
    type,
    nullable: types.includes('null'),
    unit: typeof node.unit === 'string' ? node.unit : null,
    required: required && !('default' in node),
    hasDefault: 'default' in node,
    description: String(node.description ?? ''),
    children: [],
  };
  if (typeof node.minimum === 'number') field.minimum = node.minimum;
  if (typeof node.maximum === 'number') field.maximum = node.maximum;
  if (typeof node.exclusiveMinimum === 'number') field.exclusiveMinimum = node.exclusiveMinimum;
  if (values) field.values = values;
  if (typeof node.minItems === 'number' && node.minItems === node.maxItems) field.items = node.minItems;
  if (node.items && typeof node.items === 'object') field.itemType = (node.items as SchemaNode).type as FieldType;
  if (typeof node.minLength === 'number') field.minLength = node.minLength;
  if ('default' in node) field.default = node.default;
  if (type === 'object' && !node.oneOf) {
    field.children = propertiesOf(node).map(([name, child]) => readField(`${path}.${name}`, child, requiredOf(node).includes(name), kind));
  }
  return field;
}

function readUnion(path: string, node: SchemaNode): SchemaUnion {
  const branches = (node.oneOf as SchemaNode[]).map((branch) => {
    const properties = propertiesOf(branch);
    const kindNode = properties.find(([name]) => name === 'kind')?.[1];
    if (!kindNode || typeof kindNode.const !== 'string') throw new Error(`config schema: a branch of "${path}" has no constant kind`);
    const kind = kindNode.const;
    return {
      kind,
      description: String(kindNode.description ?? ''),
      fields: properties.map(([name, child]) => readField(`${path}.${name}`, child, requiredOf(branch).includes(name), kind)),
    };
  });
  return { path, description: String(node.description ?? ''), default: node.default, branches };
}

/** A top-level entry of the schema: a plain field (scalar or object) or a union chosen by kind. */
export type TopLevelEntry = { name: string; field: SchemaField; union?: undefined } | { name: string; union: SchemaUnion; field?: undefined };

/** Every top-level entry of a configuration schema (configSchema, or a variant of it in tests), in schema order. */
export function readSchemaEntries(schema: SchemaNode): TopLevelEntry[] {
  return propertiesOf(schema).map(([name, node]) =>
    Array.isArray(node.oneOf) ? { name, union: readUnion(name, node) } : { name, field: readField(name, node, false, null) },
  );
}

/** Every top-level entry of configSchema, in schema order. */
export const SCHEMA_ENTRIES: readonly TopLevelEntry[] = readSchemaEntries(configSchema);

/** The union at `path` (`surface`, `density`). Throws for any other path: a typo in a caller's table is a bug. */
export function schemaUnion(path: string): SchemaUnion {
  const union = SCHEMA_ENTRIES.find((entry) => entry.name === path)?.union;
  if (!union) throw new Error(`config schema: "${path}" is not a union chosen by kind`);
  return union;
}

/**
 * The field at a dotted `path`. Inside a union, the field of branch `kind`, or of the first
 * branch that has it when no kind is given. Throws when the schema has no such field.
 */
export function schemaField(path: string, kind?: string): SchemaField {
  const [top, ...rest] = path.split('.');
  const entry = SCHEMA_ENTRIES.find((e) => e.name === top);
  let found: SchemaField | undefined;
  if (entry?.union) {
    const branches = entry.union.branches.filter((b) => kind === undefined || b.kind === kind);
    found = branches.map((b) => b.fields.find((f) => f.path === path)).find((f) => f !== undefined);
  } else if (entry?.field) {
    found = entry.field;
    for (let depth = 1; found && depth <= rest.length; depth++) {
      const prefix = [top, ...rest.slice(0, depth)].join('.');
      found = found.children.find((f) => f.path === prefix);
    }
  }
  if (!found) throw new Error(`config schema: no field "${path}"${kind === undefined ? '' : ` for kind "${kind}"`}`);
  return found;
}

/** The kinds of the union holding `path` whose branch has that field (`surface.radius`: tube, sphere). */
export function kindsWithField(path: string): string[] {
  const union = schemaUnion(path.split('.')[0]);
  return union.branches.filter((b) => b.fields.some((f) => f.path === path)).map((b) => b.kind);
}
