/**
 * Every control of the configuration panel, as data: the config path it edits, its label, its
 * kind and range, and when it shows. The panel (controls.ts) renders and binds them.
 *
 * What a field is comes from the config schema (core/config/schemaFields.ts): its input kind
 * (number, integer, checkbox, select), unit, range, choices and description, and, for a field
 * of the surface or density union, the kinds that show it. This file only adds presentation:
 * the label, the group, the step, labels for choices, and the few fields whose control differs
 * from what the schema implies (sliders, files, fields that exist only in the panel). Closed
 * surfaces: sphere (radius), ellipsoid (a, b, c), mesh (a sample from public/meshes/ or a
 * user's file; see model/meshFiles.ts).
 */
import { defaultResolution, type ConfigDraft } from '../../core/config';
import { densityPreset, surfaceOfKind, thicknessForKind } from '../../core/config/presets';
import { layoutOfKind } from '../../core/config/surfaceLayout';
import { kindsWithField, schemaField, schemaUnion } from '../../core/config/schemaFields';
import { SAMPLE_MESHES, sampleName, sampleUrl } from '../model/meshFiles';

/** The form's config: a resolution left null is the default (defaultResolution), recomputed as the fields it depends on change. */
type Config = ConfigDraft;

interface Option {
  value: string;
  label: string;
  disabled?: boolean;
}

type Group = 'Surface' | 'Cells' | 'Density' | 'Lloyd' | 'Sheet';
type FieldKind = 'number' | 'integer' | 'range' | 'select' | 'checkbox' | 'optional-number' | 'file' | 'mesh-file';

export interface FieldSpec {
  /** Dotted config path, or a virtual field handled by `get`/`set`. */
  path: string;
  label: string;
  group: Group;
  kind: FieldKind;
  min?: number;
  max?: number | ((c: Config) => number);
  step?: number;
  unit?: string;
  options?: Option[];
  note?: string;
  /** The schema's description of the field (for the surface's kind when it depends on it). */
  description?: (c: Config) => string;
  /** Re-run live while dragging (debounced). */
  live?: boolean;
  /** Text shown in an empty number box (what an empty field means). */
  placeholder?: (c: Config) => string;
  show?: (c: Config) => boolean;
  get?: (c: Config) => unknown;
  /** Returns the new config (plain data, validated by the caller). */
  set?: (c: Config, value: unknown) => Config;
}

/** What the panel adds to a schema field; everything else is read from the schema. */
interface Presentation {
  label: string;
  group: Group;
  step?: number;
  /** A control other than the schema's type implies (a slider, a file picker). */
  kind?: FieldKind;
  /** Labels of the choices, in the order shown; choices not listed follow under their own name. */
  labels?: Record<string, string>;
  /** Upper end of a slider where the schema has none, or one that follows the config. */
  max?: number | ((c: Config) => number);
  note?: string;
  live?: boolean;
  placeholder?: (c: Config) => string;
  /** An extra condition; a field of a union shows only for the kinds whose branch has it anyway. */
  show?: (c: Config) => boolean;
  set?: (c: Config, value: unknown) => Config;
}

const isTube = (c: Config) => c.surface.kind === 'tube';

/** The value of the union (surface or density) a path belongs to. */
function unionKindOf(c: Config, path: string): string {
  return path.startsWith('surface.') ? c.surface.kind : c.density.kind;
}

/** A union's kinds as choices: the listed labels first, in their order, then any other kind. */
function choices(values: readonly string[], labels: Record<string, string> = {}): Option[] {
  const listed = Object.keys(labels).filter((value) => values.includes(value));
  const rest = values.filter((value) => !listed.includes(value));
  return [...listed, ...rest].map((value) => ({ value, label: labels[value] ?? value }));
}

/** A panel field for the schema field at `path`: kind, unit, range, choices and visibility from the schema. */
function field(path: string, p: Presentation): FieldSpec {
  const isKindField = /^(surface|density)\.kind$/.test(path);
  const inUnion = /^(surface|density)\./.test(path) && !isKindField;
  const schema = schemaField(path);
  const values = isKindField ? schemaUnion(path.split('.')[0]).branches.map((b) => b.kind) : schema.values;
  let kind: FieldKind;
  if (p.kind) kind = p.kind;
  else if (values) kind = 'select';
  else if (schema.type === 'boolean') kind = 'checkbox';
  else if (schema.type === 'integer') kind = 'integer';
  else if (schema.type === 'number') kind = schema.nullable ? 'optional-number' : 'number';
  else throw new Error(`fields: "${path}" (${schema.type}) needs an explicit control kind`);
  const spec: FieldSpec = { path, label: p.label, group: p.group, kind };
  const min = schema.minimum ?? schema.exclusiveMinimum;
  if (min !== undefined) spec.min = min;
  const max = p.max ?? schema.maximum;
  if (max !== undefined) spec.max = max;
  if (p.step !== undefined) spec.step = p.step;
  if (schema.unit) spec.unit = schema.unit;
  if (values && kind === 'select') spec.options = choices(values, p.labels);
  if (p.note) spec.note = p.note;
  if (p.live) spec.live = true;
  if (p.placeholder) spec.placeholder = p.placeholder;
  if (p.set) spec.set = p.set;
  const kinds = inUnion ? kindsWithField(path) : null;
  spec.description = kinds
    ? (c) => schemaField(path, kinds.includes(unionKindOf(c, path)) ? unionKindOf(c, path) : kinds[0]).description
    : () => schema.description;
  const extra = p.show;
  if (kinds && extra) spec.show = (c) => kinds.includes(unionKindOf(c, path)) && extra(c);
  else if (kinds) spec.show = (c) => kinds.includes(unionKindOf(c, path));
  else if (extra) spec.show = extra;
  return spec;
}

/**
 * Switching kind: no surface ratio off a tube; uniform density on closed surfaces; a resolution
 * the user set is kept between kinds of the same layout (planar grid, cube map) and goes back to
 * the default across them (texels along the longer side and texels per cube-face edge are not
 * the same quantity).
 */
function withSurfaceKind(c: Config, kind: string): Config {
  const surface = surfaceOfKind(c.surface, kind);
  const layout = layoutOfKind(kind);
  const resolution = layout === layoutOfKind(c.surface.kind) ? c.resolution : null;
  return {
    ...c,
    surface,
    resolution,
    density: layout.uniformDensityOnly ? { kind: 'uniform' } : c.density,
    // Every kind starts from a sheet with a thickness (see thicknessForKind), never 0.
    sheet: {
      ...c.sheet,
      surfaceRatio: kind === 'tube' ? c.sheet.surfaceRatio : null,
      thickness: kind === 'tube' && c.sheet.surfaceRatio !== null ? c.sheet.thickness : thicknessForKind(surface),
    },
  } as Config;
}

/**
 * A tube's wall in the other terms (issue 26): the surface ratio s of the current thickness t, or
 * the thickness of the current s, around the seeded radius R (outward: R_outer = R·s, so
 * t = R(s − 1); inward: the other radius is R/s, so t = R(1 − 1/s)).
 */
function convertWall(c: Config, to: 'ratio' | 'thickness'): { surfaceRatio: number | null; thickness: number } {
  if (c.surface.kind !== 'tube') return { surfaceRatio: to === 'ratio' ? 2 : null, thickness: to === 'ratio' ? 0 : thicknessForKind(c.surface) };
  const r = c.surface.radius;
  const inward = c.sheet.direction === 'inward';
  if (to === 'thickness') {
    const s = c.sheet.surfaceRatio;
    if (s === null) return { surfaceRatio: null, thickness: c.sheet.thickness };
    return { surfaceRatio: null, thickness: Number((inward ? r * (1 - 1 / s) : r * (s - 1)).toPrecision(6)) };
  }
  if (c.sheet.surfaceRatio !== null) return { surfaceRatio: c.sheet.surfaceRatio, thickness: 0 };
  const t = c.sheet.thickness;
  const s = inward ? (t < r ? r / (r - t) : 2) : (r + t) / r;
  return { surfaceRatio: Number(Math.max(1, s).toPrecision(6)), thickness: 0 };
}

/**
 * The size of the mesh last computed (its surface's equivalent radius sqrt(area / 4π), µm), by
 * source and scale: a mesh's thickness slider follows its geometry, not its scale.
 */
let meshExtent: { src: string; scale: number; radius: number } | null = null;

/** Records the size of a computed mesh (from the result's surface area). */
export function setMeshExtent(src: string, scale: number, area: number): void {
  meshExtent = { src, scale, radius: Math.sqrt(area / (4 * Math.PI)) };
}

/** Largest thickness offered by the slider (the number box beside it takes any valid value). */
function maxThickness(c: Config): number {
  const s = c.surface;
  const inward = c.sheet.direction === 'inward';
  if (s.kind === 'tube') return inward ? Math.floor(s.radius * 0.95) : 400;
  if (s.kind === 'sphere') return Math.max(1, Math.floor(s.radius * (inward ? 0.95 : 2)));
  if (s.kind === 'ellipsoid') {
    const lo = Math.min(s.a, s.b, s.c);
    const hi = Math.max(s.a, s.b, s.c);
    return Math.max(1, Math.floor(inward ? ((lo * lo) / hi) * 0.95 : 2 * hi));
  }
  if (s.kind === 'mesh') {
    // From the mesh's geometry once it has been computed (µm), else from its scale.
    const known = meshExtent && meshExtent.src === s.src ? meshExtent.radius * (s.scale / meshExtent.scale) : null;
    if (known !== null) return Math.max(1, Math.ceil(known * (inward ? 0.5 : 1)));
    return Math.max(1, Math.round(s.scale * (inward ? 0.5 : 1)));
  }
  return 400;
}

const UPLOAD_NOTE = 'An uploaded file cannot travel in a link: the link and the saved session keep only its name, and ask for the file again.';

export const FIELDS: FieldSpec[] = [
  field('surface.kind', {
    label: 'Surface',
    group: 'Surface',
    labels: { tube: 'tube', plane: 'plane', sphere: 'sphere', ellipsoid: 'ellipsoid', mesh: 'mesh (sample or upload)' },
    set: (c, v) => withSurfaceKind(c, String(v)),
  }),
  field('surface.radius', { label: 'Radius', group: 'Surface', step: 1 }),
  field('surface.a', { label: 'Semi-axis a (x)', group: 'Surface', step: 1 }),
  field('surface.b', { label: 'Semi-axis b (y)', group: 'Surface', step: 1 }),
  field('surface.c', { label: 'Semi-axis c (z)', group: 'Surface', step: 1 }),
  {
    // Panel only: picks a sample mesh, which sets surface.src.
    path: 'surface.sample',
    label: 'Mesh',
    group: 'Surface',
    kind: 'select',
    options: [...SAMPLE_MESHES.map((m) => ({ value: m.name, label: m.label })), { value: '', label: 'uploaded file', disabled: true }],
    description: () => 'A sample closed surface shipped with the app (public/meshes/); sets surface.src to its address, so a link reproduces it.',
    show: (c) => c.surface.kind === 'mesh',
    get: (c) => (c.surface.kind === 'mesh' ? (sampleName(c.surface.src) ?? '') : ''),
    set: (c, v) => (c.surface.kind === 'mesh' && v ? { ...c, surface: { ...c.surface, src: sampleUrl(String(v)) } } : c),
  },
  field('surface.src', {
    label: 'Mesh file (.ply, .obj, .stl)',
    group: 'Surface',
    kind: 'mesh-file',
    note: `${UPLOAD_NOTE} A file replacing a sample starts at Scale 1: its coordinates are taken as µm (change Scale for other units).`,
    // A user's file is not the sample: the sample's scale (50 µm per unit) is not carried over.
    set: (c, v) =>
      c.surface.kind === 'mesh' ? { ...c, surface: { ...c.surface, src: String(v), scale: sampleName(c.surface.src) ? 1 : c.surface.scale } } : c,
  }),
  field('surface.scale', { label: 'Scale', group: 'Surface', step: 1 }),
  field('surface.geodesic', { label: 'Compare with the geodesic (heat-method) Voronoi', group: 'Surface' }),
  field('surface.length', { label: 'Length', group: 'Surface', step: 1 }),
  field('surface.width', { label: 'Width', group: 'Surface', step: 1 }),
  field('surface.height', { label: 'Height', group: 'Surface', step: 1 }),
  field('surface.periodicX', { label: 'Periodic in x', group: 'Surface' }),
  field('surface.periodicY', { label: 'Periodic in y', group: 'Surface' }),
  field('resolution', {
    label: 'Resolution (texels: longer side; closed: per cube-face edge)',
    group: 'Surface',
    step: 1,
    // Empty is the default every entry point gives (from the surface, cells and contact rule),
    // shown as the placeholder and recomputed as those change, until a number is typed.
    kind: 'optional-number',
    placeholder: (c) => `default: ${defaultResolution(c)}`,
  }),

  field('cells', { label: 'Cells', group: 'Cells', step: 1 }),
  field('seed', { label: 'Random seed', group: 'Cells', step: 1 }),
  field('minSpacing', { label: 'Minimum initial spacing', group: 'Cells', step: 0.5 }),

  field('density.kind', {
    label: 'Density preset',
    group: 'Density',
    labels: { uniform: 'uniform', linear: 'gradient (linear)', gaussian: 'dense patch (gaussian)', stripes: 'stripes', image: 'grayscale image' },
    set: (c, v) => ({ ...c, density: densityPreset(String(v), c) }),
  }),
  field('density.axis', { label: 'Axis', group: 'Density', labels: { x: 'x (around / across)', y: 'y (along)' } }),
  field('density.from', { label: 'Density at start', group: 'Density', step: 0.1 }),
  field('density.to', { label: 'Density at end', group: 'Density', step: 0.1 }),
  field('density.sigma', { label: 'Patch size σ', group: 'Density', step: 1 }),
  field('density.peak', { label: 'Peak density', group: 'Density', step: 0.5 }),
  field('density.period', { label: 'Period', group: 'Density', step: 1 }),
  field('density.low', { label: 'Low density', group: 'Density', step: 0.1 }),
  field('density.high', { label: 'High density', group: 'Density', step: 0.1 }),
  field('density.invert', { label: 'Invert image', group: 'Density' }),
  field('density.src', { label: 'Grayscale image (white = dense)', group: 'Density', kind: 'file' }),

  field('lloyd.maxIterations', { label: 'Lloyd iterations', group: 'Lloyd', step: 1 }),
  field('lloyd.tolerance', { label: 'Stop when sites move less than', group: 'Lloyd', step: 0.05 }),
  field('lloyd.overRelaxation', { label: 'Over-relaxation ω', group: 'Lloyd', step: 0.05 }),
  field('lloyd.warmStart', { label: 'Warm-start jump flood', group: 'Lloyd' }),
  field('jumpFlood.variant', { label: 'Jump flood', group: 'Lloyd' }),
  field('centroidPath', { label: 'Centroid pass', group: 'Lloyd' }),

  field('sheet.seeded', { label: 'Seeded surface', group: 'Sheet' }),
  field('sheet.direction', { label: 'Other surface lies', group: 'Sheet' }),
  {
    // Panel only: a tube's other surface is set by the surface ratio or by the thickness.
    path: 'sheet.geometry',
    label: 'Set the other surface by',
    group: 'Sheet',
    kind: 'select',
    options: [
      { value: 'ratio', label: 'surface ratio' },
      { value: 'thickness', label: 'thickness' },
    ],
    description: () => "A tube's other surface is set either by the surface ratio s = R_outer / R_inner (the published tube model) or by a thickness in µm.",
    show: isTube,
    get: (c) => (c.sheet.surfaceRatio === null ? 'thickness' : 'ratio'),
    // The current wall is converted, not replaced: s = (R + t) / R outward, R / (R - t) inward.
    set: (c, v) => ({ ...c, sheet: { ...c.sheet, ...convertWall(c, v === 'ratio' ? 'ratio' : 'thickness') } }),
  },
  field('sheet.surfaceRatio', {
    label: 'Surface ratio R_outer / R_inner',
    group: 'Sheet',
    kind: 'range',
    // The ratios the published tube model studies.
    max: 10,
    step: 0.05,
    live: true,
    show: (c) => isTube(c) && c.sheet.surfaceRatio !== null,
  }),
  field('sheet.thickness', {
    label: 'Thickness',
    group: 'Sheet',
    kind: 'range',
    max: maxThickness,
    step: 1,
    live: true,
    show: (c) => !isTube(c) || c.sheet.surfaceRatio === null,
  }),
  field('sheet.layers', { label: 'Intermediate layers', group: 'Sheet', step: 1 }),
  field('sheet.adjacency', {
    label: 'Neighbours from',
    group: 'Sheet',
    labels: { both: 'labels and exact', labels: 'labels (pixels)', exact: 'exact (Delaunay)' },
  }),
  field('sheet.minContactLength', { label: 'Ignore contacts shorter than (empty: lab default)', group: 'Sheet', step: 0.5 }),
  // Every schema field is reachable in the form (issue 26): the protocol with the sheet, the
  // rest under Advanced (controls.ts).
  field('sheet.protocol', {
    label: 'Protocol',
    group: 'Sheet',
    labels: { default: 'default', lab: 'lab (Gómez-Gálvez et al.: tubes with a surface ratio, outward)' },
  }),
  field('sheet.offset', {
    label: 'Other surface made by',
    group: 'Sheet',
    labels: { normal: 'parallel surface (normal)', axes: 'semi-axes + thickness (the lab spheroid model)' },
    show: (c) => layoutOfKind(c.surface.kind).offsetChoice,
  }),
  field('sheet.layerStep', { label: 'Layer step (tube: in s; else µm; empty: layers evenly spaced)', group: 'Sheet', step: 0.05 }),
  field('sheet.validityMaxRatio', { label: 'Lab protocol: valid cells checked up to ratio', group: 'Sheet', step: 0.25 }),
  field('sheet.minContactPixels', {
    label: 'Labels method: ignore contacts shorter than (texel edges at 512 px around; empty: the µm rule)',
    group: 'Sheet',
    step: 1,
  }),
  field('engine', {
    label: 'Engine',
    group: 'Lloyd',
    labels: { auto: 'auto', gpu: 'GPU (jump flood; labels and exact)', exact: 'exact (CPU; exact method only)' },
  }),
  ...(['u', 'v'] as const).map((axis, k): FieldSpec => ({
    // Panel only: one coordinate of density.center ([u, v], µm).
    path: `density.center.${axis}`,
    label: `Patch centre ${axis}`,
    group: 'Density',
    kind: 'number',
    unit: 'µm',
    step: 1,
    description: () => schemaField('density.center', 'gaussian').description ?? '',
    show: (c) => c.density.kind === 'gaussian',
    get: (c) => (c.density.kind === 'gaussian' ? c.density.center[k] : null),
    set: (c, v) => {
      if (c.density.kind !== 'gaussian') return c;
      const center = [...c.density.center] as [number, number];
      center[k] = Number(v);
      return { ...c, density: { ...c.density, center } };
    },
  })),
];

/** A field whose value differs between two configurations, in the page's words ("Thickness", "17 µm"). */
export interface ChangedField {
  path: string;
  label: string;
  shown: string;
  form: string;
}

/** The form's fields (as shown for `form`) whose values differ between `shown` and `form`. */
export function changedFields(shown: Config, form: Config): ChangedField[] {
  const out: ChangedField[] = [];
  const text = (spec: FieldSpec, value: unknown) => {
    if (value === null || value === undefined) return 'default';
    if (typeof value === 'number') return `${Number(value.toPrecision(6))}${spec.unit ? ` ${spec.unit}` : ''}`;
    if (typeof value === 'string' && value.startsWith('data:')) return 'an image';
    return String(value);
  };
  const read = (spec: FieldSpec, c: Config): unknown => {
    if (spec.get) return spec.get(c);
    let value: unknown = c;
    for (const key of spec.path.split('.')) value = value && typeof value === 'object' ? (value as Record<string, unknown>)[key] : undefined;
    return value;
  };
  for (const spec of FIELDS) {
    if (spec.show && !spec.show(form) && !spec.show(shown)) continue;
    const a = read(spec, shown);
    const b = read(spec, form);
    if (JSON.stringify(a) !== JSON.stringify(b)) out.push({ path: spec.path, label: spec.label, shown: text(spec, a), form: text(spec, b) });
  }
  return out;
}
