/** Parameter sweeps: spec validation, expansion, columns, tidy CSV, resume, aggregation, loop. */
export * from './spec';
export * from './expand';
export * from './columns';
export * from './csv';
export * from './resume';
export * from './aggregate';
export * from './rows';
export * from './runner';
export * from './shard';
export * from './flintstones';
export * from './units';
