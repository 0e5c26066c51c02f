import { readFileSync } from 'node:fs';
import { fileURLToPath } from 'node:url';
import { describe, expect, it } from 'vitest';
import { configSchema } from '../../src/core/config';
import { SCHEMA_ENTRIES, readSchemaEntries, type SchemaNode } from '../../src/core/config/schemaFields';
import { CONFIG_DOCS_PATH, CONFIG_TEMPLATE_PATH, checkConfigDocs, renderConfigDocs } from '../../scripts/docsConfig';

const read = (path: string) => readFileSync(fileURLToPath(new URL(`../../${path}`, import.meta.url)), 'utf8');
const committed = read(CONFIG_DOCS_PATH);
const template = read(CONFIG_TEMPLATE_PATH);

/** A table row of the page, found by its first cell (the field's name). */
function rowsOf(text: string, name: string): string[] {
  return text.split('\n').filter((line) => line.startsWith(`| \`${name}\` |`));
}

describe('docs:check', () => {
  it('passes on the committed docs/config.md', () => {
    expect(checkConfigDocs(committed, renderConfigDocs(template))).toBeNull();
  });

  it('fails on a tampered copy, naming the first line that differs', () => {
    const lines = committed.split('\n');
    const at = lines.findIndex((line) => line.startsWith('| `cells` |'));
    expect(at).toBeGreaterThan(0);
    const tampered = [...lines];
    tampered[at] = lines[at].replace('`200`', '`300`');
    expect(tampered[at]).not.toBe(lines[at]);
    const message = checkConfigDocs(tampered.join('\n'), renderConfigDocs(template));
    expect(message).not.toBeNull();
    expect(message).toContain(`${CONFIG_DOCS_PATH}:${at + 1} `);
    expect(message).toContain('npm run docs:write');
    expect(message).not.toContain('\n');
  });

  it('fails on a truncated copy and on a copy with a line added', () => {
    const lines = committed.split('\n');
    const half = Math.floor(lines.length / 2);
    expect(checkConfigDocs(lines.slice(0, half).join('\n'), committed)).toContain(`${CONFIG_DOCS_PATH}:${half + 1} `);
    const added = [...lines.slice(0, 3), 'a hand edit', ...lines.slice(3)].join('\n');
    expect(checkConfigDocs(added, committed)).toContain(`${CONFIG_DOCS_PATH}:4 `);
  });
});

describe('renderConfigDocs', () => {
  it('gives every field of the schema one table row', () => {
    const rendered = renderConfigDocs(template);
    const rows = rendered.split('\n').filter((line) => /^\| `[^`]+` \|/.test(line)).length;
    const fields = SCHEMA_ENTRIES.reduce((n, e) => n + (e.union ? e.union.branches.reduce((m, b) => m + b.fields.length, 0) : e.field.children.length || 1), 0);
    expect(rows).toBe(fields);
  });

  it('follows the schema: a changed default and range, a new field and a new kind appear without touching the template', () => {
    const variant: SchemaNode = structuredClone(configSchema);
    const properties = variant.properties as Record<string, SchemaNode>;
    properties.cells = { ...properties.cells, default: 321, maximum: 9999 };
    const lloyd = properties.lloyd.properties as Record<string, SchemaNode>;
    lloyd.damping = { type: 'number', minimum: 0, maximum: 2, unit: 'µm', default: 0.5, description: 'A field that only this test has.' };
    properties.extraTopLevel = { type: 'boolean', default: true, description: 'A top-level field that only this test has.' };
    const surfaces = properties.surface.oneOf as SchemaNode[];
    surfaces.push({
      type: 'object',
      additionalProperties: false,
      required: ['kind', 'side'],
      properties: {
        kind: { type: 'string', const: 'cube', description: 'A kind that only this test has.' },
        side: { type: 'number', exclusiveMinimum: 0, unit: 'µm', description: 'Side of the test cube.' },
      },
    });
    const rendered = renderConfigDocs(template, readSchemaEntries(variant));
    expect(rowsOf(rendered, 'cells')).toEqual(['| `cells` | integer |  | 1..9999 | `321` | Number of cells (sites). |']);
    expect(rowsOf(rendered, 'damping')).toEqual(['| `damping` | number | µm | 0..2 | `0.5` | A field that only this test has. |']);
    expect(rowsOf(rendered, 'extraTopLevel')).toHaveLength(1);
    expect(rendered).toContain('### `extraTopLevel` (default `true`)');
    expect(rowsOf(rendered, 'side')).toEqual(['| `side` | number | µm | > 0 | required | Side of the test cube. |']);
    expect(checkConfigDocs(committed, rendered)).not.toBeNull();
  });

  it('refuses a template directive naming a field the schema does not have', () => {
    expect(() => renderConfigDocs('{{section nosuchfield}}')).toThrow(/nosuchfield/);
    expect(() => renderConfigDocs('{{branches surface cone}}')).toThrow(/cone/);
  });
});
