/**
 * A surface's layout, as data: the one place a surface kind is turned into what every consumer
 * reads (the budget, the engine policy, the CLI and the page's sweep, the 3D view, the exports,
 * the element and the app's form). A kind is either unrolled to a rectangle (plane, tube: the
 * planar grid) or sampled on a cube-map geometry image (sphere, ellipsoid, mesh); nothing
 * downstream asks which kind it has, it reads the fields below. Pure: no GPU imports
 * (src/gpu/layout.ts builds the GPU's TexelLayout for the same two layouts).
 */
import { sheetOffsets, surfaceStack } from '../sheetGeometry';
import { checkClosedFeasible, checkFeasible, closedDefaultResolution, makeCubeGrid, makeGrid, PLANAR_DEFAULT_RESOLUTION } from './feasibility';
import { isClosedKind, type Config, type ClosedConfig, type PlanarConfig } from './types';

/** The two layouts (also the GPU's surface family names). */
export type SurfaceLayoutName = 'planar grid' | 'cube map';

/** What a layout is, whatever the config's dimensions. */
export interface SurfaceLayoutKind {
  readonly name: SurfaceLayoutName;
  /** The texture in a refusal's words: "grid" or "cube map". */
  readonly textureName: 'grid' | 'cube map';
  /** Texture rows per `resolution`: 1 (the longer side of a grid) or 6 (n x 6n cube map). */
  readonly rowsPerResolution: 1 | 6;
  /**
   * Bytes per texel beyond a planar grid's while the surface is computed: a cube map's geometry
   * image (positions, normals, areas in float32/64), and on the GPU its point and weight per
   * texel (RGBA32F) instead of a weight alone (R32F): 60. A grid: 0.
   */
  readonly extraBytesPerTexel: number;
  /**
   * Whether the short side of the seeded grid depends on the surface's aspect (an unrolled grid)
   * and must be checked against MIN_TEXELS_PER_SIDE; a cube map is resolution² per face.
   */
  readonly aspectSetsShortSide: boolean;
  /** Whether the surface has a flat (unrolled) picture: the Lloyd movie, a textured grid in 3D. */
  readonly flatPicture: boolean;
  /** Whether the exact CPU engine can run Lloyd on it (else the GPU engine only). */
  readonly exactEngine: boolean;
  /** Whether only uniform density is supported on it. */
  readonly uniformDensityOnly: boolean;
  /**
   * Whether the other surface may be made by the semi-axes (sheet.offset "axes", the lab's
   * spheroid model) as well as along the normal; an unrolled sheet's is always the normal's.
   */
  readonly offsetChoice: boolean;
  /** The resolution a config of this layout gets when it leaves `resolution` null. */
  defaultResolution(config: Pick<Config, 'surface' | 'cells' | 'sheet'>): number;
}

/** A config's layout: its kind's fields and what follows from the config's dimensions. */
export interface SurfaceLayout extends SurfaceLayoutKind {
  /** Texel sizes of every surface of the stack, seeded first (grids: unrolled; cube maps: n x 6n). */
  grids(): { width: number; height: number }[];
  /** Refuses a config that validates but cannot run sensibly at its resolution (ConfigError). */
  checkFeasible(): void;
}

const PLANAR: SurfaceLayoutKind = {
  name: 'planar grid',
  textureName: 'grid',
  rowsPerResolution: 1,
  extraBytesPerTexel: 0,
  aspectSetsShortSide: true,
  flatPicture: true,
  exactEngine: true,
  uniformDensityOnly: false,
  offsetChoice: false,
  defaultResolution: () => PLANAR_DEFAULT_RESOLUTION,
};

const CUBE_MAP: SurfaceLayoutKind = {
  name: 'cube map',
  textureName: 'cube map',
  rowsPerResolution: 6,
  extraBytesPerTexel: 60,
  aspectSetsShortSide: false,
  flatPicture: false,
  exactEngine: false,
  uniformDensityOnly: true,
  offsetChoice: true,
  defaultResolution: (config) => closedDefaultResolution(config as Pick<ClosedConfig, 'surface' | 'cells' | 'sheet'>),
};

/** Each layout by its name (the GPU layer's TexelLayouts read theirs). */
export const LAYOUTS: { readonly [name in SurfaceLayoutName]: SurfaceLayoutKind } = { 'planar grid': PLANAR, 'cube map': CUBE_MAP };

/** The layout of a surface kind ("plane", "tube": planar grid; "sphere", "ellipsoid", "mesh": cube map). */
export function layoutOfKind(kind: string): SurfaceLayoutKind {
  return isClosedKind(kind) ? CUBE_MAP : PLANAR;
}

/**
 * The resolution a config gets when it leaves `resolution` null: 512 on a planar grid; on a cube
 * map the smallest that resolves the counted contacts (feasibility.ts, closedDefaultResolution).
 */
export function defaultResolution(config: Pick<Config, 'surface' | 'cells' | 'sheet'>): number {
  return layoutOfKind(config.surface.kind).defaultResolution(config);
}

/** The largest `resolution` whose texture fits a GPU's MAX_TEXTURE_SIZE on this layout. */
export function maxResolution(layout: SurfaceLayoutKind, maxTextureSize: number): number {
  return Math.floor(maxTextureSize / layout.rowsPerResolution);
}

/** A validated config's layout: where its surface kind is decided, once. */
export function surfaceLayout(config: Config): SurfaceLayout {
  const kind = layoutOfKind(config.surface.kind);
  if (kind === CUBE_MAP) {
    const closed = config as ClosedConfig;
    return {
      ...kind,
      grids: () => {
        const { n } = makeCubeGrid(closed);
        // One cube map per surface the pipeline builds (layers, or every sheet.layerStep µm).
        return sheetOffsets(closed).map(() => ({ width: n, height: 6 * n }));
      },
      checkFeasible: () => checkClosedFeasible(closed),
    };
  }
  const planar = config as PlanarConfig;
  return {
    ...kind,
    grids: () => surfaceStack(planar, makeGrid(planar)).map((s) => ({ width: s.grid.width, height: s.grid.height })),
    checkFeasible: () => checkFeasible(planar, makeGrid(planar)),
  };
}
