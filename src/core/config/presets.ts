/**
 * Starting points shared by the app and the element (neither imports the other): the example
 * sheet the app opens with the first time, and the dimensions a surface or density kind gets
 * when the user switches to it (fields the schema requires and has no default for).
 *
 * None of these is a default: every field a config, a link, an attribute or a form leaves out
 * takes the schema's default (schema.ts), the same in the CLI, the library, the app, the element
 * and links. The example sets only the fields it is an example of.
 */
import { DEFAULT_TUBE_RADIUS } from './schema';
import { unrolledDomain } from './feasibility';
import { layoutOfKind } from './surfaceLayout';
import type { Config, AnySurfaceConfig, ConfigInput, DensitySpec, SurfaceConfig } from './types';

/**
 * The example the app opens with when neither a link nor a previous session gives a config: a
 * short tube (256 µm around, 512 µm long), 150 cells, surface ratio 1.5. Everything else
 * (Lloyd iterations, resolution, ...) is the schema's default.
 */
export const APP_START: ConfigInput = {
  surface: { kind: 'tube', radius: 256 / (2 * Math.PI), length: 512 },
  cells: 150,
  sheet: { surfaceRatio: 1.5 },
};
const DEFAULT_SPHERE_RADIUS = 60;
const DEFAULT_ELLIPSOID = { a: 90, b: 45, c: 45 } as const;
/** The sample meshes are about unit size: µm per unit. */
const DEFAULT_MESH_SCALE = 50;
/** The organoid-like sample, served from public/meshes/ (the app's sample list: app/model/meshFiles.ts). */
const DEFAULT_MESH_SRC = '/meshes/organoid.ply';

/** A surface of `kind` with default dimensions (closed kinds), or keeping the unrolled size (plane, tube). */
export function surfaceOfKind(current: AnySurfaceConfig, kind: string): AnySurfaceConfig {
  if (kind === 'sphere') return { kind: 'sphere', radius: current.kind === 'sphere' ? current.radius : DEFAULT_SPHERE_RADIUS };
  if (kind === 'ellipsoid') return { kind: 'ellipsoid', ...DEFAULT_ELLIPSOID };
  if (kind === 'mesh') return { kind: 'mesh', src: DEFAULT_MESH_SRC, scale: DEFAULT_MESH_SCALE, geodesic: false };
  if (current.kind === 'plane' || current.kind === 'tube') return planarOfKind(current, kind);
  return planarOfKind({ kind: 'tube', radius: 256 / (2 * Math.PI), length: 512 }, kind);
}

/**
 * The thickness (µm) a sheet gets when the user switches to a surface kind, so every kind starts
 * from a sheet that shows the phenomenon, or, where the geometry rules it out (parallel planes,
 * concentric spheres), from one whose 0 % the page explains (core/analysis/byConstruction.ts),
 * never from the schema's thickness 0, where the surfaces coincide.
 */
export function thicknessForKind(surface: AnySurfaceConfig): number {
  switch (surface.kind) {
    case 'tube':
      return Math.round(surface.radius); // the outer radius twice the inner: s = 2
    case 'sphere':
      return Math.round(surface.radius / 3);
    case 'ellipsoid':
      return Math.round(Math.min(surface.a, surface.b, surface.c) / 2);
    case 'mesh':
      // Small against the sample meshes' concave radii of curvature (an offset past one is refused).
      return Math.max(1, Math.round(surface.scale / 10));
    default:
      return 20;
  }
}

/** Switching between plane and tube keeps the unrolled size: circumference <-> width, length <-> height. */
function planarOfKind(current: SurfaceConfig, kind: string): SurfaceConfig {
  const d = unrolledDomain(current);
  if (kind === 'plane') return { kind: 'plane', width: d.lengthX, height: d.lengthY, periodicX: false, periodicY: false };
  if (kind === 'tube') return { kind: 'tube', radius: d.lengthX / (2 * Math.PI) || DEFAULT_TUBE_RADIUS, length: d.lengthY };
  throw new Error(`surface.kind: unknown surface "${kind}"; use plane, tube, sphere, ellipsoid or mesh`);
}

/** Density presets: parameters that suit the current domain. */
export function densityPreset(kind: string, c: Pick<Config, 'surface' | 'density'>): DensitySpec {
  // A cube map takes uniform density only: validation says so for any other preset.
  const d = layoutOfKind(c.surface.kind).uniformDensityOnly ? { lengthX: 1, lengthY: 1 } : unrolledDomain(c.surface as SurfaceConfig);
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
