/** Pure-geometry mesh toolkit (runs in Node): reading, checking, parameterizing, geodesics. */
export * from './types';
export * from './parse';
export * from './check';
export * from './write';
export * from './generate';
export * from './sparse';
export * from './heat';
export * from './spherical';
