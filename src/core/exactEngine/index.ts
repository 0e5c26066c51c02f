/** The exact CPU engine for planes and tubes: exact Voronoi Lloyd and exact surface adjacency. */
export { ExactLloydRun, ExactCentroids, type ExactLloydOptions, type ExactIterationRecord } from './exactLloyd';
export { CellIntegrator, exactDensity, type ExactDensity } from './cellIntegrals';
export { PlanarVoronoi, EDGE_FAR, EDGE_X0, EDGE_X1, EDGE_Y0, EDGE_Y1 } from './planarVoronoi';
export { exactSurface } from './exactSurface';
export { PolygonBuffer, clipHalfPlane, polygonMoments } from './polygon';
export { rasterizeCells } from './rasterize';
