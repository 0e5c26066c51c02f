/**
 * The sheet as a legacy VTK file (ASCII, DATASET POLYDATA), which ParaView and VisIt open: one
 * polygon per cell per surface, with CELL_DATA arrays cell_id, surface (0 = seeded), sides (on
 * that surface, from the analysis shown), scutoid and valid. Planes and tubes: the exact cells
 * (cellPolygons.ts) placed in 3D with the engine's embedding. Closed surfaces: each surface as
 * the 3D view's triangle mesh (a vertex per texel of the cube-map geometry image); a triangle
 * belongs to the cell most of its three texels belong to (the first texel's on a three-way tie).
 *
 * The legacy header line holds at most 256 characters: it carries the version, seed and method;
 * the full configuration is in the result JSON, the CSV and the project file.
 */
import { embed } from '../../core/surface';
import type { PlanarConfig } from '../../core/config';
import { closedSurfaceMesh } from '../../view/cubeAtlasMesh';
import type { ViewStack } from '../../view/stack';
import { surfacePolygons } from '../../view/cellPolygons';

/** Polygons with one record per polygon (VTK cells). */
interface SheetPolygons {
  /** x, y, z per point, µm. */
  points: number[];
  /** Point indices per polygon. */
  polygons: number[][];
  cellId: number[];
  surface: number[];
  sides: number[];
  scutoid: number[];
  valid: number[];
}

function sheetPolygons(stack: ViewStack): SheetPolygons {
  const out: SheetPolygons = { points: [], polygons: [], cellId: [], surface: [], sides: [], scutoid: [], valid: [] };
  const closed = stack.closed;
  const push = (id: number, surfaceIndex: number, sides: number, corners: number[]) => {
    out.polygons.push(corners);
    out.cellId.push(id);
    out.surface.push(surfaceIndex);
    out.sides.push(sides);
    out.scutoid.push(stack.scutoid[id] ?? 0);
    out.valid.push(stack.valid[id] ?? 0);
  };
  for (const surface of stack.surfaces) {
    if (closed) {
      const mesh = closedSurfaceMesh(surface.image);
      const first = out.points.length / 3;
      for (let k = 0; k < mesh.positions.length; k++) out.points.push(mesh.positions[k]);
      const t = mesh.indices;
      for (let f = 0; f < t.length; f += 3) {
        const [a, b, c] = [mesh.cells[t[f]], mesh.cells[t[f + 1]], mesh.cells[t[f + 2]]];
        const id = b === c ? b : a;
        if (id < 0) continue;
        push(id, surface.index, surface.sides[id] ?? 0, [first + t[f], first + t[f + 1], first + t[f + 2]]);
      }
      continue;
    }
    const { grid } = surface.image;
    for (const cell of surfacePolygons(surface).cells) {
      const polygon = cell.polygon;
      const count = polygon.length / 2;
      if (count < 3) continue;
      const first = out.points.length / 3;
      for (let k = 0; k < count; k++) {
        const { position } = embed((stack.result.config as PlanarConfig).surface, grid, polygon[2 * k], polygon[2 * k + 1], surface.offset);
        out.points.push(...position);
      }
      push(
        cell.id,
        surface.index,
        surface.sides[cell.id],
        Array.from({ length: count }, (_, k) => first + k),
      );
    }
  }
  return out;
}

export function cellsVtk(stack: ViewStack): string {
  const { result } = stack;
  const mesh = sheetPolygons(stack);
  const method = stack.analysis?.method ?? 'none';
  const h = result.headline;
  const headline =
    h && h.percentScutoids !== null
      ? `, ${h.percentScutoids.toFixed(1)} % scutoids${h.realizations > 1 && h.ci95 ? ` (mean n=${h.realizations}, 95% CI ${h.ci95[0].toFixed(1)}-${h.ci95[1].toFixed(1)})` : ' (one realization)'}`
      : '';
  const title = `tissue-sheet ${result.software.version} cells, seed ${result.seed}, ${result.config.surface.kind}, ${result.engine.name} engine, ${method} adjacency${headline}, um`;
  const lines = ['# vtk DataFile Version 3.0', title.replace(/[\r\n]/g, ' ').slice(0, 255), 'ASCII', 'DATASET POLYDATA'];
  const pointCount = mesh.points.length / 3;
  lines.push(`POINTS ${pointCount} float`);
  for (let p = 0; p < pointCount; p++) lines.push(`${fmt(mesh.points[3 * p])} ${fmt(mesh.points[3 * p + 1])} ${fmt(mesh.points[3 * p + 2])}`);
  const size = mesh.polygons.reduce((n, poly) => n + poly.length + 1, 0);
  lines.push(`POLYGONS ${mesh.polygons.length} ${size}`);
  for (const poly of mesh.polygons) lines.push(`${poly.length} ${poly.join(' ')}`);
  lines.push(`CELL_DATA ${mesh.polygons.length}`);
  const arrays: [string, number[]][] = [
    ['cell_id', mesh.cellId],
    ['surface', mesh.surface],
    ['sides', mesh.sides],
    ['scutoid', mesh.scutoid],
    ['valid', mesh.valid],
  ];
  for (const [name, values] of arrays) {
    lines.push(`SCALARS ${name} int 1`, 'LOOKUP_TABLE default');
    // Short lines: some readers limit the line length.
    for (let k = 0; k < values.length; k += 20) lines.push(values.slice(k, k + 20).join(' '));
  }
  return `${lines.join('\n')}\n`;
}

function fmt(value: number): string {
  return Number.isInteger(value) ? String(value) : value.toFixed(4);
}
