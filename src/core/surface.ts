import type { SurfaceConfig } from './config';
import type { Grid } from './grid';

export type Vec3 = [number, number, number];

/**
 * Maps a point of the unrolled domain (texel units) of the surface `offset` µm along the seeded
 * surface's normal to 3D (µm) and gives the unit normal. Plane: z = offset, normal +z. Tube: x
 * runs around the axis (angle 2πx/width), y along it (z), radius + offset from the axis; the
 * normal points outward, away from the axis.
 */
export function embed(
  surface: SurfaceConfig,
  grid: Grid,
  x: number,
  y: number,
  offset = 0,
): { position: Vec3; normal: Vec3 } {
  if (surface.kind === 'plane') {
    return { position: [x * grid.texelX, y * grid.texelY, offset], normal: [0, 0, 1] };
  }
  const angle = (2 * Math.PI * x) / grid.width;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const radius = surface.radius + offset;
  return { position: [radius * c, radius * s, y * grid.texelY], normal: [c, s, 0] };
}

/** Surface coordinates (µm along the unrolled domain) of a point in texel units. */
export function surfaceCoordinates(grid: Grid, x: number, y: number): [number, number] {
  return [x * grid.texelX, y * grid.texelY];
}
