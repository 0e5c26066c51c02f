/**
 * docs/config.md, generated: the hand-written prose of a template (scripts/docsConfig.template.md)
 * with every field's table filled in from the config schema (type, unit, range, default,
 * description). Pure functions of their inputs, so tests can feed a tampered page or a
 * variant schema; scripts/docs.ts reads and writes the files.
 *
 * Template directives, each alone on a line:
 *   {{section NAME}}              heading, description and table(s) of a top-level field
 *   {{heading NAME}}              only the heading, description and default of a union
 *   {{branches NAME KIND ...}}    the tables of those kinds of a union; `rest` = kinds not yet shown
 *   {{other sections}}            every top-level field no directive has shown yet
 * So a field added to the schema appears in the page without touching the template: a field
 * inside an object or a kind in its table, a new kind under `rest`, a new top-level field
 * under `{{other sections}}`.
 */
import { SCHEMA_ENTRIES, type SchemaField, type SchemaUnion, type TopLevelEntry } from '../src/core/config/schemaFields';

export const CONFIG_DOCS_PATH = 'docs/config.md';
export const CONFIG_TEMPLATE_PATH = 'scripts/docsConfig.template.md';

const NOTICE = '<!-- Generated from src/core/config/schema.ts and scripts/docsConfig.template.md by `npm run docs:write`; edit those, not this page. -->';

const TABLE_HEAD = ['| field | type | unit | range | default | meaning |', '|---|---|---|---|---|---|'];

function code(text: string): string {
  return `\`${text}\``;
}

function cell(text: string): string {
  return text.replace(/\|/g, '\\|');
}

function typeText(field: SchemaField): string {
  if (field.kind !== null && field.path.endsWith('.kind')) return code(JSON.stringify(field.values?.[0]));
  if (field.type === 'array') {
    const item = field.itemType ?? 'value';
    return field.items !== undefined ? code(`[${Array.from({ length: field.items }, () => item).join(', ')}]`) : `array of ${item}s`;
  }
  return field.nullable ? `${field.type} or null` : field.type;
}

function rangeText(field: SchemaField): string {
  if (field.kind !== null && field.path.endsWith('.kind')) return '';
  if (field.values) return field.values.map((v) => code(JSON.stringify(v))).join(', ');
  if (field.minimum !== undefined && field.maximum !== undefined) return `${field.minimum}..${field.maximum}`;
  if (field.exclusiveMinimum !== undefined) return `> ${field.exclusiveMinimum}`;
  if (field.minimum !== undefined) return `>= ${field.minimum}`;
  if (field.maximum !== undefined) return `<= ${field.maximum}`;
  if (field.minLength) return 'non-empty';
  return '';
}

function defaultText(field: SchemaField): string {
  if (field.hasDefault) return code(JSON.stringify(field.default));
  return field.required ? 'required' : '';
}

function row(field: SchemaField): string {
  const name = field.path.split('.').pop() ?? field.path;
  const cells = [code(name), typeText(field), field.unit ?? '', rangeText(field), defaultText(field), field.description];
  return `| ${cells.map(cell).join(' | ')} |`;
}

function table(fields: SchemaField[]): string[] {
  return [...TABLE_HEAD, ...fields.map(row)];
}

/** Blocks joined by blank lines. */
function paragraphs(blocks: string[][]): string[] {
  return blocks.flatMap((block, k) => (k === 0 ? block : ['', ...block]));
}

function unionHeading(union: SchemaUnion): string[] {
  return [`### ${code(union.path)}`, '', union.description, '', `Default: ${code(JSON.stringify(union.default))}.`];
}

function fieldSection(field: SchemaField): string[] {
  if (field.type === 'object') return paragraphs([[`### ${code(field.path)}`], [field.description], table(field.children)]);
  // A single field: its description is the table's meaning, not repeated above it.
  return paragraphs([[`### ${code(field.path)} (default ${code(JSON.stringify(field.default))})`], table([field])]);
}

/** Renders the page from the template's text and the schema's entries (configSchema's by default). */
export function renderConfigDocs(template: string, entries: readonly TopLevelEntry[] = SCHEMA_ENTRIES): string {
  const shown = new Set<string>();
  const shownKinds = new Map<string, Set<string>>();
  const entry = (name: string, line: string): TopLevelEntry => {
    const found = entries.find((e) => e.name === name);
    if (!found) throw new Error(`${CONFIG_TEMPLATE_PATH}: "${line}" names "${name}", which the schema does not have`);
    return found;
  };
  const branches = (union: SchemaUnion, kinds: string[]): string[] => {
    const done = shownKinds.get(union.path) ?? new Set<string>();
    shownKinds.set(union.path, done);
    const wanted = kinds.flatMap((kind) => (kind === 'rest' ? union.branches.map((b) => b.kind).filter((k) => !done.has(k) && !kinds.includes(k)) : [kind]));
    return paragraphs(
      wanted.map((kind) => {
        const branch = union.branches.find((b) => b.kind === kind);
        if (!branch) throw new Error(`${CONFIG_TEMPLATE_PATH}: ${union.path} has no kind "${kind}"`);
        done.add(kind);
        return table(branch.fields);
      }),
    );
  };
  const section = (e: TopLevelEntry): string[] => {
    shown.add(e.name);
    return e.union ? paragraphs([unionHeading(e.union), branches(e.union, ['rest'])]) : fieldSection(e.field);
  };
  const out: string[] = [NOTICE, ''];
  let otherAt = -1;
  for (const line of template.split('\n')) {
    const directive = /^\{\{(\w+)(?: (.*))?\}\}$/.exec(line.trim());
    if (!directive) {
      out.push(line);
      continue;
    }
    const [verb, args = ''] = [directive[1], directive[2]];
    const [name, ...kinds] = args.split(' ').filter(Boolean);
    if (verb === 'section') out.push(...section(entry(name, line)));
    else if (verb === 'heading' || verb === 'branches') {
      const union = entry(name, line).union;
      if (!union) throw new Error(`${CONFIG_TEMPLATE_PATH}: "${line}": ${name} is not a union chosen by kind`);
      if (verb === 'heading') {
        shown.add(name);
        out.push(...unionHeading(union));
      } else out.push(...branches(union, kinds));
    } else if (verb === 'other' && name === 'sections' && otherAt < 0) {
      otherAt = out.length;
      out.push(line);
    } else throw new Error(`${CONFIG_TEMPLATE_PATH}: unknown directive "${line}"`);
  }
  // Filled last, so it holds whatever no other directive showed, wherever it stands.
  if (otherAt >= 0) out.splice(otherAt, 1, ...paragraphs(entries.filter((e) => !shown.has(e.name)).map(section)));
  return `${out.join('\n').replace(/\n+$/, '')}\n`;
}

/**
 * Compares the committed page with the generated one. Returns null when they agree, else one
 * line naming the first line that differs and how to fix it.
 */
export function checkConfigDocs(committed: string, generated: string): string | null {
  if (committed === generated) return null;
  const have = committed.split('\n');
  const want = generated.split('\n');
  let line = 0;
  while (line < have.length && line < want.length && have[line] === want[line]) line++;
  const shorten = (text: string | undefined) => (text === undefined ? '(end of file)' : JSON.stringify(text.length > 80 ? `${text.slice(0, 77)}...` : text));
  return `${CONFIG_DOCS_PATH}:${line + 1} differs from the schema: has ${shorten(have[line])}, expected ${shorten(want[line])}; run npm run docs:write and commit the page (prose: ${CONFIG_TEMPLATE_PATH})`;
}
