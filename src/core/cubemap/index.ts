/** Cube-map geometry images for closed surfaces: texel math (cubemap.ts) and sampling (sample.ts). */
export * from './cubemap';
export * from './sample';
