/**
 * One cell as a 3D solid through the stack [seeded, layers..., other]: the scutoid itself.
 * Pure geometry (no three.js, no DOM); `cellSolidMesh.ts` puts it in the 3D view.
 *
 * Construction. On every surface k the cell's cross-section is a convex polygon around the
 * cell's site there, written in a 2D frame tangent at the site (the same directions on every
 * surface). A common set of ray angles — a uniform set (64 rays) united with the angle
 * of every polygon corner on every surface — is traced from the site to each cross-section's
 * boundary, so each cross-section passes through its own polygon's corners exactly. Each traced
 * 2D point is then put on surface k in 3D. Consecutive surfaces are joined by two triangles per
 * pair of matching rays; the first and last surfaces are closed by fans from the site. The mesh is
 * closed and consistently oriented (outward normals, positive volume) whatever the neighbours
 * do between surfaces: every ring has the same number of vertices, only their positions change.
 *
 * - Planes and tubes: the cross-section is the exact Voronoi polygon (`cellPolygons.ts`, texel
 *   units of the surface's grid, unwrapped around the site across a tube's seam) in µm of the
 *   unrolled surface; a point goes to 3D with the view's own embedding (`core/surface.ts`
 *   `embed`: a cylinder of the surface's radius, a sheet at its offset). Exact cross-sections (a
 *   tube's flat cap triangles are chords of the cylinder). Border cells are the clipped polygons.
 * - Closed surfaces (sphere, ellipsoid, mesh): the cell on a surface is the restricted Voronoi
 *   cell (the surface ∩ the 3D Voronoi cell of the site among that surface's sites). The
 *   cross-section is traced, not exact: the 3D Voronoi cell cut by the site's tangent plane (a
 *   half-plane per nearby site), each traced point then put on the surface (sphere: radially,
 *   which keeps bisector planes through the centre, so corners and borders lie on the exact
 *   cell; ellipsoid and mesh: onto the plane fitted to the nearest texels of the surface's
 *   geometry image, `LabelImage.positions`).
 *
 * Positions are relative to `origin` (µm, float64) so float32 keeps sub-nanometre precision.
 */
import { embed } from '../core/surface';
import { wrapDelta } from '../core/grid';
import { signedVolume } from '../core/mesh/types';
import { surfacePolygons } from './cellPolygons';
import { closedSections } from './cellSolidClosed';
import { cross, sub, type Section, type Vec3 } from './cellSolidSection';
import type { ViewStack } from './stack';

interface CellSolidSection {
  /** Index of the surface in the stack. */
  readonly surface: number;
  /** Corners of the cell's polygon there (its sides, border edges included). */
  readonly corners: number;
  /** The traced outline: x, y per ray in the tangent frame (µm, relative to the site). */
  readonly outline: Float64Array;
  /** Index of the site's vertex; the ring's `rays` vertices follow it. */
  readonly centre: number;
}

export interface CellSolid {
  readonly cell: number;
  /** µm; positions are relative to it. */
  readonly origin: [number, number, number];
  /** xyz per vertex, µm relative to `origin`. */
  readonly positions: Float32Array;
  /** Counter-clockwise seen from outside. */
  readonly indices: Uint32Array;
  /** Area-weighted vertex normals, unit length. */
  readonly normals: Float32Array;
  /** Vertices per ring (the same on every surface). */
  readonly rays: number;
  readonly sections: CellSolidSection[];
  /** Planes and tubes: exact cross-sections; closed surfaces: traced. */
  readonly exact: boolean;
}

/** Uniform ray angles added to the corners' angles. */
const UNIFORM_RAYS = 64;

/** The solid of cell `id` through every surface of `stack`, or null when it has none. */
export function cellSolid(stack: ViewStack, id: number): CellSolid | null {
  if (stack.surfaces.length < 2 || id < 0 || id >= stack.result.cells.length) return null;
  const sections = stack.closed ? closedSections(stack, id) : planarSections(stack, id);
  if (!sections || sections.some((s) => s.polygon.length < 6)) return null;

  const angles = rayAngles(sections, UNIFORM_RAYS);
  const rays = angles.length;
  const ringSize = rays + 1;
  const origin: Vec3 = [...sections[0].centre];
  const positions = new Float32Array(sections.length * ringSize * 3);
  const outputSections: CellSolidSection[] = [];
  sections.forEach((section, k) => {
    const base = k * ringSize;
    const put = (v: number, p: Vec3) => {
      for (let c = 0; c < 3; c++) positions[3 * v + c] = p[c] - origin[c];
    };
    put(base, section.centre);
    const outline = new Float64Array(2 * rays);
    angles.forEach((angle, i) => {
      const dx = Math.cos(angle);
      const dy = Math.sin(angle);
      const t = rayExit(section.polygon, dx, dy);
      outline[2 * i] = t * dx;
      outline[2 * i + 1] = t * dy;
      put(base + 1 + i, section.toSpace(t * dx, t * dy));
    });
    outputSections.push({ surface: k, corners: section.polygon.length / 2, outline, centre: base });
  });

  const last = sections.length - 1;
  const triangles: number[] = [];
  const ring = (k: number, i: number) => k * ringSize + 1 + (i % rays);
  for (let i = 0; i < rays; i++) {
    triangles.push(0, ring(0, i + 1), ring(0, i));
    triangles.push(last * ringSize, ring(last, i), ring(last, i + 1));
    for (let k = 0; k < last; k++) {
      triangles.push(ring(k, i), ring(k, i + 1), ring(k + 1, i + 1));
      triangles.push(ring(k, i), ring(k + 1, i + 1), ring(k + 1, i));
    }
  }
  const indices = Uint32Array.from(triangles);
  if (signedVolume({ positions, indices }) < 0) {
    for (let t = 0; t < indices.length; t += 3) [indices[t + 1], indices[t + 2]] = [indices[t + 2], indices[t + 1]];
  }
  return {
    cell: id,
    origin,
    positions,
    indices,
    normals: vertexNormals(positions, indices),
    rays,
    sections: outputSections,
    exact: !stack.closed,
  };
}

/** Planes and tubes: each surface's exact polygon in µm of the unrolled surface, around the site. */
function planarSections(stack: ViewStack, id: number): Section[] | null {
  const config = stack.result.config;
  const sections: Section[] = [];
  for (const surface of stack.surfaces) {
    const cell = surface.cells[id];
    const exact = surfacePolygons(surface).cells[id];
    if (!cell || !exact) return null;
    const { grid } = surface.image;
    const sx = cell.surface[0] / grid.texelX;
    const sy = cell.surface[1] / grid.texelY;
    const polygon = new Float64Array(exact.polygon.length);
    for (let v = 0; v < exact.polygon.length; v += 2) {
      polygon[v] = wrapDelta(exact.polygon[v] - sx, grid.width, grid.periodicX) * grid.texelX;
      polygon[v + 1] = wrapDelta(exact.polygon[v + 1] - sy, grid.height, grid.periodicY) * grid.texelY;
    }
    const toSpace = (x: number, y: number): Vec3 => embed(config.surface as never, grid, sx + x / grid.texelX, sy + y / grid.texelY, surface.offset).position;
    sections.push({ polygon, centre: toSpace(0, 0), toSpace });
  }
  return sections;
}

/** Sorted, deduplicated ray angles in [-π, π): uniform ones and every polygon corner's. */
function rayAngles(sections: Section[], uniform: number): number[] {
  const angles: number[] = [];
  for (let i = 0; i < uniform; i++) angles.push(-Math.PI + (2 * Math.PI * i) / uniform);
  for (const { polygon } of sections) {
    for (let v = 0; v < polygon.length; v += 2) angles.push(Math.atan2(polygon[v + 1], polygon[v]));
  }
  angles.sort((a, b) => a - b);
  const out: number[] = [];
  for (const a of angles) if (out.length === 0 || a - out[out.length - 1] > 1e-9) out.push(a);
  if (out.length > 1 && out[0] + 2 * Math.PI - out[out.length - 1] <= 1e-9) out.pop();
  return out;
}

/** Distance from the origin to the boundary of a convex polygon around it, along (dx, dy). */
function rayExit(polygon: Float64Array, dx: number, dy: number): number {
  const n = polygon.length / 2;
  let best = Infinity;
  for (let i = 0; i < n; i++) {
    const ax = polygon[2 * i];
    const ay = polygon[2 * i + 1];
    const j = (i + 1) % n;
    const ex = polygon[2 * j] - ax;
    const ey = polygon[2 * j + 1] - ay;
    const denom = dx * ey - dy * ex;
    if (Math.abs(denom) < 1e-15) continue;
    const t = (ax * ey - ay * ex) / denom;
    const s = (ax * dy - ay * dx) / denom;
    if (t > 1e-12 && s >= -1e-9 && s <= 1 + 1e-9 && t < best) best = t;
  }
  return Number.isFinite(best) ? best : 0;
}

function vertexNormals(positions: Float32Array, indices: Uint32Array): Float32Array {
  const normals = new Float32Array(positions.length);
  const at = (v: number): Vec3 => [positions[3 * v], positions[3 * v + 1], positions[3 * v + 2]];
  for (let t = 0; t < indices.length; t += 3) {
    const [a, b, c] = [indices[t], indices[t + 1], indices[t + 2]];
    const n = cross(sub(at(b), at(a)), sub(at(c), at(a)));
    for (const v of [a, b, c]) for (let k = 0; k < 3; k++) normals[3 * v + k] += n[k];
  }
  for (let v = 0; v < normals.length; v += 3) {
    const length = Math.hypot(normals[v], normals[v + 1], normals[v + 2]) || 1;
    for (let k = 0; k < 3; k++) normals[v + k] /= length;
  }
  return normals;
}
