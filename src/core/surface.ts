import type { SurfaceConfig } from './config';
import type { Grid } from './grid';

export type Vec3 = [number, number, number];

/**
 * Maps a point of the unrolled domain (texel units) of the surface `offset` µm along the seeded
 * surface's normal to 3D (µm) and gives the unit normal. Plane: z = offset, normal +z. Tube: x
 * runs around the axis (angle 2πx/width), y along it (z), radius + offset from the axis; the
 * normal points outward, away from the axis.
 */
export function embed(surface: SurfaceConfig, grid: Grid, x: number, y: number, offset = 0): { position: Vec3; normal: Vec3 } {
  if (surface.kind === 'plane') {
    return { position: [x * grid.texelX, y * grid.texelY, offset], normal: [0, 0, 1] };
  }
  const angle = (2 * Math.PI * x) / grid.width;
  const c = Math.cos(angle);
  const s = Math.sin(angle);
  const radius = surface.radius + offset;
  return { position: [radius * c, radius * s, y * grid.texelY], normal: [c, s, 0] };
}

/**
 * embed's positions and the surface coordinates (µm along the unrolled domain) of many points at
 * once (interleaved x, y texel units), into columns: (x, y, z) at 3i, (u, v) at 2i; the same
 * arithmetic, no object per point.
 */
export function embedAll(
  surface: SurfaceConfig,
  grid: Grid,
  points: ArrayLike<number>,
  offset: number,
  position: Float64Array,
  coordinates: Float64Array,
): void {
  const n = Math.floor(points.length / 2);
  for (let i = 0; i < n; i++) {
    const x = points[2 * i];
    const y = points[2 * i + 1];
    if (surface.kind === 'plane') {
      position[3 * i] = x * grid.texelX;
      position[3 * i + 1] = y * grid.texelY;
      position[3 * i + 2] = offset;
    } else {
      const angle = (2 * Math.PI * x) / grid.width;
      const radius = surface.radius + offset;
      position[3 * i] = radius * Math.cos(angle);
      position[3 * i + 1] = radius * Math.sin(angle);
      position[3 * i + 2] = y * grid.texelY;
    }
    coordinates[2 * i] = x * grid.texelX;
    coordinates[2 * i + 1] = y * grid.texelY;
  }
}
