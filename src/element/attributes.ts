/**
 * The element's kebab-case attributes and how they map onto the configuration. Attributes
 * override the `config` property, which overrides the defaults (the app's small default tube).
 * Numbers are parsed as given; a bad value reaches validation, which names the field.
 *
 * Which config fields are attributes is listed here; how each one parses (number, nullable
 * number, string, boolean) and which surface kinds take it are read from the config schema.
 */
import { CLOSED_SURFACE_KINDS, isClosedConfig, validateAnyConfig, type AnyConfig, type AnySurfaceConfig, type ConfigInput } from '../core/config';
import { APP_DEFAULTS, densityPreset, surfaceOfKind, thicknessForKind } from '../core/config/presets';
import { kindsWithField, schemaField } from '../core/config/schemaFields';
import { setPath } from '../core/sweep';

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
export const OTHER_ATTRIBUTES = ['manual'];

function parse(kind: Kind, text: string): unknown {
  switch (kind) {
    case 'boolean':
      return text !== 'false';
    case 'string':
      return text.trim();
    case 'nullable-number':
      return text.trim() === '' || text.trim() === 'null' ? null : Number(text);
    default:
      return text.trim() === '' ? Number.NaN : Number(text);
  }
}

/**
 * The validated configuration of an element: defaults, then `base` (the config property), then
 * the attributes. Switching `surface` to a plane drops the tube's surface ratio; giving a
 * thickness on a tube without a surface ratio uses the thickness. A closed surface (sphere,
 * ellipsoid, mesh) starts from the app's dimensions for it and, without a `resolution`
 * attribute, the default resolution (defaultResolution: from the cells and the minimum contact length). A mesh without `src` uses `meshName` (the
 * element's meshFile) or the organoid sample.
 */
export function configFromAttributes(element: Element, base: ConfigInput | null, meshName?: string): AnyConfig {
  // Top-level fields the config property leaves out (the surface, say) come from the defaults.
  const input = structuredClone({ ...APP_DEFAULTS, ...base }) as Record<string, unknown>;
  const surfaceKind = element.getAttribute('surface');
  if (surfaceKind !== null && surfaceKind !== (input.surface as { kind?: string } | undefined)?.kind) {
    // A different kind starts from that kind's required fields (an empty plane/tube is invalid).
    if (CLOSED_SURFACE_KINDS.some((closed) => closed === surfaceKind)) {
      input.surface = surfaceOfKind({ kind: 'tube', radius: 1, length: 1 }, surfaceKind);
      // Without a resolution attribute, the default every entry point gives this surface.
      if (!element.hasAttribute('resolution')) input.resolution = null;
    } else {
      input.surface = surfaceKind === 'plane' ? { kind: 'plane', width: 512, height: 512 } : { kind: surfaceKind, radius: 256 / (2 * Math.PI), length: 512 };
    }
  }
  if (surfaceKind !== null && surfaceKind !== 'tube') {
    // Every kind starts from a sheet with a thickness (never the coincident surfaces of thickness 0).
    const sheet = { ...(input.sheet as Record<string, unknown> | undefined) };
    if (!element.hasAttribute('thickness') && !sheet.thickness) sheet.thickness = thicknessForKind(input.surface as AnySurfaceConfig);
    input.sheet = sheet;
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
    setPath(input, path, parse(kind, text));
  }
  const sheet = (input.sheet ?? {}) as Record<string, unknown>;
  const kind = (input.surface as { kind: string }).kind;
  if (!element.hasAttribute('surface-ratio') && (kind !== 'tube' || element.hasAttribute('thickness'))) sheet.surfaceRatio = null;
  input.sheet = sheet;
  let config = validateAnyConfig(input);
  const density = element.getAttribute('density');
  if (density !== null && density !== config.density.kind) config = validateAnyConfig({ ...config, density: densityPreset(density, config) });
  if (isClosedConfig(config) && density === null && config.density.kind !== 'uniform') config = { ...config, density: { kind: 'uniform' } };
  return config;
}
