/** Analysis of Voronoi sheets: adjacency and scutoid statistics. */
export * from './adjacency';
export * from './scutoids';
