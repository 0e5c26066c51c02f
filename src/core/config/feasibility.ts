/** The grid a configuration implies, and the checks that need it (or several fields at once). */
import { LAB_MEAN_CELL_DIAMETER_PIXELS, LAB_MIN_BOUNDARY_PIXELS } from '../analysis/adjacency';
import type { Grid } from '../grid';
import { checkMethods } from './methods';
import { ConfigError } from './configError';
import { RSA_JAMMING_COVERAGE } from '../sites';
import type { ClosedConfig, ClosedSurfaceConfig, PlanarConfig, SurfaceConfig } from './types';

// ---------------------------------------------------------------------------------------------
// Grid and feasibility
// ---------------------------------------------------------------------------------------------

/** The unrolled domain of a surface: its extents in µm and which axes wrap. */
export interface UnrolledDomain {
  lengthX: number;
  lengthY: number;
  periodicX: boolean;
  periodicY: boolean;
}

export function unrolledDomain(surface: SurfaceConfig): UnrolledDomain {
  if (surface.kind === 'tube') {
    return { lengthX: 2 * Math.PI * surface.radius, lengthY: surface.length, periodicX: true, periodicY: false };
  }
  return { lengthX: surface.width, lengthY: surface.height, periodicX: surface.periodicX, periodicY: surface.periodicY };
}

/**
 * The sampling grid: the longer side gets `resolution` texels, the other as many texels of the
 * same size as fit (rounded, at least 1). Texel sizes are then recomputed from the texel counts
 * so both lengths are exact; texels are square up to that rounding.
 */
export function makeGrid(config: Pick<PlanarConfig, 'surface' | 'resolution'>): Grid {
  const domain = unrolledDomain(config.surface);
  const texel = Math.max(domain.lengthX, domain.lengthY) / config.resolution;
  const width = domain.lengthX >= domain.lengthY ? config.resolution : Math.max(1, Math.round(domain.lengthX / texel));
  const height = domain.lengthX >= domain.lengthY ? Math.max(1, Math.round(domain.lengthY / texel)) : config.resolution;
  return {
    width,
    height,
    texelX: domain.lengthX / width,
    texelY: domain.lengthY / height,
    periodicX: domain.periodicX,
    periodicY: domain.periodicY,
  };
}

/** Texels a cell needs at least for its centroid to mean something. */
const MIN_TEXELS_PER_CELL = 16;

/** Area per point of the densest packing of points `spacing` apart (hexagonal lattice). */
function hexagonalAreaPerPoint(spacing: number): number {
  return (Math.sqrt(3) / 2) * spacing * spacing;
}

/**
 * Refuses a minSpacing that the hexagonal lattice could hold but random placement cannot: sites
 * are placed by random sequential addition, which jams once the disks of diameter d around them
 * cover RSA_JAMMING_COVERAGE of the area (about 0.547, against the lattice's 0.907). Such a run
 * would place sites for a while and then fail; refused now, before anything is computed.
 */
function checkPlacementJam(cells: number, d: number, available: number, area: number): void {
  const coverage = (cells * Math.PI * d * d) / 4 / available;
  if (coverage > RSA_JAMMING_COVERAGE) {
    const largest = Math.sqrt((4 * RSA_JAMMING_COVERAGE * area) / (Math.PI * cells));
    throw new ConfigError(
      'minSpacing',
      `minSpacing: ${cells} cells at least ${d} µm apart would cover ${fmt(100 * coverage)} % of the surface with their disks, but random placement jams near ${100 * RSA_JAMMING_COVERAGE} %; lower minSpacing to well below ${fmt(largest)} µm or lower cells`,
    );
  }
}

/**
 * Rejects configurations that validate but cannot run sensibly on this grid. These checks need
 * the grid (or several fields at once), which is why they are not in the schema.
 */
export function checkFeasible(config: PlanarConfig, grid: Grid): void {
  const texels = grid.width * grid.height;
  if (config.cells * MIN_TEXELS_PER_CELL > texels) {
    const need = config.cells * MIN_TEXELS_PER_CELL;
    throw new ConfigError(
      'cells',
      `cells: ${config.cells} cells need at least ${need} texels (${MIN_TEXELS_PER_CELL} per cell) but the grid has ${texels}; lower cells or raise resolution`,
    );
  }

  const domain = unrolledDomain(config.surface);
  const d = config.minSpacing;
  if (d > 0 && config.cells > 1) {
    // Disks of diameter d around the sites do not overlap and stay within the domain grown by
    // d/2 on each open side; their packing density is at most that of the hexagonal lattice.
    // This is a necessary condition only: random dart throwing saturates well before it.
    const areaX = domain.lengthX + (domain.periodicX ? 0 : d);
    const areaY = domain.lengthY + (domain.periodicY ? 0 : d);
    const available = areaX * areaY;
    const needed = config.cells * hexagonalAreaPerPoint(d);
    if (needed > available) {
      const area = domain.lengthX * domain.lengthY;
      const largest = Math.sqrt(area / (config.cells * (Math.sqrt(3) / 2)));
      throw new ConfigError(
        'minSpacing',
        `minSpacing: ${config.cells} cells at least ${d} µm apart need ${fmt(needed)} µm² (hexagonal packing) but the surface has ${fmt(area)} µm²; lower minSpacing to at most ${fmt(largest)} µm or lower cells`,
      );
    }
    // A density field places sites by rejection too: the jam comes sooner, found as it happens.
    if (config.density.kind === 'uniform') checkPlacementJam(config.cells, d, available, domain.lengthX * domain.lengthY);
  }

  checkSheet(config);
  checkDensityScale(config, grid);

  if (config.density.kind === 'gaussian') {
    const [u, v] = config.density.center;
    if (u < 0 || u > domain.lengthX || v < 0 || v > domain.lengthY) {
      throw new ConfigError(
        'density.center',
        `density.center: [${u}, ${v}] µm is outside the domain [0, ${fmt(domain.lengthX)}] x [0, ${fmt(domain.lengthY)}] µm; move the centre inside`,
      );
    }
  }
}

/** Density values the density texture (32-bit floats) holds, with room for their products. */
const DENSITY_RANGE = [1e-30, 1e30] as const;

/**
 * A density the grid can hold: every value within DENSITY_RANGE (1e-300 became 0 in the texture,
 * 1e300 infinity) and stripes at least two texels wide per period (finer ones cannot be drawn on
 * the grid, and the exact engine's cell integrals cut every cell at each stripe: a period of 1e-6
 * µm never finished).
 */
function checkDensityScale(config: PlanarConfig, grid: Grid): void {
  const density = config.density as unknown as Record<string, unknown>;
  for (const key of ['from', 'to', 'low', 'high', 'peak']) {
    const value = density[key];
    if (typeof value === 'number' && !(value >= DENSITY_RANGE[0] && value <= DENSITY_RANGE[1])) {
      throw new ConfigError(
        `density.${key}`,
        `density.${key}: ${value} is outside ${DENSITY_RANGE[0]} to ${DENSITY_RANGE[1]}, what the density texture holds; densities are relative: scale them together`,
      );
    }
  }
  if (config.density.kind === 'stripes') {
    const texel = config.density.axis === 'x' ? grid.texelX : grid.texelY;
    if (!(config.density.period >= 2 * texel)) {
      throw new ConfigError(
        'density.period',
        `density.period: ${config.density.period} µm is finer than two texels of this grid (2 x ${fmt(texel)} µm along ${config.density.axis}): the stripes cannot be drawn on it; raise density.period to at least ${fmt(2 * texel)} µm, or resolution`,
      );
    }
  }
}

/** The other surface must exist: a ratio only on a tube, an inward offset short of the axis. */
export function checkSheet(config: PlanarConfig): void {
  checkMethods(config);
  const { sheet, surface } = config;
  if (sheet.surfaceRatio !== null) {
    if (surface.kind !== 'tube') {
      throw new ConfigError(
        'sheet.surfaceRatio',
        `sheet.surfaceRatio: only a tube has a surface ratio (surface.kind is "${surface.kind}"); give sheet.thickness in µm instead`,
      );
    }
    if (sheet.thickness !== 0) {
      throw new ConfigError(
        'sheet.thickness',
        `sheet.thickness: give either sheet.thickness (${sheet.thickness} µm) or sheet.surfaceRatio (${sheet.surfaceRatio}), not both`,
      );
    }
  }
  if (surface.kind === 'tube' && sheet.direction === 'inward' && sheet.thickness >= surface.radius) {
    throw new ConfigError(
      'sheet.thickness',
      `sheet.thickness: ${sheet.thickness} µm inward reaches the tube's axis (radius ${fmt(surface.radius)} µm); use less than ${fmt(surface.radius)} µm or direction "outward"`,
    );
  }
}

function fmt(value: number): string {
  return Number(value.toPrecision(6)).toString();
}

/** `resolution` of planes and tubes when the config leaves it null. */
export const PLANAR_DEFAULT_RESOLUTION = 512;
/** The lab's shortest counted contact relative to the mean cell diameter (6 px of 102.4 px). */
const LAB_CONTACT_PER_DIAMETER = LAB_MIN_BOUNDARY_PIXELS / LAB_MEAN_CELL_DIAMETER_PIXELS;

/**
 * The resolution a closed surface gets when its config leaves `resolution` null (planes and
 * tubes: PLANAR_DEFAULT_RESOLUTION; surfaceLayout.ts's defaultResolution picks): the smallest n (a multiple of 8, 32 to 1024) whose texel edge sqrt(area / 6 n²) is
 * at most half the minimum contact length, so that the labels method resolves every counted
 * contact (with the default contact rule, 6/102.4 of the mean cell diameter, n depends on the
 * number of cells only: 200 for 200 cells), and at least MIN_TEXELS_PER_CELL texels per cell.
 */
export function closedDefaultResolution(config: Pick<ClosedConfig, 'surface' | 'cells' | 'sheet'>): number {
  const { surface, cells, sheet } = config;
  const area =
    surface.kind === 'sphere' ? 4 * Math.PI * surface.radius ** 2 : surface.kind === 'ellipsoid' ? ellipsoidArea(surface.a, surface.b, surface.c) : null;
  const length = sheet.minContactLength;
  // Diameter over contact length: from the given length where the area is known before loading.
  const diameterPerContact = area !== null && length !== null && length > 0 ? Math.sqrt(area / cells) / length : 1 / LAB_CONTACT_PER_DIAMETER;
  const forContacts = 2 * Math.sqrt(cells / 6) * diameterPerContact;
  const forCells = Math.sqrt((MIN_TEXELS_PER_CELL * cells) / 6);
  const n = Math.ceil(Math.max(forContacts, forCells) / 8) * 8;
  return Math.min(1024, Math.max(32, n));
}

// ---------------------------------------------------------------------------------------------
// Closed surfaces: cube-map size and feasibility
// ---------------------------------------------------------------------------------------------

/** The cube-map geometry image of a closed surface: n x n texels per face, 6 faces. */
export interface CubeGrid {
  /** Texels along each face edge (= config.resolution). */
  readonly n: number;
  readonly texels: number;
}

export function makeCubeGrid(config: Pick<ClosedConfig, 'resolution'>): CubeGrid {
  return { n: config.resolution, texels: 6 * config.resolution * config.resolution };
}

/** Surface area of an ellipsoid (Knud Thomsen's formula, relative error below 1.1 %). */
export function ellipsoidArea(a: number, b: number, c: number): number {
  const p = 1.6075;
  return 4 * Math.PI * (((a * b) ** p + (a * c) ** p + (b * c) ** p) / 3) ** (1 / p);
}

/**
 * Smallest principal radius of curvature of an analytic closed surface (µm): R for a sphere;
 * (smallest semi-axis)² / (largest semi-axis) for an ellipsoid (at the tips of the longest
 * axis). null for a mesh (estimated from the mesh at run time).
 */
export function minCurvatureRadius(surface: ClosedSurfaceConfig): number | null {
  if (surface.kind === 'sphere') return surface.radius;
  if (surface.kind === 'ellipsoid') {
    const lo = Math.min(surface.a, surface.b, surface.c);
    const hi = Math.max(surface.a, surface.b, surface.c);
    return (lo * lo) / hi;
  }
  return null;
}

/** The refusal of an inward offset that reaches a focal point of the surface. */
export function inwardOffsetError(thickness: number, radius: number, where: string): ConfigError {
  return new ConfigError(
    'sheet.thickness',
    `sheet.thickness: ${fmt(thickness)} µm inward reaches the smallest radius of curvature of the ${where} (${fmt(radius)} µm), where the offset surface folds over itself; use less than ${fmt(radius)} µm or direction "outward"`,
  );
}

/**
 * checkFeasible for closed surfaces: at most one cell per 16 texels of the 6 n² cube map,
 * uniform density only, minSpacing within hexagonal packing of the surface area (analytic
 * surfaces), no surfaceRatio, exact adjacency only on the sphere, and no inward offset at or
 * beyond the smallest radius of curvature (sphere, ellipsoid; a mesh is checked once loaded).
 */
export function checkClosedFeasible(config: ClosedConfig, grid: CubeGrid = makeCubeGrid(config)): void {
  if (config.cells * MIN_TEXELS_PER_CELL > grid.texels) {
    const need = config.cells * MIN_TEXELS_PER_CELL;
    throw new ConfigError(
      'cells',
      `cells: ${config.cells} cells need at least ${need} texels (${MIN_TEXELS_PER_CELL} per cell) but the cube map has ${grid.texels} (6 x ${grid.n}²); lower cells or raise resolution`,
    );
  }
  if (config.density.kind !== 'uniform') {
    throw new ConfigError('density.kind', `density.kind: closed surfaces support only "uniform" density for now (got "${config.density.kind}")`);
  }
  const { surface } = config;
  const d = config.minSpacing;
  if (d > 0 && config.cells > 1 && surface.kind !== 'mesh') {
    const area = surface.kind === 'sphere' ? 4 * Math.PI * surface.radius ** 2 : ellipsoidArea(surface.a, surface.b, surface.c);
    const needed = config.cells * hexagonalAreaPerPoint(d);
    if (needed > area) {
      const largest = Math.sqrt(area / (config.cells * (Math.sqrt(3) / 2)));
      throw new ConfigError(
        'minSpacing',
        `minSpacing: ${config.cells} cells at least ${d} µm apart need ${fmt(needed)} µm² (hexagonal packing) but the surface has ${fmt(area)} µm²; lower minSpacing to at most ${fmt(largest)} µm or lower cells`,
      );
    }
    checkPlacementJam(config.cells, d, area, area);
  }
  checkClosedSheet(config);
}

/** The sheet of a closed surface: the GPU engine, a thickness (no ratio), methods that exist there, no fold. */
export function checkClosedSheet(config: ClosedConfig): void {
  const { surface, sheet } = config;
  if (config.engine === 'exact') {
    throw new ConfigError('engine', `engine: "exact" runs planes and tubes only; a ${surface.kind} runs on the GPU cube-map engine: use "auto" or "gpu"`);
  }
  checkMethods(config);
  if (sheet.surfaceRatio !== null) {
    throw new ConfigError(
      'sheet.surfaceRatio',
      `sheet.surfaceRatio: only a tube has a surface ratio (surface.kind is "${surface.kind}"); give sheet.thickness in µm instead`,
    );
  }
  const radius = minCurvatureRadius(surface);
  // "axes" offsets are ellipsoids again: they never fold (checkMethods bounds the inward ones).
  if (radius !== null && sheet.offset === 'normal' && sheet.direction === 'inward' && sheet.thickness >= radius) {
    throw inwardOffsetError(sheet.thickness, radius, surface.kind);
  }
}
