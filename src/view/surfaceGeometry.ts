/**
 * Triangle meshes of the sheet's surfaces for the 3D view, placed with the engine's own
 * embedding (src/core/surface.ts `embed`), so the view and the result's 3D positions agree.
 * UV (0..1, 0..1) maps to the unrolled domain, texture row 0 = y 0.
 *
 * Closed surfaces (sphere, ellipsoid, meshes) will add their own builder here.
 */
import * as THREE from 'three';
import type { SurfaceConfig } from '../core/config';
import type { Grid } from '../core/grid';
import { embed } from '../core/surface';

/** Flat facets around the surface (a tube's circle as a 128-gon; a plane is one facet). */
export function surfaceSegments(surface: SurfaceConfig): number {
  return surface.kind === 'tube' ? 128 : 1;
}

export function surfaceGeometry(surface: SurfaceConfig, grid: Grid, offset: number): THREE.BufferGeometry {
  const segmentsX = surfaceSegments(surface);
  const segmentsY = 1;
  const positions: number[] = [];
  const uvs: number[] = [];
  const indices: number[] = [];
  for (let j = 0; j <= segmentsY; j++) {
    for (let i = 0; i <= segmentsX; i++) {
      const u = i / segmentsX;
      const v = j / segmentsY;
      const { position } = embed(surface, grid, u * grid.width, v * grid.height, offset);
      positions.push(...position);
      uvs.push(u, v);
    }
  }
  const row = segmentsX + 1;
  for (let j = 0; j < segmentsY; j++) {
    for (let i = 0; i < segmentsX; i++) {
      const a = j * row + i;
      indices.push(a, a + 1, a + row, a + 1, a + row + 1, a + row);
    }
  }
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.Float32BufferAttribute(positions, 3));
  geometry.setAttribute('uv', new THREE.Float32BufferAttribute(uvs, 2));
  geometry.setIndex(indices);
  return geometry;
}
