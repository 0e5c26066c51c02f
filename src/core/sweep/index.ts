/** Parameter sweeps: expansion, tidy CSV, aggregation, resumable loop. */
export * from './expand';
export * from './csv';
export * from './aggregate';
export * from './runner';
