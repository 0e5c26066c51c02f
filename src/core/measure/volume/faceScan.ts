/**
 * One pass over the voxel faces of a classified volume: per cell, its faces on the outside and
 * on the lumen (counts and signed sums per axis, face-centre sums), which faces of the volume
 * it touches; per pair of cells, the faces they share (the lateral interface).
 *
 * Face areas and the true (not staircase) area of a patch: a plane with unit normal n, cut into
 * voxel faces, has faces normal to axis i of total area A |n_i|, so sum_i count_i a_i |n_i| = A
 * exactly, where a_i is the area of one face normal to axis i. The signed sums give n (the
 * patch's vector area is A n). surfaceArea() applies this with each patch's mean normal.
 */
import { CELL, LUMEN, OUTSIDE } from './voxelClasses';
import type { VolumeArray } from './tiffVolume';

export const FACE_X0 = 1;
export const FACE_X1 = 2;
export const FACE_Y0 = 4;
export const FACE_Y1 = 8;
export const FACE_Z0 = 16;
export const FACE_Z1 = 32;
export const VOLUME_FACE_NAMES: ReadonlyArray<[number, string]> = [
  [FACE_X0, 'first column'],
  [FACE_X1, 'last column'],
  [FACE_Y0, 'first row'],
  [FACE_Y1, 'last row'],
  [FACE_Z0, 'first page'],
  [FACE_Z1, 'last page'],
];

/** Faces of one kind per cell (index = dense id): counts, signed sums and centre sums per axis. */
export interface FaceTally {
  /** 3 per cell: faces normal to x, y, z. */
  readonly counts: Float64Array;
  /** 3 per cell: faces counted +1 when the other side is towards +axis, -1 otherwise. */
  readonly signed: Float64Array;
  /** 3 per cell: sum of face-centre coordinates in voxel units, per face normal axis (x, y, z sums). */
  readonly centres: Float64Array;
}

export interface LateralTally {
  /** Pair key a * (cells + 1) + b, a < b (dense ids). */
  readonly keys: number[];
  /** 3 counts then 3 signed sums (towards b) per pair. */
  readonly faces: Float64Array;
}

export interface FaceScan {
  /** FACE_* bits per dense id. */
  readonly volumeFaces: Uint8Array;
  readonly outside: FaceTally;
  readonly lumen: FaceTally;
  readonly lateral: LateralTally;
}

function tally(cells: number): FaceTally {
  return { counts: new Float64Array(3 * (cells + 1)), signed: new Float64Array(3 * (cells + 1)), centres: new Float64Array(9 * (cells + 1)) };
}

export function scanFaces(ids: VolumeArray, classes: Uint8Array, width: number, height: number, depth: number, cells: number): FaceScan {
  const W = width;
  const plane = width * height;
  const volumeFaces = new Uint8Array(cells + 1);
  const outside = tally(cells);
  const lumen = tally(cells);
  const pairIndex = new Map<number, number>();
  const keys: number[] = [];
  let faces = new Float64Array(6 * 64);
  let lastKey = -1;
  let lastPair = -1;
  const stride = cells + 1;

  const addSurface = (cell: number, kind: number, axis: number, sign: number, cx: number, cy: number, cz: number) => {
    const t = kind === OUTSIDE ? outside : lumen;
    t.counts[3 * cell + axis]++;
    t.signed[3 * cell + axis] += sign;
    const o = 9 * cell + 3 * axis;
    t.centres[o] += cx;
    t.centres[o + 1] += cy;
    t.centres[o + 2] += cz;
  };
  const addLateral = (a: number, b: number, axis: number, sign: number) => {
    // sign: +1 when b lies towards +axis from a
    let lo = a;
    let hi = b;
    if (a > b) {
      lo = b;
      hi = a;
      sign = -sign;
    }
    const key = lo * stride + hi;
    if (key !== lastKey) {
      lastKey = key;
      let p = pairIndex.get(key);
      if (p === undefined) {
        p = keys.push(key) - 1;
        pairIndex.set(key, p);
        if (6 * keys.length > faces.length) {
          const bigger = new Float64Array(faces.length * 2);
          bigger.set(faces);
          faces = bigger;
        }
      }
      lastPair = p;
    }
    faces[6 * lastPair + axis]++;
    faces[6 * lastPair + 3 + axis] += sign;
  };
  /** The face between voxel i and its +axis neighbour j (centre cx, cy, cz in voxel units). */
  const face = (i: number, j: number, axis: number, cx: number, cy: number, cz: number) => {
    const ci = classes[i];
    const cj = classes[j];
    if (ci === CELL) {
      if (cj === CELL) {
        if (ids[i] !== ids[j]) addLateral(ids[i], ids[j], axis, 1);
      } else if (cj === OUTSIDE || cj === LUMEN) addSurface(ids[i], cj, axis, 1, cx, cy, cz);
    } else if (cj === CELL && (ci === OUTSIDE || ci === LUMEN)) addSurface(ids[j], ci, axis, -1, cx, cy, cz);
  };

  for (let z = 0; z < depth; z++) {
    for (let y = 0; y < height; y++) {
      const row = z * plane + y * W;
      for (let x = 0; x < W; x++) {
        const i = row + x;
        const ci = classes[i];
        const id = ids[i];
        if (ci === CELL) {
          let bits = 0;
          if (x === 0) bits |= FACE_X0;
          if (x === W - 1) bits |= FACE_X1;
          if (y === 0) bits |= FACE_Y0;
          if (y === height - 1) bits |= FACE_Y1;
          if (z === 0) bits |= FACE_Z0;
          if (z === depth - 1) bits |= FACE_Z1;
          if (bits) volumeFaces[id] |= bits;
        }
        // Fast path: same class and same id on the other side means no face of interest.
        if (x < W - 1 && (classes[i + 1] !== ci || ids[i + 1] !== id)) face(i, i + 1, 0, x + 1, y + 0.5, z + 0.5);
        if (y < height - 1 && (classes[i + W] !== ci || ids[i + W] !== id)) face(i, i + W, 1, x + 0.5, y + 1, z + 0.5);
        if (z < depth - 1 && (classes[i + plane] !== ci || ids[i + plane] !== id)) face(i, i + plane, 2, x + 0.5, y + 0.5, z + 1);
      }
    }
  }
  return { volumeFaces, outside, lumen, lateral: { keys, faces: faces.subarray(0, 6 * keys.length) } };
}

/**
 * Area of a patch of voxel faces (µm²) from its counts and signed sums per axis: the faces
 * weighted by |n_i| of the patch's mean normal n (exact for a plane). A patch whose signed
 * sums cancel (a closed or folded patch) has no mean normal: its staircase area is returned.
 */
export function surfaceArea(counts: ArrayLike<number>, signed: ArrayLike<number>, o: number, faceArea: readonly [number, number, number]): number {
  const vx = signed[o] * faceArea[0];
  const vy = signed[o + 1] * faceArea[1];
  const vz = signed[o + 2] * faceArea[2];
  const staircase = counts[o] * faceArea[0] + counts[o + 1] * faceArea[1] + counts[o + 2] * faceArea[2];
  const norm = Math.hypot(vx, vy, vz);
  if (!(norm > 1e-9 * staircase)) return staircase;
  return (counts[o] * faceArea[0] * Math.abs(vx) + counts[o + 1] * faceArea[1] * Math.abs(vy) + counts[o + 2] * faceArea[2] * Math.abs(vz)) / norm;
}
