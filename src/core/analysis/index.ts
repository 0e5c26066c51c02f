/** Analysis of Voronoi sheets: adjacency and scutoid statistics. */
export * from './adjacency';
export * from './scutoids';
export * from './protocol';
export * from './protocolTube';
export * from './flintstones';
export * from './record';
export * from './headline';
export * from './byConstruction';
export * from './realizations';
