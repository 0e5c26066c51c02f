/**
 * The indexed triangle mesh every mesh routine of tissue-sheet works on.
 *
 * Why this shape: it is exactly what a three.js BufferGeometry holds (so loaders and
 * three-mesh-bvh take it without copying), it is transferable to workers and to GPU
 * buffers, and it has no DOM/WebGL dependency, so all geometry runs in Node.
 *
 * - `positions`: x, y, z per vertex (3 floats per vertex).
 * - `indices`: 3 vertex ids per triangle. Triangles are expected counter-clockwise when seen
 *   from outside (outward normals), which is what `checkMesh` verifies as "consistent
 *   orientation" and what the spherical parameterization assumes (it flips if the signed
 *   volume is negative).
 */
export interface TriangleMesh {
  positions: Float32Array;
  indices: Uint32Array;
}

export type Vec3 = [number, number, number];

/** Axis-aligned bounding box; `diagonal` is the length of its diagonal (0 for an empty mesh). */
export function boundingBox(positions: ArrayLike<number>): { min: Vec3; max: Vec3; diagonal: number } {
  const min: Vec3 = [Infinity, Infinity, Infinity];
  const max: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const v = positions[i + k];
      if (v < min[k]) min[k] = v;
      if (v > max[k]) max[k] = v;
    }
  }
  if (positions.length === 0) return { min: [0, 0, 0], max: [0, 0, 0], diagonal: 0 };
  const diagonal = Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  return { min, max, diagonal };
}

/**
 * (b - a) × (c - a) of triangle f (vertex ids at t[3f .. 3f + 2], x, y, z per vertex in `p`),
 * written into `out` (allocates nothing): along the face normal (counter-clockwise vertices),
 * twice the triangle's area long.
 */
export function triangleCross(p: ArrayLike<number>, t: ArrayLike<number>, f: number, out: Float64Array): Float64Array {
  return crossOfDifferences(p, t[3 * f], t[3 * f + 1], t[3 * f], t[3 * f + 2], out);
}

/** (p_b - p_a) × (p_d - p_c) of points of `p` (x, y, z per point), written into `out` (allocates nothing). */
export function crossOfDifferences(p: ArrayLike<number>, a: number, b: number, c: number, d: number, out: Float64Array): Float64Array {
  const ux = p[3 * b] - p[3 * a],
    uy = p[3 * b + 1] - p[3 * a + 1],
    uz = p[3 * b + 2] - p[3 * a + 2];
  const vx = p[3 * d] - p[3 * c],
    vy = p[3 * d + 1] - p[3 * c + 1],
    vz = p[3 * d + 2] - p[3 * c + 2];
  out[0] = uy * vz - uz * vy;
  out[1] = uz * vx - ux * vz;
  out[2] = ux * vy - uy * vx;
  return out;
}

/** (p_b - p_a) · (p_d - p_c) of points of `p` (x, y, z per point). */
export function dotOfDifferences(p: ArrayLike<number>, a: number, b: number, c: number, d: number): number {
  return (
    (p[3 * b] - p[3 * a]) * (p[3 * d] - p[3 * c]) +
    (p[3 * b + 1] - p[3 * a + 1]) * (p[3 * d + 1] - p[3 * c + 1]) +
    (p[3 * b + 2] - p[3 * a + 2]) * (p[3 * d + 2] - p[3 * c + 2])
  );
}

const crossScratch = new Float64Array(3);

/** Area of triangle f (see triangleCross). */
export function triangleArea(p: ArrayLike<number>, t: ArrayLike<number>, f: number): number {
  const n = triangleCross(p, t, f, crossScratch);
  return 0.5 * Math.hypot(n[0], n[1], n[2]);
}

/** Total area of a triangle mesh (positions x, y, z per vertex, 3 vertex ids per triangle). */
export function meshArea(p: ArrayLike<number>, t: ArrayLike<number>): number {
  let s = 0;
  for (let f = 0; f < t.length / 3; f++) s += triangleArea(p, t, f);
  return s;
}

/** Area of every triangle (float64, computed from the float32 positions). */
export function faceAreas(mesh: TriangleMesh): Float64Array {
  const { positions: p, indices: t } = mesh;
  const out = new Float64Array(t.length / 3);
  for (let f = 0; f < out.length; f++) {
    // sqrt of the squares, not hypot: the areas every mesh result was computed with (the last bit differs).
    const [x, y, z] = triangleCross(p, t, f, crossScratch);
    out[f] = 0.5 * Math.sqrt(x * x + y * y + z * z);
  }
  return out;
}

/**
 * Signed enclosed volume (divergence theorem). Positive when the triangles are oriented
 * outward; used to detect inside-out meshes.
 */
export function signedVolume(mesh: { readonly positions: ArrayLike<number>; readonly indices: ArrayLike<number> }): number {
  const { positions: p, indices: t } = mesh;
  let v = 0;
  for (let f = 0; f < t.length; f += 3) {
    const a = 3 * t[f],
      b = 3 * t[f + 1],
      c = 3 * t[f + 2];
    v += p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) - p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) + p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c]);
  }
  return v / 6;
}

/**
 * Area-weighted vertex normals (unit length). Smooth normals are what the geometry image
 * stores per texel: cells are projected along them to the apical surface, and face normals
 * would make that projection jump at every mesh edge.
 */
export function vertexNormals(mesh: TriangleMesh): Float32Array {
  return Float32Array.from(areaWeightedVertexNormals(mesh.positions, mesh.indices));
}

/** Area-weighted vertex normals (sum of the incident faces' cross products), unit length, in float64. */
export function areaWeightedVertexNormals(positions: ArrayLike<number>, indices: ArrayLike<number>): Float64Array {
  const p = positions;
  const n = new Float64Array(p.length);
  const cross = new Float64Array(3);
  for (let f = 0; f < indices.length / 3; f++) {
    triangleCross(p, indices, f, cross);
    for (let k = 0; k < 3; k++) {
      const i = 3 * indices[3 * f + k];
      n[i] += cross[0];
      n[i + 1] += cross[1];
      n[i + 2] += cross[2];
    }
  }
  for (let i = 0; i < n.length; i += 3) {
    const l = Math.hypot(n[i], n[i + 1], n[i + 2]) || 1;
    n[i] /= l;
    n[i + 1] /= l;
    n[i + 2] /= l;
  }
  return n;
}

/** Mean edge length (each undirected edge counted once per incident face side; fine for h). */
export function meanEdgeLength(mesh: TriangleMesh): number {
  const { positions: p, indices: t } = mesh;
  let s = 0;
  for (let f = 0; f < t.length; f += 3) {
    for (let k = 0; k < 3; k++) {
      const a = 3 * t[f + k],
        b = 3 * t[f + ((k + 1) % 3)];
      s += Math.hypot(p[b] - p[a], p[b + 1] - p[a + 1], p[b + 2] - p[a + 2]);
    }
  }
  return t.length ? s / t.length : 0;
}

/** Concatenates meshes (no welding): e.g. two spheres make a two-component mesh. */
export function mergeMeshes(...meshes: TriangleMesh[]): TriangleMesh {
  const positions = new Float32Array(meshes.reduce((s, m) => s + m.positions.length, 0));
  const indices = new Uint32Array(meshes.reduce((s, m) => s + m.indices.length, 0));
  let pv = 0,
    pi = 0;
  for (const m of meshes) {
    positions.set(m.positions, pv);
    for (let i = 0; i < m.indices.length; i++) indices[pi + i] = m.indices[i] + pv / 3;
    pv += m.positions.length;
    pi += m.indices.length;
  }
  return { positions, indices };
}
