/**
 * Closed surfaces (sphere, ellipsoid, mesh) for the 3D view and the PLY export, drawn from the
 * result: the label image of a closed surface is a cube-map atlas (n x 6n texels, face f in
 * rows f n .. f n + n - 1, see core/cubemap/cubemap.ts) and carries, per texel, the 3D point of
 * the surface there (`LabelImage.positions`, its geometry image). Every texel is a vertex,
 * labelled with the texel's cell; the triangles are each face's n x n grid of texels, strips
 * across the 12 cube edges (texel rows of two faces joined through the cube's edge map) and one
 * triangle at each of the 8 cube corners (where three faces meet): a closed surface with no
 * seam. Pure data (no three.js, no DOM); the triangles of a resolution are built once.
 */
import { CUBE_EDGE, CUBE_EDGES, CUBE_FACES, texelIndex, wrapTexel } from '../core/cubemap/cubemap';
import { crossOfDifferences, meanEdgeLength, signedVolume } from '../core/mesh/types';
import type { LabelImage } from '../run';

/** A surface as triangles, outward normals, and the cell of every vertex. */
export interface ClosedSurfaceMesh {
  /** xyz per vertex: the geometry image's texel positions (µm), in atlas order. */
  positions: Float32Array;
  /** Outward unit normal per vertex. */
  normals: Float32Array;
  /** Counter-clockwise seen from outside. */
  indices: Uint32Array;
  /** Cell id per vertex (the texel's label). */
  cells: Int32Array;
  /** 1 where a vertex sits on a cell boundary: a triangle joins it to a vertex of a cell of higher id (one side of each boundary is marked). */
  boundary: Uint8Array;
  /** Mean triangle edge length (µm): a length scale for stripes. */
  edgeLength: number;
}

/** What a resolution n gives every surface: triangles and the 4 texel neighbours of each texel. */
interface AtlasTopology {
  /** Triangles wound one way on every face (the cube map's s x t side; see closedSurfaceMesh). */
  indices: Uint32Array;
  /** Per texel: the texels at i + 1, i - 1, j + 1, j - 1 (across cube edges where needed). */
  neighbours: Int32Array;
}

const topologies = new Map<number, AtlasTopology>();

/** The triangle mesh of a closed surface's label image; throws when the image has no positions. */
export function closedSurfaceMesh(image: LabelImage): ClosedSurfaceMesh {
  const { grid, labels, positions } = image;
  const n = grid.width;
  if (grid.height !== 6 * n || labels.length !== 6 * n * n) {
    throw new Error(`label image "${image.name}": ${grid.width} x ${grid.height} texels is not a cube-map atlas (n x 6n)`);
  }
  if (!positions || positions.length !== 3 * labels.length) {
    throw new Error(`label image "${image.name}": no geometry image (positions: xyz per texel) to draw the closed surface from`);
  }
  const topology = atlasTopology(n);
  const normals = texelNormals(positions, topology.neighbours);
  // Triangles and normals face the s x t side of the cube map, inward on the direction sphere;
  // a surface may be mapped either way round, so the enclosed volume's sign says which it is.
  const inward = signedVolume({ positions, indices: topology.indices }) < 0;
  const indices = inward ? reversedTriangles(topology.indices) : topology.indices;
  if (inward) for (let k = 0; k < normals.length; k++) normals[k] = -normals[k];
  return {
    positions,
    normals,
    indices,
    cells: labels,
    boundary: cellBoundaries(labels, indices),
    edgeLength: meanEdgeLength({ positions, indices }),
  };
}

/** Triangles and texel neighbours of an n x 6n atlas (cached per n). */
export function atlasTopology(n: number): AtlasTopology {
  let topology = topologies.get(n);
  if (!topology) {
    const triangles: number[] = [];
    faceGrids(n, triangles);
    edgeStrips(n, triangles);
    cornerTriangles(n, triangles);
    topology = { indices: Uint32Array.from(triangles), neighbours: texelNeighbours(n) };
    topologies.set(n, topology);
  }
  return topology;
}

/** Each face's texels as an (n - 1)² grid of quads, two triangles each. */
function faceGrids(n: number, out: number[]): void {
  for (let f = 0; f < 6; f++) {
    for (let j = 0; j + 1 < n; j++) {
      for (let i = 0; i + 1 < n; i++) {
        const a = texelIndex(f, i, j, n),
          b = texelIndex(f, i + 1, j, n);
        const c = texelIndex(f, i, j + 1, n),
          d = texelIndex(f, i + 1, j + 1, n);
        out.push(a, b, d, a, d, c);
      }
    }
  }
}

/**
 * The 12 cube edges: the border row of texels of face f along one edge, joined to the row of
 * the neighbouring face across it (wrapTexel of the texels one step outside), once per edge
 * (from the face of lower index). Wound like the face grids: the border edge a_k -> a_(k+1) is
 * used in the opposite direction to the face grid's triangle along it.
 */
function edgeStrips(n: number, out: number[]): void {
  for (let f = 0; f < 6; f++) {
    for (const edge of [CUBE_EDGE.MinusS, CUBE_EDGE.PlusS, CUBE_EDGE.MinusT, CUBE_EDGE.PlusT]) {
      if (CUBE_EDGES[f][edge].face < f) continue;
      const alongS = edge === CUBE_EDGE.MinusT || edge === CUBE_EDGE.PlusT;
      const inside = edge === CUBE_EDGE.MinusS || edge === CUBE_EDGE.MinusT ? 0 : n - 1;
      const outside = edge === CUBE_EDGE.MinusS || edge === CUBE_EDGE.MinusT ? -1 : n;
      const at = (k: number, across: number) => {
        const t = alongS ? wrapTexel(f, k, across, n) : wrapTexel(f, across, k, n);
        return texelIndex(t.face, t.i, t.j, n);
      };
      const forward = edge === CUBE_EDGE.MinusS || edge === CUBE_EDGE.PlusT;
      for (let k = 0; k + 1 < n; k++) {
        const a0 = at(k, inside),
          a1 = at(k + 1, inside),
          b0 = at(k, outside),
          b1 = at(k + 1, outside);
        if (forward) out.push(a0, a1, b1, a0, b1, b0);
        else out.push(a1, a0, b0, a1, b0, b1);
      }
    }
  }
}

/** The 8 cube corners: the corner texels of the three faces meeting there, one triangle. */
function cornerTriangles(n: number, out: number[]): void {
  const corners = new Map<string, { texel: number; direction: number[] }[]>();
  for (let f = 0; f < 6; f++) {
    const { normal, s, t } = CUBE_FACES[f];
    for (const su of [-1, 1]) {
      for (const sv of [-1, 1]) {
        const i = su < 0 ? 0 : n - 1,
          j = sv < 0 ? 0 : n - 1;
        const corner = [0, 1, 2].map((k) => normal[k] + su * s[k] + sv * t[k]);
        const key = corner.join(',');
        const centre = [0, 1, 2].map((k) => normal[k] + su * (1 - 1 / n) * s[k] + sv * (1 - 1 / n) * t[k]);
        if (!corners.has(key)) corners.set(key, []);
        corners.get(key)!.push({ texel: texelIndex(f, i, j, n), direction: centre });
      }
    }
  }
  for (const [key, [p, q, r]] of corners) {
    const corner = key.split(',').map(Number);
    // Wind it like the faces: (q - p) x (r - p) points inward (against the corner) there.
    const u = [0, 1, 2].map((k) => q.direction[k] - p.direction[k]);
    const v = [0, 1, 2].map((k) => r.direction[k] - p.direction[k]);
    const cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]];
    const inward = cross[0] * corner[0] + cross[1] * corner[1] + cross[2] * corner[2] < 0;
    out.push(p.texel, inward ? q.texel : r.texel, inward ? r.texel : q.texel);
  }
}

/** Per texel, its neighbours at i + 1, i - 1, j + 1, j - 1 (one cube edge crossed at most). */
function texelNeighbours(n: number): Int32Array {
  const out = new Int32Array(4 * 6 * n * n);
  for (let f = 0; f < 6; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const o = 4 * texelIndex(f, i, j, n);
        [
          [i + 1, j],
          [i - 1, j],
          [i, j + 1],
          [i, j - 1],
        ].forEach(([x, y], k) => {
          const t = wrapTexel(f, x, y, n);
          out[o + k] = texelIndex(t.face, t.i, t.j, n);
        });
      }
    }
  }
  return out;
}

/** Unit normals from central differences over the texel grid, on the s x t side. */
function texelNormals(positions: Float32Array, neighbours: Int32Array): Float32Array {
  const normals = new Float32Array(positions.length);
  const count = positions.length / 3;
  const cross = new Float64Array(3);
  for (let v = 0; v < count; v++) {
    // (s+ - s-) × (t+ - t-) of the texel's four neighbours.
    const [nx, ny, nz] = crossOfDifferences(positions, neighbours[4 * v + 1], neighbours[4 * v], neighbours[4 * v + 3], neighbours[4 * v + 2], cross);
    const l = Math.hypot(nx, ny, nz) || 1;
    normals[3 * v] = nx / l;
    normals[3 * v + 1] = ny / l;
    normals[3 * v + 2] = nz / l;
  }
  return normals;
}

function reversedTriangles(t: Uint32Array): Uint32Array {
  const out = new Uint32Array(t.length);
  for (let f = 0; f < t.length; f += 3) {
    out[f] = t[f];
    out[f + 1] = t[f + 2];
    out[f + 2] = t[f + 1];
  }
  return out;
}

/** 1 for a vertex joined by a triangle edge to a vertex of a cell of higher id. */
function cellBoundaries(cells: Int32Array, indices: Uint32Array): Uint8Array {
  const boundary = new Uint8Array(cells.length);
  for (let f = 0; f < indices.length; f += 3) {
    for (let k = 0; k < 3; k++) {
      const i = indices[f + k],
        j = indices[f + ((k + 1) % 3)];
      if (cells[i] < cells[j]) boundary[i] = 1;
      else if (cells[j] < cells[i]) boundary[j] = 1;
    }
  }
  return boundary;
}
