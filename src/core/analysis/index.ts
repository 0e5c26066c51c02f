/** Analysis of Voronoi sheets: adjacency, scutoid statistics, the tube model. */
export * from './adjacency';
export * from './scutoids';
export * from './tubeModel';
