import { describe, expect, it } from 'vitest';
import { validateConfig, type ConfigInput, type PlanarConfig } from '../../src/core/config';
import { makeGrid } from '../../src/core/config';
import { surfaceStack } from '../../src/core/sheetGeometry';

/**
 * A tube's stack to surface ratio s ends on the very surface that a stack to a larger ratio has
 * as its layer at s (the lab protocol's validity layers, laid out to validityMaxRatio, serve every
 * ratio of a sweep with one exact diagram each, memoised by grid): the same offset and grid, bit
 * for bit, outward and inward.
 */
const tube = (surfaceRatio: number, direction: 'outward' | 'inward', radius: number): PlanarConfig =>
  validateConfig({
    surface: { kind: 'tube', radius, length: 4096 },
    resolution: 512,
    cells: 200,
    sheet: { surfaceRatio, direction, layerStep: 0.25 },
  } satisfies ConfigInput) as PlanarConfig;

describe('surfaceStack of a tube', () => {
  for (const direction of ['outward', 'inward'] as const) {
    for (const radius of [81.48733086305042, 17.3, 250.123456789]) {
      it(`the other surface at s is the layer at s of a stack to s = 10 (${direction}, R = ${radius})`, () => {
        const longest = tube(10, direction, radius);
        const seeded = makeGrid(longest);
        const layers = surfaceStack(longest, seeded);
        for (let k = 1; k < layers.length; k++) {
          const s = 1 + 0.25 * k;
          const stack = surfaceStack(tube(s, direction, radius), seeded);
          const other = stack[stack.length - 1];
          expect(other.offset, `s = ${s}`).toBe(layers[k].offset);
          expect(other.grid, `s = ${s}`).toEqual(layers[k].grid);
          // Every layer of the shorter stack is the longer stack's layer with the same index.
          stack.forEach((surface, j) => expect(surface.grid, `s = ${s}, layer ${j}`).toEqual(layers[j].grid));
        }
      });
    }
  }
});
