import type { SurfaceAdjacency } from '../core/analysis';
import type { ClosedConfig } from '../core/config';
import { offsetClosedSurface, type OffsetMode } from '../core/closed/closedOffset';
import type { ClosedSites } from '../core/closed/geometry';
import { restrictedVoronoi } from '../core/closed/restrictedVoronoi';
import { sphereSurface, triangleNeighbours, type RestrictedSurface } from '../core/closed/restrictedSurface';
import type { ClosedSurface } from './closedSurface';

/** The seeded surface as the restricted Voronoi diagram sees it, built once per prepared surface. */
const bases = new WeakMap<ClosedSurface, RestrictedSurface>();

/**
 * The exact method on a closed surface: the restricted Voronoi diagram of the sites on the
 * surface at `offset` (Yan, Lévy et al. 2009, as geogram computes it): the analytic sphere or
 * ellipsoid, or the mesh's triangles, clipped by the bisector planes of the sites, with true
 * contact lengths in µm (src/core/closed/restrictedVoronoi.ts). Offset surfaces are made as
 * the GPU labels them: the parallel surface with the sites moved along their normals ("normal"),
 * or the ellipsoid with grown semi-axes and the sites' closest points on it ("axes").
 */
export function closedExactAdjacency(
  config: ClosedConfig,
  surface: ClosedSurface,
  sites: ClosedSites,
  offset: number,
  mode: OffsetMode,
  label: string,
): SurfaceAdjacency {
  const base = baseSurface(config, surface);
  const layer = offset === 0 ? { surface: base, sites: sites.positions } : offsetClosedSurface(base, sites.positions, sites.normals, sites.count, offset, mode);
  const rvd = restrictedVoronoi(layer.surface, layer.sites, sites.count);
  return { ...rvd.adjacency, label };
}

function baseSurface(config: ClosedConfig, surface: ClosedSurface): RestrictedSurface {
  let base = bases.get(surface);
  if (!base) {
    const kind = config.surface;
    if (kind.kind === 'sphere') base = sphereSurface(kind.radius);
    else if (kind.kind === 'ellipsoid') base = { kind: 'ellipsoid', a: kind.a, b: kind.b, c: kind.c };
    else {
      const mesh = surface.mesh!.mesh;
      base = {
        kind: 'mesh',
        positions: mesh.positions,
        indices: mesh.indices,
        triangleNeighbours: triangleNeighbours(mesh.indices, mesh.positions.length / 3),
      };
    }
    bases.set(surface, base);
  }
  return base;
}
