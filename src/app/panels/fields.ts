/**
 * Every control of the configuration panel, as data: the config path it edits, its label, its
 * kind and range, and when it shows. The panel (controls.ts) renders and binds them; changing
 * the list is all it takes to add a field. Closed surfaces: sphere (radius), ellipsoid (a, b,
 * c), mesh (a sample from public/meshes/ or a user's file; see model/meshFiles.ts).
 */
import { DEFAULT_TUBE_RADIUS, isClosedConfig, unrolledDomain, type AnyConfig, type DensitySpec, type SurfaceConfig } from '../../core/config';
import { SAMPLE_MESHES, sampleName, sampleUrl } from '../model/meshFiles';

type Config = AnyConfig;
type AnySurface = AnyConfig['surface'];

export interface Option {
  value: string;
  label: string;
  disabled?: boolean;
}

export interface FieldSpec {
  /** Dotted config path, or a virtual field handled by `get`/`set`. */
  path: string;
  label: string;
  group: 'Surface' | 'Cells' | 'Density' | 'Lloyd' | 'Sheet';
  kind: 'number' | 'integer' | 'range' | 'select' | 'checkbox' | 'optional-number' | 'file' | 'mesh-file';
  min?: number;
  max?: number | ((c: Config) => number);
  step?: number;
  unit?: string;
  options?: Option[];
  note?: string;
  /** Re-run live while dragging (debounced). */
  live?: boolean;
  show?: (c: Config) => boolean;
  get?: (c: Config) => unknown;
  /** Returns the new config (plain data, validated by the caller). */
  set?: (c: Config, value: unknown) => Config;
}

const isTube = (c: Config) => c.surface.kind === 'tube';
const isPlane = (c: Config) => c.surface.kind === 'plane';
const isKind = (kind: AnySurface['kind']) => (c: Config) => c.surface.kind === kind;
const isMesh = isKind('mesh');

/** Closed surfaces start small enough for a software GPU: n texels per cube face. */
export const CLOSED_RESOLUTION = 64;
const PLANAR_RESOLUTION = 256;
export const DEFAULT_SPHERE_RADIUS = 60;
export const DEFAULT_ELLIPSOID = { a: 90, b: 45, c: 45 } as const;
/** The samples are about unit size: µm per unit. */
export const DEFAULT_MESH_SCALE = 50;
export const DEFAULT_MESH_SRC = sampleUrl('organoid.ply');

/** A surface of `kind` with default dimensions (closed kinds), or keeping the unrolled size (plane, tube). */
export function surfaceOfKind(current: AnySurface, kind: string): AnySurface {
  if (kind === 'sphere') return { kind: 'sphere', radius: current.kind === 'sphere' ? current.radius : DEFAULT_SPHERE_RADIUS };
  if (kind === 'ellipsoid') return { kind: 'ellipsoid', ...DEFAULT_ELLIPSOID };
  if (kind === 'mesh') return { kind: 'mesh', src: DEFAULT_MESH_SRC, scale: DEFAULT_MESH_SCALE, geodesic: false };
  if (current.kind === 'plane' || current.kind === 'tube') return planarOfKind(current, kind);
  return planarOfKind({ kind: 'tube', radius: 256 / (2 * Math.PI), length: 512 }, kind);
}

/** Switching kind: closed kinds get a cube-map resolution, planar ones a planar one; no surface ratio off a tube; uniform density on closed surfaces. */
function withSurfaceKind(c: Config, kind: string): Config {
  const surface = surfaceOfKind(c.surface, kind);
  const wasClosed = isClosedConfig(c);
  const closed = kind === 'sphere' || kind === 'ellipsoid' || kind === 'mesh';
  const resolution = closed && !wasClosed ? Math.min(c.resolution, CLOSED_RESOLUTION) : !closed && wasClosed ? PLANAR_RESOLUTION : c.resolution;
  return {
    ...c,
    surface,
    resolution,
    density: closed ? { kind: 'uniform' } : c.density,
    sheet: { ...c.sheet, surfaceRatio: kind === 'tube' ? c.sheet.surfaceRatio : null },
  } as Config;
}

/** Largest thickness offered by the slider. */
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
  if (s.kind === 'mesh') return Math.max(1, Math.round(s.scale * (inward ? 0.5 : 1)));
  return 400;
}
const densityIs = (...kinds: DensitySpec['kind'][]) => (c: Config) => kinds.includes(c.density.kind);

/** Switching between plane and tube keeps the unrolled size: circumference <-> width, length <-> height. */
function planarOfKind(current: SurfaceConfig, kind: string): SurfaceConfig {
  const d = unrolledDomain(current);
  if (kind === 'plane') return { kind: 'plane', width: d.lengthX, height: d.lengthY, periodicX: false, periodicY: false };
  if (kind === 'tube') return { kind: 'tube', radius: d.lengthX / (2 * Math.PI) || DEFAULT_TUBE_RADIUS, length: d.lengthY };
  throw new Error(`surface.kind: unknown surface "${kind}"; use plane, tube, sphere, ellipsoid or mesh`);
}

/** Density presets: parameters that suit the current domain. */
export function densityPreset(kind: string, c: Config): DensitySpec {
  // Closed surfaces take uniform density only: validation says so for any other preset.
  const d = isClosedConfig(c) ? { lengthX: 1, lengthY: 1 } : unrolledDomain(c.surface);
  switch (kind) {
    case 'linear':
      return { kind: 'linear', axis: 'y', from: 1, to: 4 };
    case 'gaussian':
      return { kind: 'gaussian', center: [d.lengthX / 2, d.lengthY / 2], sigma: Math.min(d.lengthX, d.lengthY) / 4, peak: 6 };
    case 'stripes':
      return { kind: 'stripes', axis: 'y', period: d.lengthY / 2, low: 1, high: 4 };
    case 'image':
      return c.density.kind === 'image' ? c.density : { kind: 'image', src: '', low: 1, high: 16, invert: false };
    default:
      return { kind: 'uniform' };
  }
}

const AXES: Option[] = [
  { value: 'x', label: 'x (around / across)' },
  { value: 'y', label: 'y (along)' },
];

const UPLOAD_NOTE = 'An uploaded file cannot travel in a link: the link and the saved session keep only its name, and ask for the file again.';

export const FIELDS: FieldSpec[] = [
  {
    path: 'surface.kind',
    label: 'Surface',
    group: 'Surface',
    kind: 'select',
    options: [
      { value: 'tube', label: 'tube' },
      { value: 'plane', label: 'plane' },
      { value: 'sphere', label: 'sphere' },
      { value: 'ellipsoid', label: 'ellipsoid' },
      { value: 'mesh', label: 'mesh (sample or upload)' },
    ],
    set: (c, v) => withSurfaceKind(c, String(v)),
  },
  { path: 'surface.radius', label: 'Radius', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: (c) => isTube(c) || c.surface.kind === 'sphere' },
  { path: 'surface.a', label: 'Semi-axis a (x)', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: isKind('ellipsoid') },
  { path: 'surface.b', label: 'Semi-axis b (y)', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: isKind('ellipsoid') },
  { path: 'surface.c', label: 'Semi-axis c (z)', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: isKind('ellipsoid') },
  {
    path: 'surface.sample',
    label: 'Mesh',
    group: 'Surface',
    kind: 'select',
    options: [...SAMPLE_MESHES.map((m) => ({ value: m.name, label: m.label })), { value: '', label: 'uploaded file', disabled: true }],
    show: isMesh,
    get: (c) => (c.surface.kind === 'mesh' ? (sampleName(c.surface.src) ?? '') : ''),
    set: (c, v) => (c.surface.kind === 'mesh' && v ? { ...c, surface: { ...c.surface, src: sampleUrl(String(v)) } } : c),
  },
  {
    path: 'surface.src',
    label: 'Mesh file (.ply, .obj, .stl)',
    group: 'Surface',
    kind: 'mesh-file',
    note: UPLOAD_NOTE,
    show: isMesh,
  },
  { path: 'surface.scale', label: 'Scale', unit: 'µm per mesh unit', group: 'Surface', kind: 'number', min: 0, step: 1, show: isMesh },
  { path: 'surface.geodesic', label: 'Compare with the geodesic (heat-method) Voronoi', group: 'Surface', kind: 'checkbox', show: isMesh },
  { path: 'surface.length', label: 'Length', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: isTube },
  { path: 'surface.width', label: 'Width', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: isPlane },
  { path: 'surface.height', label: 'Height', unit: 'µm', group: 'Surface', kind: 'number', min: 0, step: 1, show: isPlane },
  { path: 'surface.periodicX', label: 'Periodic in x', group: 'Surface', kind: 'checkbox', show: isPlane },
  { path: 'surface.periodicY', label: 'Periodic in y', group: 'Surface', kind: 'checkbox', show: isPlane },
  { path: 'resolution', label: 'Resolution (texels: longer side; closed: per cube-face edge)', group: 'Surface', kind: 'integer', min: 16, max: 16384, step: 1 },

  { path: 'cells', label: 'Cells', group: 'Cells', kind: 'integer', min: 1, step: 1 },
  { path: 'seed', label: 'Random seed', group: 'Cells', kind: 'integer', min: 0, step: 1 },
  { path: 'minSpacing', label: 'Minimum initial spacing', unit: 'µm', group: 'Cells', kind: 'number', min: 0, step: 0.5 },

  {
    path: 'density.kind',
    label: 'Density preset',
    group: 'Density',
    kind: 'select',
    options: [
      { value: 'uniform', label: 'uniform' },
      { value: 'linear', label: 'gradient (linear)' },
      { value: 'gaussian', label: 'dense patch (gaussian)' },
      { value: 'stripes', label: 'stripes' },
      { value: 'image', label: 'grayscale image' },
    ],
    set: (c, v) => ({ ...c, density: densityPreset(String(v), c) }),
  },
  { path: 'density.axis', label: 'Axis', group: 'Density', kind: 'select', options: AXES, show: densityIs('linear', 'stripes') },
  { path: 'density.from', label: 'Density at start', group: 'Density', kind: 'number', min: 0, step: 0.1, show: densityIs('linear') },
  { path: 'density.to', label: 'Density at end', group: 'Density', kind: 'number', min: 0, step: 0.1, show: densityIs('linear') },
  { path: 'density.sigma', label: 'Patch size σ', unit: 'µm', group: 'Density', kind: 'number', min: 0, step: 1, show: densityIs('gaussian') },
  { path: 'density.peak', label: 'Peak density', group: 'Density', kind: 'number', min: 0, step: 0.5, show: densityIs('gaussian') },
  { path: 'density.period', label: 'Period', unit: 'µm', group: 'Density', kind: 'number', min: 0, step: 1, show: densityIs('stripes') },
  { path: 'density.low', label: 'Low density', group: 'Density', kind: 'number', min: 0, step: 0.1, show: densityIs('stripes', 'image') },
  { path: 'density.high', label: 'High density', group: 'Density', kind: 'number', min: 0, step: 0.1, show: densityIs('stripes', 'image') },
  { path: 'density.invert', label: 'Invert image', group: 'Density', kind: 'checkbox', show: densityIs('image') },
  { path: 'density.src', label: 'Grayscale image (white = dense)', group: 'Density', kind: 'file', show: densityIs('image') },

  { path: 'lloyd.maxIterations', label: 'Lloyd iterations', group: 'Lloyd', kind: 'integer', min: 0, max: 100000, step: 1 },
  { path: 'lloyd.tolerance', label: 'Stop when sites move less than', unit: 'µm', group: 'Lloyd', kind: 'number', min: 0, step: 0.05 },
  { path: 'lloyd.overRelaxation', label: 'Over-relaxation ω', group: 'Lloyd', kind: 'number', min: 1, max: 1.95, step: 0.05 },
  { path: 'lloyd.warmStart', label: 'Warm-start jump flood', group: 'Lloyd', kind: 'checkbox' },
  {
    path: 'jumpFlood.variant',
    label: 'Jump flood',
    group: 'Lloyd',
    kind: 'select',
    options: ['jfa+2', '1+jfa', 'jfa'].map((v) => ({ value: v, label: v })),
  },
  {
    path: 'centroidPath',
    label: 'Centroid pass',
    group: 'Lloyd',
    kind: 'select',
    options: ['auto', 'blend', 'gather', 'readback'].map((v) => ({ value: v, label: v })),
  },

  {
    path: 'sheet.seeded',
    label: 'Seeded surface',
    group: 'Sheet',
    kind: 'select',
    options: [
      { value: 'basal', label: 'basal' },
      { value: 'apical', label: 'apical' },
    ],
  },
  {
    path: 'sheet.direction',
    label: 'Other surface lies',
    group: 'Sheet',
    kind: 'select',
    options: [
      { value: 'outward', label: 'outward' },
      { value: 'inward', label: 'inward' },
    ],
  },
  {
    path: 'sheet.geometry',
    label: 'Set the other surface by',
    group: 'Sheet',
    kind: 'select',
    options: [
      { value: 'ratio', label: 'surface ratio' },
      { value: 'thickness', label: 'thickness' },
    ],
    show: isTube,
    get: (c) => (c.sheet.surfaceRatio === null ? 'thickness' : 'ratio'),
    set: (c, v) => ({ ...c, sheet: { ...c.sheet, surfaceRatio: v === 'ratio' ? 2 : null, thickness: 0 } }),
  },
  {
    path: 'sheet.surfaceRatio',
    label: 'Surface ratio R_outer / R_inner',
    group: 'Sheet',
    kind: 'range',
    min: 1,
    max: 10,
    step: 0.05,
    live: true,
    show: (c) => isTube(c) && c.sheet.surfaceRatio !== null,
  },
  {
    path: 'sheet.thickness',
    label: 'Thickness',
    unit: 'µm',
    group: 'Sheet',
    kind: 'range',
    min: 0,
    max: maxThickness,
    step: 1,
    live: true,
    show: (c) => !isTube(c) || c.sheet.surfaceRatio === null,
  },
  { path: 'sheet.layers', label: 'Intermediate layers', group: 'Sheet', kind: 'integer', min: 0, max: 64, step: 1 },
  {
    path: 'sheet.adjacency',
    label: 'Neighbours from',
    group: 'Sheet',
    kind: 'select',
    options: [
      { value: 'both', label: 'labels and exact' },
      { value: 'labels', label: 'labels (pixels)' },
      { value: 'exact', label: 'exact (Delaunay)' },
    ],
  },
  {
    path: 'sheet.minContactLength',
    label: 'Ignore contacts shorter than (empty: lab default)',
    unit: 'µm',
    group: 'Sheet',
    kind: 'optional-number',
    min: 0,
    step: 0.5,
  },
];
