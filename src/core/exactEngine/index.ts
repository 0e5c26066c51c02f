/** The exact CPU engine for planes and tubes: exact Voronoi Lloyd and exact surface adjacency. */
export { ExactLloydRun } from './exactLloyd';
export { exactDensity } from './cellIntegrals';
export { PlanarVoronoi } from './planarVoronoi';
export { exactSurface } from './exactSurface';
export { PolygonBuffer } from './polygon';
export { rasterizeCells } from './rasterize';
