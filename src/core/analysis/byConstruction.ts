/**
 * Results that are fixed by the geometry, whatever the sites: the rule behind the page's and the
 * element's "0 % by construction, because ..." message, so a biologist never reads a 0 as a
 * finding.
 *
 * A cell is a scutoid when its neighbour set differs between surfaces. The other surfaces get the
 * seeded sites projected along the normal; when every surface of the stack is the seeded one up
 * to a uniform scale (or a translation), the projected sites have the same Voronoi diagram on
 * each, so no neighbour can change and % scutoids is 0 by construction:
 * - thickness 0 (and, on a tube, no surface ratio or s = 1): the surfaces coincide;
 * - a plane: the other surface is a parallel copy, every site keeps its (x, y);
 * - a sphere (or an ellipsoid with a = b = c): the offset surfaces are concentric spheres and the
 *   spherical Voronoi diagram only scales.
 * A result with no valid cell (every cell touches an open end of a tube or plane) has no
 * percentage at all; `noValidCells` says so.
 */
import type { Config } from '../config/types';

export interface ByConstruction {
  /** The value fixed by the geometry (0: no neighbour can change). */
  readonly percent: 0;
  /** Short name of the case, for tests and data attributes. */
  readonly reason: 'coincident' | 'surface-ratio-1' | 'parallel-planes' | 'concentric-spheres';
  /** One sentence for people: why the value is what it is, and what to change. */
  readonly message: string;
}

/** Relative tolerance under which two semi-axes count as equal. */
const SAME_AXIS = 1e-9;

/** Why % scutoids of `config` is 0 whatever the sites, or null when it depends on them. */
export function byConstruction(config: Config): ByConstruction | null {
  const surface = config.surface;
  const sheet = config.sheet as { thickness: number; surfaceRatio?: number | null };
  const ratio = surface.kind === 'tube' ? (sheet.surfaceRatio ?? null) : null;
  if (ratio === 1) {
    return {
      percent: 0,
      reason: 'surface-ratio-1',
      message:
        'Surface ratio s = 1: both surfaces are the same cylinder, so every cell keeps its neighbours and % scutoids is 0 by construction. Raise s above 1.',
    };
  }
  const isSphere = surface.kind === 'sphere' || (surface.kind === 'ellipsoid' && sameLength(surface.a, surface.b) && sameLength(surface.b, surface.c));
  if (ratio === null && sheet.thickness === 0) {
    // What to change: a thickness, except where the geometry keeps 0 at any thickness.
    const hint =
      surface.kind === 'plane'
        ? 'A thickness alone would not help: parallel planes give 0 at any thickness; curvature makes scutoids: try a tube, an ellipsoid or a mesh.'
        : isSphere
          ? 'A thickness alone would not help: concentric spheres give 0 at any thickness; try an ellipsoid or a mesh with a thickness.'
          : `Give the sheet a thickness${surface.kind === 'tube' ? ' (or a surface ratio above 1)' : ''}.`;
    return {
      percent: 0,
      reason: 'coincident',
      message: `Thickness 0: the basal and apical surfaces coincide, so every cell keeps its neighbours and % scutoids is 0 by construction. ${hint}`,
    };
  }
  if (surface.kind === 'plane') {
    return {
      percent: 0,
      reason: 'parallel-planes',
      message:
        'Parallel planes: each site keeps its position on the other plane, so the Voronoi diagrams are identical and % scutoids is 0 by construction. Curvature makes scutoids: try a tube, an ellipsoid or a mesh.',
    };
  }
  if (isSphere) {
    return {
      percent: 0,
      reason: 'concentric-spheres',
      message:
        'Concentric spheres: projecting along the radius only scales the spherical Voronoi diagram, so every cell keeps its neighbours and % scutoids is 0 by construction. Try an ellipsoid or a mesh.',
    };
  }
  return null;
}

/** The message for a result with no valid cell, or null when some cell was counted. */
export function noValidCells(validCells: number, cells: number): string | null {
  if (validCells > 0) return null;
  return `None of the ${cells} cells was counted: every cell touches an open end of the sheet, so there is no % scutoids. Add cells or make the sheet longer.`;
}

function sameLength(x: number, y: number): boolean {
  return Math.abs(x - y) <= SAME_AXIS * Math.max(Math.abs(x), Math.abs(y));
}
