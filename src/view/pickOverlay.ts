/**
 * The picked cell in the 3D view of a plane or tube (issue 27): its exact outline (cellOutline.ts)
 * as a small white mesh with a dark border laid on each surface, instead of repainting every
 * surface's picture (seconds at 100,000 cells). The surfaces are flat facets (a tube is a 128-gon:
 * surfaceGeometry.ts) whose texture coordinates are linear on each facet, so the outline is cut
 * at facet edges and each piece placed on its facet's plane: it covers exactly the texels of the
 * cell in the picture below it.
 */
import * as THREE from 'three';
import type { PlanarConfig, SurfaceConfig } from '../core/config';
import type { Grid } from '../core/grid';
import { embed } from '../core/surface';
import { surfaceSegments } from './surfaceGeometry';
import { cellOutline, outlineCells } from './cellOutline';
import { clipHalfPlane } from './cellSolidSection';
import type { ViewStack, ViewSurface } from './stack';

/** The part of convex `polygon` (x, y pairs) with a <= x <= b. */
function clipStrip(polygon: readonly number[], a: number, b: number): number[] {
  const out = clipHalfPlane(clipHalfPlane(Float64Array.from(polygon), -1, 0, -a), 1, 0, b);
  return out.length >= 6 ? Array.from(out) : [];
}

/**
 * `polygon` (texel units, unwrapped) cut into pieces that each lie on one facet, `segments`
 * facets across `width` texels; on a periodic axis each piece is moved into [0, width].
 * `facet` is the facet index of each piece.
 */
export function facetPieces(polygon: ArrayLike<number>, width: number, segments: number, periodic: boolean): { facet: number; polygon: number[] }[] {
  const points = Array.from(polygon);
  if (points.length < 6) return [];
  const step = width / segments;
  let minX = Infinity;
  let maxX = -Infinity;
  for (let k = 0; k < points.length; k += 2) {
    minX = Math.min(minX, points[k]);
    maxX = Math.max(maxX, points[k]);
  }
  const pieces: { facet: number; polygon: number[] }[] = [];
  for (let i = Math.floor(minX / step); i * step < maxX; i++) {
    const piece = clipStrip(points, i * step, (i + 1) * step);
    if (piece.length === 0) continue;
    const wraps = periodic ? Math.floor(i / segments) : 0;
    if (!periodic && (i < 0 || i >= segments)) continue;
    for (let k = 0; k < piece.length; k += 2) piece[k] -= wraps * width;
    pieces.push({ facet: i - wraps * segments, polygon: piece });
  }
  return pieces;
}

/**
 * Segment (x0, y0)-(x1, y1) cut where it crosses facet edges (multiples of `step`): each part
 * with its facet, moved into [0, width] on a periodic axis.
 */
export function splitEdge(
  x0: number,
  y0: number,
  x1: number,
  y1: number,
  step: number,
  segments: number,
  periodic: boolean,
): [number, number, number, number, number][] {
  const cuts = [0, 1];
  if (x1 !== x0) {
    const lo = Math.min(x0, x1);
    const hi = Math.max(x0, x1);
    for (let i = Math.floor(lo / step) + 1; i * step < hi; i++) cuts.push((i * step - x0) / (x1 - x0));
  }
  cuts.sort((a, b) => a - b);
  const parts: [number, number, number, number, number][] = [];
  for (let k = 0; k + 1 < cuts.length; k++) {
    const [ta, tb] = [cuts[k], cuts[k + 1]];
    if (tb - ta <= 0) continue;
    const xa = x0 + ta * (x1 - x0);
    const xb = x0 + tb * (x1 - x0);
    const i = Math.floor((xa + xb) / 2 / step);
    const wraps = periodic ? Math.floor(i / segments) : 0;
    if (!periodic && (i < 0 || i >= segments)) continue;
    const shift = wraps * segments * step;
    parts.push([i - wraps * segments, xa - shift, y0 + ta * (y1 - y0), xb - shift, y0 + tb * (y1 - y0)]);
  }
  return parts;
}

/** Triangles (fan per piece) and border segments of the outline, as 3D positions on the surface. */
export function outlinePositions(
  surface: SurfaceConfig,
  grid: Grid,
  offset: number,
  polygon: ArrayLike<number>,
): { triangles: Float32Array; border: Float32Array } {
  const segments = surfaceSegments(surface);
  const step = grid.width / segments;
  const corner = (i: number, y: number) => embed(surface, grid, i * step, y, offset).position;
  // Linear on facet i: the same interpolation the facet's texture coordinates get.
  const place = (facet: number, x: number, y: number, out: number[]) => {
    const t = (x - facet * step) / step;
    const a = corner(facet, y);
    const b = corner(facet + 1, y);
    out.push(a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]), a[2] + t * (b[2] - a[2]));
  };
  const triangles: number[] = [];
  const border: number[] = [];
  const pieces = facetPieces(polygon, grid.width, segments, grid.periodicX);
  for (const { facet, polygon: p } of pieces) {
    const n = p.length / 2;
    for (let k = 1; k + 1 < n; k++) {
      place(facet, p[0], p[1], triangles);
      place(facet, p[2 * k], p[2 * k + 1], triangles);
      place(facet, p[2 * k + 2], p[2 * k + 3], triangles);
    }
  }
  // The border: the outline's own edges (not the cuts at facet edges), each split at facet edges.
  for (let k = 0; k < polygon.length; k += 2) {
    const next = (k + 2) % polygon.length;
    for (const [facet, x0, y0, x1, y1] of splitEdge(polygon[k], polygon[k + 1], polygon[next], polygon[next + 1], step, segments, grid.periodicX)) {
      place(facet, x0, y0, border);
      place(facet, x1, y1, border);
    }
  }
  return { triangles: new Float32Array(triangles), border: new Float32Array(border) };
}

/** The outline's fill and border materials; one pair per view, kept (their shader programs too). */
export interface OutlineMaterials {
  readonly fill: THREE.MeshBasicMaterial;
  readonly line: THREE.LineBasicMaterial;
}

/** Materials of outlines cut by `clip` (the view's cut). */
export function outlineMaterials(clip: THREE.Plane): OutlineMaterials {
  return {
    // White, pulled towards the camera: drawn over the picture it lies on.
    fill: new THREE.MeshBasicMaterial({
      color: 0xffffff,
      side: THREE.DoubleSide,
      polygonOffset: true,
      polygonOffsetFactor: -2,
      polygonOffsetUnits: -8,
      clippingPlanes: [clip],
    }),
    line: new THREE.LineBasicMaterial({ color: 0x141414, clippingPlanes: [clip] }),
  };
}

/** The picked cell's overlay on one surface; added to the surface's mesh. */
export function outlineObject(positions: { triangles: Float32Array; border: Float32Array }, materials: OutlineMaterials): THREE.Group {
  const group = new THREE.Group();
  group.name = 'picked-cell';
  const fill = new THREE.BufferGeometry();
  fill.setAttribute('position', new THREE.BufferAttribute(positions.triangles, 3));
  const line = new THREE.BufferGeometry();
  line.setAttribute('position', new THREE.BufferAttribute(positions.border, 3));
  group.add(new THREE.Mesh(fill, materials.fill), new THREE.LineSegments(line, materials.line));
  // Drawn after the surface it lies on, before the cell's solid (cellSolidMesh.ts, 1000). Not on
  // the group itself: three.js sorts a Group's children by its renderOrder first (groupOrder), so
  // a group at 1 would be drawn after the solid, hiding it.
  for (const child of group.children) child.renderOrder = 1;
  return group;
}

/** Frees an overlay's geometries (its materials are the view's). */
export function disposeOutline(group: THREE.Object3D): void {
  group.traverse((o) => (o as THREE.Mesh).geometry?.dispose());
}

/** Cell `id`'s overlay on a plane's or tube's `surface` of `stack`, or null (none picked, or no such cell). */
export function surfaceOutline(stack: ViewStack, surface: ViewSurface, id: number, materials: OutlineMaterials): THREE.Group | null {
  if (id < 0 || id >= surface.cells.length || stack.closed) return null;
  const { grid } = surface.image;
  const polygon = cellOutline(grid, outlineCells(surface.cells), id);
  if (polygon.length < 6) return null;
  return outlineObject(outlinePositions((stack.result.config as PlanarConfig).surface, grid, surface.offset, polygon), materials);
}
