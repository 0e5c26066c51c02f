/**
 * The element's kebab-case attributes and how they map onto the configuration. Attributes
 * override the `config` property, which overrides the defaults (the app's small default tube).
 * Numbers are parsed as given; a bad value reaches validation, which names the field.
 */
import { CLOSED_RESOLUTION, densityPreset, surfaceOfKind } from '../app/panels/fields';
import { APP_DEFAULTS } from '../app/model/settings';
import { isClosedConfig, validateAnyConfig, type AnyConfig, type ConfigInput } from '../core/config';
import { setPath } from '../core/sweep';

type Kind = 'number' | 'string' | 'boolean' | 'nullable-number';

/** attribute -> [config path, kind]. */
export const ATTRIBUTES: Record<string, [string, Kind]> = {
  surface: ['surface.kind', 'string'],
  radius: ['surface.radius', 'number'],
  a: ['surface.a', 'number'],
  b: ['surface.b', 'number'],
  c: ['surface.c', 'number'],
  src: ['surface.src', 'string'],
  scale: ['surface.scale', 'number'],
  length: ['surface.length', 'number'],
  width: ['surface.width', 'number'],
  height: ['surface.height', 'number'],
  'periodic-x': ['surface.periodicX', 'boolean'],
  'periodic-y': ['surface.periodicY', 'boolean'],
  resolution: ['resolution', 'number'],
  cells: ['cells', 'number'],
  seed: ['seed', 'number'],
  'min-spacing': ['minSpacing', 'number'],
  iterations: ['lloyd.maxIterations', 'number'],
  tolerance: ['lloyd.tolerance', 'number'],
  'over-relaxation': ['lloyd.overRelaxation', 'number'],
  'jump-flood': ['jumpFlood.variant', 'string'],
  'centroid-path': ['centroidPath', 'string'],
  seeded: ['sheet.seeded', 'string'],
  direction: ['sheet.direction', 'string'],
  thickness: ['sheet.thickness', 'number'],
  'surface-ratio': ['sheet.surfaceRatio', 'nullable-number'],
  layers: ['sheet.layers', 'number'],
  adjacency: ['sheet.adjacency', 'string'],
  'min-contact-length': ['sheet.minContactLength', 'nullable-number'],
  density: ['density.kind', 'string'],
};

/** Surface fields each kind takes: other surface attributes are ignored (switching kind keeps them harmless). */
const SURFACE_FIELDS: Record<string, string[]> = {
  plane: ['width', 'height', 'periodicX', 'periodicY'],
  tube: ['radius', 'length'],
  sphere: ['radius'],
  ellipsoid: ['a', 'b', 'c'],
  mesh: ['src', 'scale'],
};

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
 * attribute, a cube map of 64 texels per face edge. A mesh without `src` uses `meshName` (the
 * element's meshFile) or the organoid sample.
 */
export function configFromAttributes(element: Element, base: ConfigInput | null, meshName?: string): AnyConfig {
  // Top-level fields the config property leaves out (the surface, say) come from the defaults.
  const input = structuredClone({ ...APP_DEFAULTS, ...base }) as Record<string, unknown>;
  const surfaceKind = element.getAttribute('surface');
  if (surfaceKind !== null && surfaceKind !== (input.surface as { kind?: string } | undefined)?.kind) {
    // A different kind starts from that kind's required fields (an empty plane/tube is invalid).
    if (['sphere', 'ellipsoid', 'mesh'].includes(surfaceKind)) {
      input.surface = surfaceOfKind({ kind: 'tube', radius: 1, length: 1 }, surfaceKind);
      if (!element.hasAttribute('resolution')) input.resolution = Math.min(Number(input.resolution ?? 512), CLOSED_RESOLUTION);
    } else {
      input.surface = surfaceKind === 'plane' ? { kind: 'plane', width: 512, height: 512 } : { kind: surfaceKind, radius: 256 / (2 * Math.PI), length: 512 };
    }
  }
  const surface = input.surface as { kind?: string; src?: string };
  if (surface.kind === 'mesh' && meshName && !element.hasAttribute('src')) surface.src = meshName;
  for (const [attribute, [path, kind]] of Object.entries(ATTRIBUTES)) {
    const text = element.getAttribute(attribute);
    if (text === null || attribute === 'surface') continue;
    if (attribute === 'density') continue;
    const currentKind = (input.surface as { kind?: string } | undefined)?.kind ?? '';
    if (path.startsWith('surface.') && !(SURFACE_FIELDS[currentKind] ?? []).includes(path.slice('surface.'.length))) continue;
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
