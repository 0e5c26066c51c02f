/**
 * Units in the sweep files' headers, and the base geometry each run's row carries.
 *
 * Convention (docs/sweep.md, "Reading the files"): a column whose quantity has a unit is named
 * `<name>_<unit>`: everything after the first underscore is the unit, so a plain
 * `pandas.read_csv` reads the files and the unit stays in the name (`sheet.thickness_um`). No
 * column name of ours has an underscore otherwise (config paths and summary names are
 * camelCase). Units: `um` µm, `um4` µm⁴ (× relative density: the CVT energy), `pct` percent
 * (0 to 100), `frac` a fraction (0 to 1), `um_per_unit` µm per mesh coordinate unit. Counts,
 * ratios (s), means of counts and text have no suffix.
 *
 * Inside the program, rows keep the plain names (`exact.percentScutoids`): the suffix is added
 * where a header is written (`fileColumn`) and removed where one is read (`plainColumn`), so
 * resume, merge and the page read the files they write.
 */
import type { Config } from '../config';
import { schemaField } from '../config/schemaFields';

const SCHEMA_UNITS: Record<string, string> = { µm: 'um', 'µm per mesh unit': 'um_per_unit' };

/** The unit of a config path from the config schema (`surface.radius`: "um"), or null. */
function configUnit(path: string): string | null {
  try {
    const unit = schemaField(path).unit;
    return unit === null ? null : (SCHEMA_UNITS[unit] ?? unit.replace(/µ/g, 'u').replace(/\W+/g, '_'));
  } catch {
    return null; // not a field of the schema (a summary column) or a whole section
  }
}

/** The unit suffix of a column (plain name), or null when it has none. */
export function columnUnit(name: string): string | null {
  if (name === 'finalEnergy') return 'um4';
  if (/^(labels|exact)\./.test(name)) {
    if (name.endsWith('.percentScutoids')) return 'pct';
    if (/\.polygons\.[^.]+$/.test(name)) return 'frac';
    return null;
  }
  return configUnit(name);
}

/** The name a column has in a file's header. */
export function fileColumn(name: string): string {
  const unit = columnUnit(name);
  return unit === null ? name : `${name}_${unit}`;
}

/** The plain name of a header cell (the inverse of fileColumn). */
export function plainColumn(name: string): string {
  const at = name.indexOf('_');
  return at === -1 ? name : name.slice(0, at);
}

export function fileHeader(header: readonly string[]): string[] {
  return header.map(fileColumn);
}

/**
 * Config paths whose values each row carries (the base geometry and the protocol), as leaves
 * of the validated config: every field of `surface` (kind and its dimensions), then these.
 */
const GEOMETRY_PATHS = [
  'density.kind',
  'cells',
  'minSpacing',
  'lloyd.maxIterations',
  'sheet.seeded',
  'sheet.direction',
  'sheet.thickness',
  'sheet.surfaceRatio',
  'sheet.layers',
  'sheet.layerStep',
  'sheet.protocol',
  'sheet.adjacency',
  'engine',
] as const;

function at(config: unknown, path: string): unknown {
  let value: unknown = config;
  for (const part of path.split('.')) value = value !== null && typeof value === 'object' ? (value as Record<string, unknown>)[part] : undefined;
  return value;
}

/**
 * The geometry values of a validated config (plain names), leaving out what a varied field
 * covers (the field itself, a field under it, or a section holding it): those have their own
 * column. Null fields (a ratio not given) and arrays are left out.
 */
export function geometryValues(config: Config, varied: readonly string[]): Record<string, string | number | boolean> {
  const out: Record<string, string | number | boolean> = {};
  const covered = (path: string) => varied.some((f) => f === path || path.startsWith(`${f}.`) || f.startsWith(`${path}.`));
  const surface = (config as { surface: Record<string, unknown> }).surface;
  const paths = [...Object.keys(surface).map((k) => `surface.${k}`), ...GEOMETRY_PATHS];
  for (const path of paths) {
    if (covered(path)) continue;
    const value = at(config, path);
    if (typeof value === 'number' || typeof value === 'string' || typeof value === 'boolean') out[path] = value;
  }
  return out;
}

/**
 * The geometry columns over `configs` (in order of first appearance), which of them hold text,
 * and each config's values.
 */
export function geometryColumns(configs: Iterable<Config>, varied: readonly string[]): { columns: string[]; text: Set<string> } {
  const columns: string[] = [];
  const text = new Set<string>();
  for (const config of configs) {
    for (const [path, value] of Object.entries(geometryValues(config, varied))) {
      if (!columns.includes(path)) columns.push(path);
      if (typeof value !== 'number') text.add(path);
    }
  }
  return { columns, text };
}
