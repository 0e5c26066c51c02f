import type { SurfaceConfig } from './config';
import type { Grid } from './grid';

export type Vec3 = [number, number, number];

/**
 * Maps a point of the unrolled domain (texel units) to 3D (µm) and gives the unit normal.
 * Plane: z = 0, normal +z. Tube: x runs around the axis (angle 2πx/width), y along it (z);
 * the normal points outward, away from the axis.
 */
export function embed(surface: SurfaceConfig, grid: Grid, x: number, y: number): { position: Vec3; normal: Vec3 } {
  if (surface.kind === 'plane') {
    return { position: [x * grid.texelX, y * grid.texelY, 0], normal: [0, 0, 1] };
  }
  const angle = (2 * Math.PI * x) / grid.width;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  return { position: [surface.radius * c, surface.radius * s, y * grid.texelY], normal: [c, s, 0] };
}

/** Surface coordinates (µm along the unrolled domain) of a point in texel units. */
export function surfaceCoordinates(grid: Grid, x: number, y: number): [number, number] {
  return [x * grid.texelX, y * grid.texelY];
}
