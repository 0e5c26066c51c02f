/**
 * The element's kebab-case attributes and how they map onto the configuration. Attributes
 * override the `config` property, which overrides the schema's defaults: the same defaults as
 * the CLI, the library, the app and links (an element with no attributes shows the schema's
 * default sheet, the published tube). Numbers are parsed as given; a bad value reaches
 * validation, which names the field.
 *
 * Which config fields are attributes is listed here; how each one parses (number, nullable
 * number, string, boolean) and which surface kinds take it are read from the config schema.
 */
import { ConfigError, configSchema, validateConfig, type Config, type ConfigInput, type SurfaceConfig } from '../core/config';
import { densityPreset, surfaceOfKind } from '../core/config/presets';
import { layoutOfKind, surfaceLayout } from '../core/config/surfaceLayout';
import { kindsWithField, schemaField, schemaUnion } from '../core/config/schemaFields';
import { setPath } from '../core/sweep';
import { readDecimal } from '../core/config/decimal';

/** The schema's default surface (the published tube). */
const DEFAULT_SURFACE = configSchema.properties.surface.default as SurfaceConfig;

type Kind = 'number' | 'string' | 'boolean' | 'nullable-number';

/** Config paths that are attributes, named by the kebab-case of their last part unless renamed here. */
const ATTRIBUTE_PATHS: (string | [attribute: string, path: string])[] = [
  ['surface', 'surface.kind'],
  'surface.radius',
  'surface.a',
  'surface.b',
  'surface.c',
  'surface.src',
  'surface.scale',
  'surface.length',
  'surface.width',
  'surface.height',
  'surface.periodicX',
  'surface.periodicY',
  'resolution',
  'cells',
  'seed',
  'minSpacing',
  ['iterations', 'lloyd.maxIterations'],
  'lloyd.tolerance',
  'lloyd.overRelaxation',
  ['jump-flood', 'jumpFlood.variant'],
  'centroidPath',
  'sheet.seeded',
  'sheet.direction',
  'sheet.thickness',
  'sheet.surfaceRatio',
  'sheet.layers',
  'sheet.adjacency',
  'sheet.minContactLength',
  ['density', 'density.kind'],
];

function kebabCase(name: string): string {
  return name.replace(/[A-Z]/g, (letter) => `-${letter.toLowerCase()}`);
}

/** How an attribute's text parses, from the schema type of its field. */
function attributeKind(path: string): Kind {
  const field = schemaField(path);
  if (field.type === 'boolean') return 'boolean';
  if (field.type === 'number' || field.type === 'integer') return field.nullable ? 'nullable-number' : 'number';
  return 'string';
}

/** attribute -> [config path, kind]. */
export const ATTRIBUTES: Record<string, [string, Kind]> = Object.fromEntries(
  ATTRIBUTE_PATHS.map((entry) => {
    const [attribute, path] = typeof entry === 'string' ? [kebabCase(entry.split('.').pop() ?? entry), entry] : entry;
    return [attribute, [path, attributeKind(path)]];
  }),
);

/** Attributes that are not configuration. */
export const OTHER_ATTRIBUTES = ['manual', 'realizations'];

function parse(kind: Kind, text: string, attribute: string, path: string): unknown {
  switch (kind) {
    case 'boolean':
      return text !== 'false';
    case 'string':
      return text.trim();
    case 'nullable-number':
      return text.trim() === '' || text.trim() === 'null' ? null : number(text, attribute, path);
    default:
      if (text.trim() === '') throw new ConfigError(path, `${attribute}: the attribute is empty; give a number or remove it`);
      return number(text, attribute, path);
  }
}

/** A number attribute as a person writes it ("22,5" is 22.5: readDecimal), or a ConfigError in words. */
function number(text: string, attribute: string, path: string): number {
  const reading = readDecimal(text);
  if (!reading.ok) throw new ConfigError(path, `${attribute}: ${reading.message}`);
  return reading.value;
}

/**
 * The validated configuration of an element: the schema's defaults, then `base` (the config
 * property), then the attributes. A `surface` attribute naming another kind than `base` starts
 * from that kind's required dimensions (a tube: the schema's default tube; a plane: its unrolled
 * size; a closed kind: the app's dimensions for it), which the dimension attributes override;
 * across planar and closed kinds a resolution without its attribute goes back to the default.
 * Switching `surface` to a plane drops the tube's surface ratio; giving a thickness on a tube
 * without a surface ratio uses the thickness. A mesh without `src` uses `meshName` (the
 * element's meshFile) or the organoid sample.
 */
export function configFromAttributes(element: Element, base: ConfigInput | null, meshName?: string): Config {
  const input = structuredClone(base ?? {}) as Record<string, unknown>;
  // The schema's default surface, written out so that dimension attributes (radius, length) apply to it.
  input.surface ??= structuredClone(DEFAULT_SURFACE);
  const surfaceKind = element.getAttribute('surface');
  const baseKind = (input.surface as { kind?: string }).kind ?? '';
  if (surfaceKind !== null && surfaceKind !== baseKind) {
    // A different kind starts from that kind's required fields (an empty plane/tube is invalid).
    // (A closed kind's defaults; a plane or tube keeps the default tube's unrolled size.)
    input.surface = surfaceOfKind(DEFAULT_SURFACE, surfaceKind);
    // A resolution means texels along the longer side on a plane or tube, per cube-face edge on
    // a closed surface: without its attribute, the default of the new layout.
    if (layoutOfKind(surfaceKind) !== layoutOfKind(baseKind) && !element.hasAttribute('resolution')) input.resolution = null;
  }
  const surface = input.surface as { kind?: string; src?: string };
  if (surface.kind === 'mesh' && meshName && !element.hasAttribute('src')) surface.src = meshName;
  for (const [attribute, [path, kind]] of Object.entries(ATTRIBUTES)) {
    const text = element.getAttribute(attribute);
    if (text === null || attribute === 'surface') continue;
    if (attribute === 'density') continue;
    const currentKind = (input.surface as { kind?: string } | undefined)?.kind ?? '';
    // Surface fields the current kind does not take are ignored (switching kind keeps them harmless).
    if (path.startsWith('surface.') && !kindsWithField(path).includes(currentKind)) continue;
    setPath(input, path, parse(kind, text, attribute, path));
  }
  const sheet = (input.sheet ?? {}) as Record<string, unknown>;
  const kind = (input.surface as { kind: string }).kind;
  if (!element.hasAttribute('surface-ratio') && (kind !== 'tube' || element.hasAttribute('thickness'))) sheet.surfaceRatio = null;
  input.sheet = sheet;
  let config = validateConfig(input);
  const density = densityAttribute(element.getAttribute('density'));
  if (density !== null && density !== config.density.kind) config = validateConfig({ ...config, density: densityPreset(density, config) });
  if (surfaceLayout(config).uniformDensityOnly && density === null && config.density.kind !== 'uniform') config = { ...config, density: { kind: 'uniform' } };
  return config;
}

/**
 * The `density` attribute (a preset's kind), checked like every enumerated attribute: a value
 * that is not a density kind (`"gausian"`) is refused naming the attribute and the kinds, never
 * run as uniform density.
 */
function densityAttribute(text: string | null): string | null {
  if (text === null) return null;
  const kinds = schemaUnion('density').branches.map((branch) => branch.kind);
  const kind = text.trim();
  if (!kinds.includes(kind)) throw new ConfigError('density.kind', `density: must be one of ${kinds.map((k) => `"${k}"`).join(', ')} (got "${text}")`);
  return kind;
}
