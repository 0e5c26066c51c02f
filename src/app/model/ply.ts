/**
 * The cells as a mesh: an ASCII PLY with one polygon per cell per surface. Cell polygons are
 * the exact Voronoi cells (d3-delaunay, periodic copies around a tube) of the sites on each
 * surface, placed in 3D with the engine's embedding; each polygon has its own vertices, which
 * carry the cell's data: id, surface index, sides on that surface (from the analysis shown),
 * scutoid and valid flags.
 *
 * Closed surfaces (sphere, ellipsoid, mesh): every surface of the stack as the triangle mesh the
 * 3D view draws (a vertex per texel of its cube-map geometry image), each vertex carrying the
 * data of its texel's cell.
 */
import { surfacePolygons } from '../../view/cellPolygons';
import { embed } from '../../core/surface';
import type { PlanarConfig } from '../../core/config';
import { closedSurfaceMesh } from '../../view/cubeAtlasMesh';
import { provenanceLines } from './cellRows';
import type { ViewStack } from '../../view/stack';
import type { CellSolid } from '../../view/cellSolid';

export function cellsPly(stack: ViewStack): string {
  if (stack.closed) return closedCellsPly(stack);
  // A stack that is not closed is unrolled: a plane's or a tube's config.
  const config = stack.result.config as PlanarConfig;
  const vertices: string[] = [];
  const faces: string[] = [];
  for (const surface of stack.surfaces) {
    const { grid } = surface.image;
    const voronoi = surfacePolygons(surface);
    for (const cell of voronoi.cells) {
      const polygon = cell.polygon;
      const count = polygon.length / 2;
      if (count < 3) continue;
      const first = vertices.length;
      const data = `${cell.id} ${surface.index} ${surface.sides[cell.id]} ${stack.scutoid[cell.id]} ${stack.valid[cell.id]}`;
      for (let k = 0; k < count; k++) {
        const { position } = embed(config.surface, grid, polygon[2 * k], polygon[2 * k + 1], surface.offset);
        vertices.push(`${position.map((v) => v.toFixed(4)).join(' ')} ${data}`);
      }
      faces.push(`${count} ${Array.from({ length: count }, (_, k) => first + k).join(' ')}`);
    }
  }
  return plyDocument(stack, 'cells of every surface (0 = seeded), µm', vertices, faces);
}

function closedCellsPly(stack: ViewStack): string {
  const vertices: string[] = [];
  const faces: string[] = [];
  for (const surface of stack.surfaces) {
    const mesh = closedSurfaceMesh(surface.image);
    const first = vertices.length;
    for (let v = 0; v < mesh.cells.length; v++) {
      const id = mesh.cells[v];
      const p = [mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]];
      vertices.push(
        `${p.map((x) => x.toFixed(4)).join(' ')} ${id} ${surface.index} ${surface.sides[id] ?? 0} ${stack.scutoid[id] ?? 0} ${stack.valid[id] ?? 0}`,
      );
    }
    const t = mesh.indices;
    for (let f = 0; f < t.length; f += 3) faces.push(`3 ${first + t[f]} ${first + t[f + 1]} ${first + t[f + 2]}`);
  }
  return plyDocument(
    stack,
    'closed surfaces (0 = seeded) as triangle meshes, a vertex per texel of the cube-map geometry image labelled with its cell, µm',
    vertices,
    faces,
  );
}

/**
 * One cell's solid through the stack (src/view/cellSolid.ts) as a closed triangle mesh, µm in the
 * sheet's frame; each vertex carries the cell, the surface its ring lies on, the cell's sides
 * there and its flags, as in `cellsPly`.
 */
export function cellSolidPly(stack: ViewStack, solid: CellSolid): string {
  const id = solid.cell;
  const ringSize = solid.rays + 1;
  const vertices: string[] = [];
  for (let v = 0; v < solid.positions.length / 3; v++) {
    const surface = Math.floor(v / ringSize);
    const p = [0, 1, 2].map((c) => solid.positions[3 * v + c] + solid.origin[c]);
    const sides = stack.surfaces[surface]?.sides[id] ?? 0;
    vertices.push(`${p.map((x) => x.toFixed(4)).join(' ')} ${id} ${surface} ${sides} ${stack.scutoid[id] ?? 0} ${stack.valid[id] ?? 0}`);
  }
  const faces: string[] = [];
  const t = solid.indices;
  for (let f = 0; f < t.length; f += 3) faces.push(`3 ${t[f]} ${t[f + 1]} ${t[f + 2]}`);
  const how = solid.exact ? 'exact cross-sections' : 'traced restricted Voronoi cross-sections';
  return plyDocument(stack, `cell ${id} as a closed solid through the surfaces (${how}), outward triangles, µm`, vertices, faces);
}

function plyDocument(stack: ViewStack, comment: string, vertices: string[], faces: string[]): string {
  const header = [
    'ply',
    'format ascii 1.0',
    `comment tissue-sheet ${stack.result.software.version}: ${comment}`,
    // Provenance: one comment line each (PLY comments end at the line's end).
    ...provenanceLines(stack, 'tissue-sheet cells').map((line) => `comment ${line.replace(/[\r\n]+/g, ' ')}`),
    `element vertex ${vertices.length}`,
    'property float x',
    'property float y',
    'property float z',
    'property int cell',
    'property uchar surface',
    'property uchar sides',
    'property uchar scutoid',
    'property uchar valid',
    `element face ${faces.length}`,
    'property list uchar int vertex_indices',
    'end_header',
  ];
  return `${[...header, ...vertices, ...faces].join('\n')}\n`;
}
