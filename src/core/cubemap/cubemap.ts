/**
 * Cube-map math for geometry images of closed (genus-0) surfaces.
 *
 * Why a cube map: the sphere (our parameter domain, see core/mesh/spherical.ts) is covered by
 * 6 square grids with no singular point and bounded distortion (texel solid angles differ by
 * at most a factor 3√3 ≈ 5.2 between face centre and cube corner), and a jump flood on it only
 * needs, besides the 6 squares, to know where a texel lands when a step leaves its face. That
 * is what this module gives, exactly (integer texel maps), so the GPU side can use it as is.
 *
 * ORIENTATION: the OpenGL / WebGL cube-map convention (OpenGL 4.6 spec, table 8.19), the same
 * that GLSL `texture(samplerCube, dir)` uses. Faces in order
 *   0: +X, 1: -X, 2: +Y, 3: -Y, 4: +Z, 5: -Z.
 * On face f, the face-plane coordinates (u, v) ∈ [-1, 1]² give the direction
 *   dir = normal_f + u · s_f + v · t_f     (then normalised)
 * with (normal, s, t):
 *   +X: (+x, -z, -y)   -X: (-x, +z, -y)   +Y: (+y, +x, +z)
 *   -Y: (-y, +x, -z)   +Z: (+z, +x, -y)   -Z: (-z, -x, -y)
 * TEXELS: face f has n × n texels; texel (i, j) covers u ∈ [2i/n - 1, 2(i+1)/n - 1] (i along s)
 * and v likewise with j (along t); its centre is at ((i + 0.5) 2/n - 1, (j + 0.5) 2/n - 1).
 * STORAGE: texel (f, i, j) is at index (f · n + j) · n + i, i.e. a 2D texture n wide and 6n
 * high with face f in rows [f n, (f + 1) n) (the "vertical strip" atlas).
 * Note: three.js's CubeCamera renders with a mirrored x; we follow the GL table, not it.
 */

export type Vec3 = [number, number, number];

export const FACE_NAMES = ['+X', '-X', '+Y', '-Y', '+Z', '-Z'] as const;

/** normal, s axis (u grows along it), t axis (v grows along it), per face. */
export const CUBE_FACES: ReadonlyArray<{ normal: Vec3; s: Vec3; t: Vec3 }> = [
  { normal: [1, 0, 0], s: [0, 0, -1], t: [0, -1, 0] },
  { normal: [-1, 0, 0], s: [0, 0, 1], t: [0, -1, 0] },
  { normal: [0, 1, 0], s: [1, 0, 0], t: [0, 0, 1] },
  { normal: [0, -1, 0], s: [1, 0, 0], t: [0, 0, -1] },
  { normal: [0, 0, 1], s: [1, 0, 0], t: [0, -1, 0] },
  { normal: [0, 0, -1], s: [-1, 0, 0], t: [0, -1, 0] },
];

const dot = (a: Vec3, b: Vec3) => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];

/** Index of texel (face, i, j) in the 6 n² storage order. */
export function texelIndex(face: number, i: number, j: number, n: number): number {
  return (face * n + j) * n + i;
}

/** Inverse of texelIndex. */
export function texelFromIndex(index: number, n: number): { face: number; i: number; j: number } {
  const i = index % n;
  const row = (index - i) / n;
  const j = row % n;
  return { face: (row - j) / n, i, j };
}

/** Unit direction through the face-plane point (u, v) of face f (u, v may lie outside [-1, 1]). */
function faceUvToDirection(face: number, u: number, v: number): Vec3 {
  const { normal: N, s, t } = CUBE_FACES[face];
  const x = N[0] + u * s[0] + v * t[0],
    y = N[1] + u * s[1] + v * t[1],
    z = N[2] + u * s[2] + v * t[2];
  const l = Math.hypot(x, y, z);
  return [x / l, y / l, z / l];
}

/** Unit direction of the centre of texel (i, j) of face f. */
export function texelDirection(face: number, i: number, j: number, n: number): Vec3 {
  return faceUvToDirection(face, ((i + 0.5) * 2) / n - 1, ((j + 0.5) * 2) / n - 1);
}

/**
 * Face and face-plane coordinates of a direction (need not be unit). The face is the axis of
 * largest |component|; ties (cube edges) go to x before y before z, and to + before -.
 */
function directionToFaceUv(d: Vec3): { face: number; u: number; v: number } {
  const ax = Math.abs(d[0]),
    ay = Math.abs(d[1]),
    az = Math.abs(d[2]);
  let face: number;
  if (ax >= ay && ax >= az) face = d[0] >= 0 ? 0 : 1;
  else if (ay >= az) face = d[1] >= 0 ? 2 : 3;
  else face = d[2] >= 0 ? 4 : 5;
  const F = CUBE_FACES[face];
  const m = dot(d, F.normal);
  return { face, u: dot(d, F.s) / m, v: dot(d, F.t) / m };
}

/** Texel containing a direction (u = 1 exactly is put in the last texel). */
export function directionToTexel(d: Vec3, n: number): { face: number; i: number; j: number; u: number; v: number } {
  const { face, u, v } = directionToFaceUv(d);
  const i = Math.min(n - 1, Math.max(0, Math.floor(((u + 1) / 2) * n)));
  const j = Math.min(n - 1, Math.max(0, Math.floor(((v + 1) / 2) * n)));
  return { face, i, j, u, v };
}

/**
 * Solid angle subtended by the face-plane rectangle [0, x] × [0, y] (signed), the building block
 * of the exact texel solid angle: Ω = atan2(x y, √(x² + y² + 1)).
 */
function cornerSolidAngle(x: number, y: number): number {
  return Math.atan2(x * y, Math.sqrt(x * x + y * y + 1));
}

/**
 * Exact solid angle of texel (i, j) (the same on every face):
 * Ω = A(x1, y1) - A(x0, y1) - A(x1, y0) + A(x0, y0), A(x, y) = atan2(x y, √(x² + y² + 1)).
 * Summed over the 6 n² texels this is 4π up to rounding.
 */
export function texelSolidAngle(i: number, j: number, n: number): number {
  const x0 = (2 * i) / n - 1,
    x1 = (2 * (i + 1)) / n - 1;
  const y0 = (2 * j) / n - 1,
    y1 = (2 * (j + 1)) / n - 1;
  return cornerSolidAngle(x1, y1) - cornerSolidAngle(x0, y1) - cornerSolidAngle(x1, y0) + cornerSolidAngle(x0, y0);
}

/**
 * Edges of a face, numbered by where a texel coordinate leaves [0, n): 0: i < 0 (u < -1),
 * 1: i >= n (u > 1), 2: j < 0 (v < -1), 3: j >= n (v > 1). A plain object rather than an enum
 * so the numbers can be copied into GLSL as they are.
 */
export const CUBE_EDGE = { MinusS: 0, PlusS: 1, MinusT: 2, PlusT: 3 } as const;

/**
 * How face-plane coordinates continue across one edge: the neighbour face and the affine map
 * (u', v') = (a u + b v + c, d u + e v + f) that unfolds face f's plane beyond that edge onto the
 * neighbour (a rotation by a multiple of 90° plus a shift; every coefficient is 0, ±1 or ±2).
 * It is the exact continuation: a point a distance δ beyond the edge on f's plane lands a
 * distance δ inside the neighbour, measured perpendicular to the shared edge.
 */
export interface EdgeTransform {
  face: number;
  a: number;
  b: number;
  c: number;
  d: number;
  e: number;
  f: number;
}

function computeEdgeTransforms(): EdgeTransform[][] {
  const table: EdgeTransform[][] = [];
  for (let face = 0; face < 6; face++) {
    const F = CUBE_FACES[face];
    const row: EdgeTransform[] = [];
    for (let edge = 0; edge < 4; edge++) {
      const axis = edge < 2 ? F.s : F.t;
      const sign = edge % 2 === 0 ? -1 : 1;
      const nNormal: Vec3 = [sign * axis[0], sign * axis[1], sign * axis[2]];
      const g = CUBE_FACES.findIndex((G) => dot(G.normal, nNormal) === 1);
      const G = CUBE_FACES[g];
      // Fold a point beyond the edge onto g: clamp the crossing coordinate to the edge and go
      // δ (the excess) along -normal_f.
      const fold = (u: number, v: number): [number, number] => {
        const cu = edge < 2 ? sign : u,
          cv = edge < 2 ? v : sign;
        const delta = edge < 2 ? sign * u - 1 : sign * v - 1;
        const P: Vec3 = [0, 1, 2].map((k) => F.normal[k] * (1 - delta) + cu * F.s[k] + cv * F.t[k]) as Vec3;
        return [dot(P, G.s), dot(P, G.t)];
      };
      // Three points beyond the edge determine the affine map.
      const p0: [number, number] = edge < 2 ? [sign * 1.5, 0] : [0, sign * 1.5];
      const p1: [number, number] = edge < 2 ? [sign * 1.25, 0] : [0, sign * 1.25];
      const p2: [number, number] = edge < 2 ? [sign * 1.5, 0.5] : [0.5, sign * 1.5];
      const q0 = fold(...p0),
        q1 = fold(...p1),
        q2 = fold(...p2);
      // Solve for (a, b, c) and (d, e, f).
      const solve = (r0: number, r1: number, r2: number) => {
        const M = [
          [p0[0], p0[1], 1],
          [p1[0], p1[1], 1],
          [p2[0], p2[1], 1],
        ];
        const det = (m: number[][]) =>
          m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
          m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
          m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
        const D = det(M);
        const rhs = [r0, r1, r2];
        return [0, 1, 2].map((col) => Math.round(det(M.map((r, k) => r.map((x, c) => (c === col ? rhs[k] : x)))) / D));
      };
      const [a, b, c] = solve(q0[0], q1[0], q2[0]);
      const [d, e, f] = solve(q0[1], q1[1], q2[1]);
      row.push({ face: g, a, b, c, d, e, f });
    }
    table.push(row);
  }
  return table;
}

/** CUBE_EDGES[face][edge]: see EdgeTransform and CUBE_EDGE. */
export const CUBE_EDGES: ReadonlyArray<ReadonlyArray<EdgeTransform>> = computeEdgeTransforms();

/**
 * The same transforms in integer texel indices for resolution n:
 * i' = A i + B j + C, j' = D i + E j + F. Flat Int32Array of 6 × 4 × 7 entries
 * [face', A, B, C, D, E, F] per (face, edge), ready to upload as a uniform array.
 * Derivation: the texel centre x = i + ½ maps to u = 2x/n - 1; applying (a, b, c) and going back
 * gives i' = a i + b j + (a + b - 1)/2 + (c + 1 - a - b) n/2 (all integers: exactly one of a, b
 * is ±1 and c + 1 - a - b is even).
 */
export function texelEdgeTable(n: number): Int32Array {
  const out = new Int32Array(6 * 4 * 7);
  for (let face = 0; face < 6; face++) {
    for (let edge = 0; edge < 4; edge++) {
      const T = CUBE_EDGES[face][edge];
      const o = (face * 4 + edge) * 7;
      out[o] = T.face;
      out[o + 1] = T.a;
      out[o + 2] = T.b;
      out[o + 3] = (T.a + T.b - 1) / 2 + ((T.c + 1 - T.a - T.b) * n) / 2;
      out[o + 4] = T.d;
      out[o + 5] = T.e;
      out[o + 6] = (T.d + T.e - 1) / 2 + ((T.f + 1 - T.d - T.e) * n) / 2;
    }
  }
  return out;
}

const tableCache = new Map<number, Int32Array>();

/**
 * Where texel (i, j) of face f lands when (i, j) may lie outside [0, n)², e.g. after a jump
 * flood step of up to n texels. Crosses one edge at a time (the s edge first when both
 * coordinates are out), following the rigid unfolding of the cube, so a step off an edge and
 * the opposite step back return to the same texel. Near a cube corner (both coordinates out)
 * there is no unique answer, three faces meet there; the result is a texel next to the corner.
 */
export function wrapTexel(face: number, i: number, j: number, n: number): { face: number; i: number; j: number } {
  let table = tableCache.get(n);
  if (!table) {
    table = texelEdgeTable(n);
    tableCache.set(n, table);
  }
  for (let step = 0; step < 4; step++) {
    let edge: number;
    if (i < 0) edge = 0;
    else if (i >= n) edge = 1;
    else if (j < 0) edge = 2;
    else if (j >= n) edge = 3;
    else return { face, i, j };
    const o = (face * 4 + edge) * 7;
    const ni = table[o + 1] * i + table[o + 2] * j + table[o + 3];
    const nj = table[o + 4] * i + table[o + 5] * j + table[o + 6];
    face = table[o];
    i = ni;
    j = nj;
  }
  // Steps longer than a face: fall back to the direction of the extended face-plane point.
  const d = faceUvToDirection(face, ((i + 0.5) * 2) / n - 1, ((j + 0.5) * 2) / n - 1);
  const t = directionToTexel(d, n);
  return { face: t.face, i: t.i, j: t.j };
}

/**
 * How many steps of a whole face (n) a cold jump flood of the cube map runs before its halving
 * steps (src/core/jumpSchedule.ts), from the faces that hold a site (`sites`: `stride` values
 * per site, the atlas index of its texel at offset 3; face = index / n²): 0 when all six do;
 * 2 when one face holds them all (its opposite face is two faces away); else 1 (every face
 * without a site then borders one with a site).
 */
export function cubeFaceHops(n: number, sites: ArrayLike<number>, count: number, stride = 4): number {
  let faces = 0;
  for (let i = 0; i < count; i++) faces |= 1 << Math.floor(sites[stride * i + 3] / (n * n));
  if (faces === 0b111111) return 0;
  return faces & (faces - 1) ? 1 : 2;
}
