/**
 * The exact cells of a planar surface of the stack (plane or tube), computed from the cells'
 * sites on that surface with core/exact.ts (Delaunay, periodic copies around a tube, clipped at
 * open edges): the polygons the PLY, VTK and SVG exports and the smooth 3D borders are made of.
 * Exact whatever engine ran: the label images only approximate these polygons by texels.
 */
import { exactVoronoi, type ExactVoronoi } from '../core/exact';
import type { ViewSurface } from './stack';

/**
 * Kept by the surface's cell list and grid: a stack made again for the same result (a new
 * headline, or each export in the worker holding an opened result: exportFiles.ts) reuses them.
 */
const cache = new WeakMap<object, { grid: ViewSurface['image']['grid']; voronoi: ExactVoronoi }>();

/** Exact Voronoi cells of `surface`'s sites, polygons in texel units (cached per cell list and grid). */
export function surfacePolygons(surface: ViewSurface): ExactVoronoi {
  const { grid } = surface.image;
  const known = cache.get(surface.cells);
  if (known && sameGrid(known.grid, grid)) return known.voronoi;
  const sites = new Float64Array(surface.cells.length * 2);
  surface.cells.forEach((cell, i) => {
    sites[2 * i] = cell.surface[0] / grid.texelX;
    sites[2 * i + 1] = cell.surface[1] / grid.texelY;
  });
  const voronoi = exactVoronoi(grid, sites);
  cache.set(surface.cells, { grid, voronoi });
  return voronoi;
}

function sameGrid(a: ViewSurface['image']['grid'], b: ViewSurface['image']['grid']): boolean {
  return a === b || JSON.stringify(a) === JSON.stringify(b);
}
