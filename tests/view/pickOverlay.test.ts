import { describe, expect, it } from 'vitest';
import type { SurfaceConfig } from '../../src/core/config';
import type { Grid } from '../../src/core/grid';
import { facetPieces, outlinePositions, splitEdge } from '../../src/view/pickOverlay';

const area = (p: readonly number[]) => {
  let sum = 0;
  for (let k = 0; k < p.length; k += 2) sum += p[k] * p[(k + 3) % p.length] - p[(k + 2) % p.length] * p[k + 1];
  return Math.abs(sum) / 2;
};
// A hexagon straddling the seam of a 100-texel periodic axis cut in 10 facets.
const HEX = Array.from({ length: 6 }, (_, k) => [-3 + 14 * Math.cos((k * Math.PI) / 3), 50 + 14 * Math.sin((k * Math.PI) / 3)]).flat();

describe('pickOverlay (the picked cell laid on the facets of the 3D view)', () => {
  it('facet pieces keep the area, each lies on its facet, and wrap into the surface', () => {
    const pieces = facetPieces(HEX, 100, 10, true);
    expect(pieces.reduce((s, p) => s + area(p.polygon), 0)).toBeCloseTo(area(HEX), 9);
    for (const { facet, polygon } of pieces) {
      expect(facet).toBeGreaterThanOrEqual(0);
      expect(facet).toBeLessThan(10);
      for (let k = 0; k < polygon.length; k += 2) {
        expect(polygon[k]).toBeGreaterThanOrEqual(facet * 10 - 1e-9);
        expect(polygon[k]).toBeLessThanOrEqual(facet * 10 + 10 + 1e-9);
      }
    }
    // Facets 8, 9 (left of the seam, wrapped) and 0, 1.
    expect(pieces.map((p) => p.facet).sort((a, b) => a - b)).toEqual([0, 1, 8, 9]);
  });

  it('a plane keeps only what lies on it', () => {
    const pieces = facetPieces(HEX, 100, 1, false);
    expect(pieces).toHaveLength(1);
    expect(area(pieces[0].polygon)).toBeLessThan(area(HEX));
    expect(area(pieces[0].polygon)).toBeGreaterThan(0);
  });

  it('an edge is split where it crosses facet edges, and its parts join up', () => {
    const parts = splitEdge(-12, 0, 25, 37, 10, 10, true);
    expect(parts.map((p) => p[0])).toEqual([8, 9, 0, 1, 2]);
    const length = parts.reduce((s, [, x0, y0, x1, y1]) => s + Math.hypot(x1 - x0, y1 - y0), 0);
    expect(length).toBeCloseTo(Math.hypot(37, 37), 9);
  });

  it('on a tube every vertex lies on its facet (between the facet corners) at the right height', () => {
    const grid: Grid = { width: 100, height: 100, texelX: 2, texelY: 3, periodicX: true, periodicY: false };
    const surface = { kind: 'tube', radius: 50, length: 300 } as SurfaceConfig;
    const { triangles, border } = outlinePositions(surface, grid, 5, HEX);
    expect(triangles.length % 9).toBe(0);
    expect(border.length % 6).toBe(0);
    // The 128-gon's facet chords lie at least r cos(pi / 128) from the axis, at most r.
    for (const points of [triangles, border]) {
      for (let k = 0; k < points.length; k += 3) {
        const r = Math.hypot(points[k], points[k + 1]);
        expect(r).toBeLessThanOrEqual(55 + 1e-4);
        expect(r).toBeGreaterThanOrEqual(55 * Math.cos(Math.PI / 128) - 1e-4);
        expect(points[k + 2]).toBeGreaterThanOrEqual((50 - 14) * 3 - 1e-4);
        expect(points[k + 2]).toBeLessThanOrEqual((50 + 14) * 3 + 1e-4);
      }
    }
  });
});
