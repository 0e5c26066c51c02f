/**
 * The model of the same tissue, drawable (docs/measure.md, "The model of the same tissue"): one
 * realization of the best Voronoi k of a `compareVolume` comparison, its basal and apical surfaces
 * as triangles each in its model cell, with the cells' sides, neighbours, validity and scutoid
 * flags, for the page to draw beside the measured tissue. Not in the CLI's result (the page is
 * the consumer); everything is typed arrays, to be transferred.
 *
 * The realization is the first (seed `comparison.seed`), rebuilt from the comparison record
 * (seed, best k, minimum spacing, surface ratio) by the same steps compareVolume ran, so a saved
 * comparison (a project file) draws again without re-running the search; `matches` says
 * whether its statistics are the record's first realization's (they are, for the same volume).
 *
 * - Closed shell: the seeded (lumen-side) and other meshes of compareVolume; each cell drawn as
 *   its exact restricted Voronoi pieces (each piece, a convex polygon in one mesh triangle,
 *   fanned into triangles): a drawn triangle belongs to the site nearest every point of it.
 * - Open piece: the fitted tube in the volume's coordinates (its axis through its centre, the
 *   model's length centred there), each cell the exact Voronoi polygon of the unrolled surface
 *   (inner radius; the outer one scaled around by the ratio, as the model projects radially),
 *   fanned and subdivided so that the triangles follow the curvature.
 */
import { analyzeSurfaces, neighbourSet, type SurfaceAdjacency } from '../../analysis';
import { restrictedVoronoi } from '../../closed/restrictedVoronoi';
import { exactVoronoi } from '../../exact';
import type { Grid } from '../../grid';
import { placeSites } from '../../sites';
import { exactLloyd } from '../compare';
import { shellSetup, tubeGrid, type ShellMeshes, type VolumeComparison } from './compareVolume';
import { lloydStepOnMesh, randomSitesOnMesh } from './meshModel';
import type { TubeGeometry } from './tubeFit';
import type { VolumeMeasuredResult } from './volumeResult';

/** Drawn triangles per surface at most (the page's budget for the measured surfaces too). */
const MAX_MODEL_TRIANGLES = 300_000;

/** One of the model's surfaces, drawn. */
interface ModelSurfaceDrawing {
  readonly name: 'basal' | 'apical';
  readonly faces: 'outside' | 'lumen';
  /** x, y, z per vertex, three vertices per triangle (unshared), µm in the volume's coordinates. */
  readonly positions: Float32Array;
  /** Model cell (0-based) per triangle. */
  readonly cells: Int32Array;
  /** The cells' sites on this surface, x, y, z each (µm). */
  readonly sites: Float32Array;
  /** Sides per cell on this surface (the analysis's). */
  readonly sides: Int32Array;
  /** Neighbours per cell on this surface: cell i's are neighbours[offsets[i] .. offsets[i + 1]), ascending. */
  readonly offsets: Int32Array;
  readonly neighbours: Int32Array;
  /** µm: about a fifth of a cell across (the drawing's stripes and detail scale). */
  readonly spacing: number;
}

export interface VolumeModelDrawing {
  readonly kind: 'mesh' | 'tube';
  /** Which realization (0: the first) and its seed; the Voronoi k drawn (the best). */
  readonly realization: 0;
  readonly seed: number;
  readonly k: number;
  readonly cells: number;
  /** Per cell: 1 when valid (not on an open end of the tube). */
  readonly valid: Uint8Array;
  /** Per cell: 1 when a scutoid (valid, its neighbours differ between the surfaces). */
  readonly scutoid: Uint8Array;
  /** Basal, then apical. */
  readonly surfaces: [ModelSurfaceDrawing, ModelSurfaceDrawing];
  readonly percentScutoids: number;
  /** Whether this realization's % scutoids and mean transitions are the comparison's first realization's. */
  readonly matches: boolean;
}

/** Grows a Float32Array / Int32Array pair (triangles and their cells) without a number[] per value. */
class TriangleBuffer {
  positions = new Float32Array(9 * 1024);
  cells = new Int32Array(1024);
  count = 0;

  constructor(private readonly max: number) {}

  /** Appends triangle (a, b, c) of cell `cell`; false when over the budget. */
  add(cell: number, a: ArrayLike<number>, ao: number, b: ArrayLike<number>, bo: number, c: ArrayLike<number>, co: number): boolean {
    if (this.count >= this.max) return false;
    if (this.count === this.cells.length) {
      const positions = new Float32Array(2 * this.positions.length);
      positions.set(this.positions);
      this.positions = positions;
      const cells = new Int32Array(2 * this.cells.length);
      cells.set(this.cells);
      this.cells = cells;
    }
    const o = 9 * this.count;
    for (let k = 0; k < 3; k++) {
      this.positions[o + k] = a[ao + k];
      this.positions[o + 3 + k] = b[bo + k];
      this.positions[o + 6 + k] = c[co + k];
    }
    this.cells[this.count++] = cell;
    return true;
  }

  finish(): { positions: Float32Array; cells: Int32Array } {
    return { positions: this.positions.slice(0, 9 * this.count), cells: this.cells.slice(0, this.count) };
  }
}

/** The neighbour sets of a surface (neighbourSet's form) as one flat list. */
function neighbourLists(adj: SurfaceAdjacency): { offsets: Int32Array; neighbours: Int32Array } {
  const sets = Array.from({ length: adj.count }, (_, i) => neighbourSet(adj, i));
  const offsets = new Int32Array(adj.count + 1);
  sets.forEach((s, i) => (offsets[i + 1] = offsets[i] + s.length));
  const neighbours = new Int32Array(offsets[adj.count]);
  sets.forEach((s, i) => neighbours.set(s, offsets[i]));
  return { offsets, neighbours };
}

interface Drawn {
  readonly triangles: { positions: Float32Array; cells: Int32Array };
  readonly sites: Float32Array;
  readonly adjacency: SurfaceAdjacency;
}

/** The seeded and other surfaces drawn, analysed together, in basal, apical order. */
function assemble(
  result: VolumeMeasuredResult,
  comparison: VolumeComparison,
  kind: 'mesh' | 'tube',
  seeded: Drawn,
  other: Drawn,
  spacing: number,
): VolumeModelDrawing {
  const analysis = analyzeSurfaces([seeded.adjacency, other.adjacency]);
  const inner = result.inputs.layers.findIndex((l) => l.faces === 'lumen');
  const surface = (d: Drawn, k: number): ModelSurfaceDrawing => ({
    name: result.inputs.layers[k === 0 ? inner : 1 - inner].name,
    faces: k === 0 ? 'lumen' : 'outside',
    positions: d.triangles.positions,
    cells: d.triangles.cells,
    sites: d.sites,
    sides: analysis.cells.sides[k],
    ...neighbourLists(d.adjacency),
    spacing,
  });
  const drawn = [surface(seeded, 0), surface(other, 1)];
  if (inner !== 0) drawn.reverse();
  const { percentScutoids, meanTransitions } = analysis.summary;
  const same = (a: number, b: number | undefined) => a === b || (Number.isNaN(a) && Number.isNaN(b));
  return {
    kind,
    realization: 0,
    seed: comparison.seed,
    k: comparison.bestK,
    cells: seeded.adjacency.count,
    valid: analysis.cells.valid,
    scutoid: analysis.cells.scutoid,
    surfaces: [drawn[0], drawn[1]],
    percentScutoids,
    matches: same(percentScutoids, comparison.percentScutoids[0]) && same(meanTransitions, comparison.meanTransitions[0]),
  };
}

/** Whether triangle (p[0..2], p[b..], p[c..]) is flat: twice its area below 1e-9 of its longest edge squared. */
function flat(p: Float64Array, b: number, c: number): boolean {
  const ux = p[b] - p[0],
    uy = p[b + 1] - p[1],
    uz = p[b + 2] - p[2];
  const vx = p[c] - p[0],
    vy = p[c + 1] - p[1],
    vz = p[c + 2] - p[2];
  const cross = Math.hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
  const longest = Math.max(ux * ux + uy * uy + uz * uz, vx * vx + vy * vy + vz * vz, (vx - ux) ** 2 + (vy - uy) ** 2 + (vz - uz) ** 2);
  return cross <= 1e-9 * longest;
}

/** A closed shell's realization 0 on its meshes (compareShell's steps), drawn as exact RVD pieces. */
function shellDrawing(result: VolumeMeasuredResult, comparison: VolumeComparison, meshes: ShellMeshes, maxTriangles: number): VolumeModelDrawing | string {
  const setup = shellSetup(result, meshes);
  if ('note' in setup) return setup.note;
  if (setup.cells !== comparison.cells) return `the comparison has ${comparison.cells} cells, this volume's lumen side ${setup.cells}`;
  let sites = randomSitesOnMesh(setup.seeded, setup.cells, setup.minSpacing, comparison.seed);
  for (let k = 1; k < comparison.bestK; k++) sites = lloydStepOnMesh(setup.seeded, sites);
  const carried = setup.carry(sites).sites;
  let over = false;
  const draw = (mesh: typeof setup.seeded, at: Float64Array): Drawn => {
    const buffer = new TriangleBuffer(maxTriangles);
    const rvd = restrictedVoronoi({ kind: 'mesh', positions: mesh.positions, indices: mesh.indices, triangleNeighbours: mesh.neighbours }, at, setup.cells, {
      // Each piece is convex: a fan from its first vertex, leaving out flat triangles (three
      // vertices in a line, where a bisector passes through a vertex: no area, edges along a side).
      onPiece: (site, _triangle, polygon, n) => {
        for (let v = 1; v + 1 < n && !over; v++) {
          if (!flat(polygon, 3 * v, 3 * v + 3)) over = !buffer.add(site, polygon, 0, polygon, 3 * v, polygon, 3 * v + 3);
        }
      },
    });
    return { triangles: buffer.finish(), sites: Float32Array.from(at), adjacency: rvd.adjacency };
  };
  const seeded = draw(setup.seeded, sites);
  const other = draw(setup.other, carried);
  if (over) return `the model's surfaces need more than ${maxTriangles} triangles to draw`;
  return assemble(result, comparison, 'mesh', seeded, other, meshes.spacing);
}

/** An orthonormal frame (u, v) across a unit axis. */
function across(axis: readonly number[]): [number[], number[]] {
  const seed = Math.abs(axis[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
  const c = [axis[1] * seed[2] - axis[2] * seed[1], axis[2] * seed[0] - axis[0] * seed[2], axis[0] * seed[1] - axis[1] * seed[0]];
  const n = Math.hypot(c[0], c[1], c[2]);
  const u = c.map((x) => x / n);
  const v = [axis[1] * u[2] - axis[2] * u[1], axis[2] * u[0] - axis[0] * u[2], axis[0] * u[1] - axis[1] * u[0]];
  return [u, v];
}

/** Maps unrolled texel coordinates of the tube model (x around, y along) to the volume's µm. */
function tubePoint(geometry: TubeGeometry, grid: Grid, radius: number): (x: number, y: number, out: Float64Array, o: number) => void {
  const [u, v] = across(geometry.axis);
  const { axis, centre } = geometry;
  return (x, y, out, o) => {
    const theta = (2 * Math.PI * x) / grid.width;
    const along = (y - grid.height / 2) * grid.texelY;
    const c = radius * Math.cos(theta);
    const s = radius * Math.sin(theta);
    for (let k = 0; k < 3; k++) out[o + k] = centre[k] + along * axis[k] + c * u[k] + s * v[k];
  };
}

/** An open piece's realization 0 on its fitted tube (compareWithModel's steps), drawn on the cylinders. */
function tubeDrawing(result: VolumeMeasuredResult, comparison: VolumeComparison, geometry: TubeGeometry, maxTriangles: number): VolumeModelDrawing | string {
  const grid = tubeGrid(result, geometry);
  const cells = geometry.seededCells;
  const sites = exactLloyd(grid, Float64Array.from(placeSites(grid, cells, comparison.seed, comparison.minSpacing)), comparison.bestK - 1);
  const ratio = comparison.surfaceRatio;
  // Subdivisions of each fan triangle: edges of at most about 0.1 rad around, within the budget.
  const diagrams = [exactVoronoi(grid, sites), exactVoronoi({ ...grid, texelX: grid.texelX * ratio }, sites)];
  let fans = 0;
  let widest = 0;
  for (const diagram of diagrams) {
    let surfaceFans = 0;
    for (const cell of diagram.cells) {
      const p = cell.polygon;
      surfaceFans += Math.max(0, p.length / 2 - 2);
      let low = Infinity;
      let high = -Infinity;
      for (let k = 0; k < p.length; k += 2) {
        low = Math.min(low, p[k]);
        high = Math.max(high, p[k]);
      }
      if (high > low) widest = Math.max(widest, high - low);
    }
    fans = Math.max(fans, surfaceFans);
  }
  const wanted = Math.max(1, Math.ceil((2 * Math.PI * widest) / grid.width / 0.1));
  const m = Math.min(8, wanted, Math.floor(Math.sqrt(maxTriangles / Math.max(1, fans))));
  if (m < 1) return `the model's surfaces need more than ${maxTriangles} triangles to draw`;
  const draw = (k: number): Drawn => {
    const radius = k === 0 ? geometry.innerRadius : geometry.outerRadius;
    const map = tubePoint(geometry, grid, radius);
    const buffer = new TriangleBuffer(maxTriangles);
    const corners = new Float64Array(9);
    for (const cell of diagrams[k].cells) {
      const p = cell.polygon;
      const n = p.length / 2;
      for (let f = 1; f + 1 < n; f++) {
        // Fan triangle (0, f, f + 1), split into m² by a barycentric grid (same points on shared edges).
        const at = (i: number, j: number, o: number) => {
          const a = (m - i - j) / m;
          const b = i / m;
          const c = j / m;
          map(a * p[0] + b * p[2 * f] + c * p[2 * f + 2], a * p[1] + b * p[2 * f + 1] + c * p[2 * f + 3], corners, o);
        };
        for (let i = 0; i < m; i++) {
          for (let j = 0; i + j < m; j++) {
            at(i, j, 0);
            at(i + 1, j, 3);
            at(i, j + 1, 6);
            buffer.add(cell.id, corners, 0, corners, 3, corners, 6);
            if (i + j + 1 < m) {
              at(i + 1, j + 1, 0);
              buffer.add(cell.id, corners, 3, corners, 0, corners, 6);
            }
          }
        }
      }
    }
    const xyz = new Float32Array(3 * cells);
    const one = new Float64Array(3);
    for (let i = 0; i < cells; i++) {
      map(sites[2 * i], sites[2 * i + 1], one, 0);
      xyz.set(one, 3 * i);
    }
    return { triangles: buffer.finish(), sites: xyz, adjacency: diagrams[k].adjacency };
  };
  const seeded = draw(0);
  const other = draw(1);
  const spacing = (grid.texelX * Math.sqrt((512 * 4096) / 200)) / 5;
  return assemble(result, comparison, 'tube', seeded, other, spacing);
}

/**
 * The comparison's first realization drawn (see the module comment), or null with a note. A
 * closed shell needs the meshes it was compared on (measureVolume's onSurfaceMeshes).
 */
export function volumeModelDrawing(
  result: VolumeMeasuredResult,
  comparison: VolumeComparison,
  meshes?: ShellMeshes,
  maxTriangles = MAX_MODEL_TRIANGLES,
): { drawing: VolumeModelDrawing | null; note: string } {
  const g = comparison.geometry;
  let out: VolumeModelDrawing | string;
  if (g.kind === 'tube') out = tubeDrawing(result, comparison, g, maxTriangles);
  else if (!meshes) out = 'a closed shell is drawn on its own surface meshes; measure it with onSurfaceMeshes';
  else out = shellDrawing(result, comparison, meshes, maxTriangles);
  return typeof out === 'string' ? { drawing: null, note: `model not drawn: ${out}` } : { drawing: out, note: '' };
}
