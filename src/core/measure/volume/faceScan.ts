/**
 * One pass over the voxel faces of a classified volume: per cell, its faces on the outside and
 * on the lumen (counts per axis, face-centre sums, true area), which faces of
 * the volume it touches; per pair of cells, the faces they share (the lateral interface).
 *
 * Face areas and the true (not staircase) area of a surface: a plane with unit normal n, cut
 * into voxel faces, has faces normal to axis i of total area A |n_i|, so summing a_i |n_i| over
 * its faces gives A exactly, where a_i is the area of one face normal to axis i.
 * - Cells on the outside and lumen: n is the surface's local normal at each face, from the
 *   background voxels in a ball of NORMAL_RADIUS voxels around the face centre (the centroid of
 *   a half-ball lies along its normal); found in voxel-index space, where the ball is round,
 *   then carried to µm (a plane's normal in index space, divided by the voxel size per axis).
 * - Lateral interfaces: surfaceArea() with the interface's mean normal (its vector area).
 */
import { CELL, LUMEN, OUTSIDE } from './voxelClasses';
import type { VolumeArray } from './tiffVolume';

const FACE_X0 = 1;
const FACE_X1 = 2;
const FACE_Y0 = 4;
const FACE_Y1 = 8;
const FACE_Z0 = 16;
const FACE_Z1 = 32;
export const VOLUME_FACE_NAMES: ReadonlyArray<[number, string]> = [
  [FACE_X0, 'first column'],
  [FACE_X1, 'last column'],
  [FACE_Y0, 'first row'],
  [FACE_Y1, 'last row'],
  [FACE_Z0, 'first page'],
  [FACE_Z1, 'last page'],
];

/** Faces of one kind per cell (index = dense id): counts and centre sums per axis, and the true area. */
export interface FaceTally {
  /** 3 per cell: faces normal to x, y, z. */
  readonly counts: Float64Array;
  /** 9 per cell: sums of face-centre coordinates (x, y, z) in voxel units, per face normal axis. */
  readonly centres: Float64Array;
  /** 1 per cell: area in µm², each face weighted by the local normal (see the module comment). */
  readonly area: Float64Array;
}

/** Radius (voxels) of the ball whose background voxels give a face's local normal. */
const NORMAL_RADIUS = 3;

interface LateralTally {
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
  return { counts: new Float64Array(3 * (cells + 1)), centres: new Float64Array(9 * (cells + 1)), area: new Float64Array(cells + 1) };
}

/** Offsets of the voxels in the ball of NORMAL_RADIUS around a voxel centre. */
function ballOffsets(): { dx: Int32Array; dy: Int32Array; dz: Int32Array } {
  const r = NORMAL_RADIUS;
  const list: number[][] = [];
  for (let dz = -r; dz <= r; dz++)
    for (let dy = -r; dy <= r; dy++) for (let dx = -r; dx <= r; dx++) if (dx * dx + dy * dy + dz * dz <= r * r) list.push([dx, dy, dz]);
  return { dx: Int32Array.from(list, (e) => e[0]), dy: Int32Array.from(list, (e) => e[1]), dz: Int32Array.from(list, (e) => e[2]) };
}

export function scanFaces(
  ids: VolumeArray,
  classes: Uint8Array,
  width: number,
  height: number,
  depth: number,
  cells: number,
  voxelSize: { x: number; y: number; z: number },
): FaceScan {
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

  const faceArea = [voxelSize.y * voxelSize.z, voxelSize.x * voxelSize.z, voxelSize.x * voxelSize.y];
  const b = ballOffsets();
  const R = NORMAL_RADIUS;
  const linear = Int32Array.from(b.dx, (dx, k) => b.dz[k] * plane + b.dy[k] * W + dx);
  // A voxel with several faces on a surface computes its normal once.
  let cachedVoxel = -1;
  let cachedKind = -1;
  const unit = new Float64Array(3);
  /** |n_axis| of the surface's local unit normal (µm) at cell voxel (x, y, z), facing background `kind`. */
  const normalComponent = (x: number, y: number, z: number, axis: number, kind: number): number => {
    const at = z * plane + y * W + x;
    if (at !== cachedVoxel || kind !== cachedKind) {
      cachedVoxel = at;
      cachedKind = kind;
      let sx = 0;
      let sy = 0;
      let sz = 0;
      if (x >= R && y >= R && z >= R && x < W - R && y < height - R && z < depth - R) {
        // Inside: no bounds to check.
        for (let k = 0; k < linear.length; k++) {
          if (classes[at + linear[k]] === kind) {
            sx += b.dx[k];
            sy += b.dy[k];
            sz += b.dz[k];
          }
        }
      } else {
        for (let k = 0; k < linear.length; k++) {
          const qx = x + b.dx[k];
          const qy = y + b.dy[k];
          const qz = z + b.dz[k];
          if (qx < 0 || qy < 0 || qz < 0 || qx >= W || qy >= height || qz >= depth) continue;
          if (classes[at + linear[k]] !== kind) continue;
          sx += b.dx[k];
          sy += b.dy[k];
          sz += b.dz[k];
        }
      }
      // Index-space normal to µm: divide by the voxel size per axis.
      const nx = sx / voxelSize.x;
      const ny = sy / voxelSize.y;
      const nz = sz / voxelSize.z;
      const norm = Math.hypot(nx, ny, nz);
      if (norm > 0) {
        unit[0] = Math.abs(nx) / norm;
        unit[1] = Math.abs(ny) / norm;
        unit[2] = Math.abs(nz) / norm;
      } else {
        // No net direction (background all around, a one-voxel cell): each face counts whole.
        unit.fill(1);
      }
    }
    return unit[axis];
  };
  const addSurface = (cell: number, kind: number, axis: number, sign: number, cx: number, cy: number, cz: number) => {
    const t = kind === OUTSIDE ? outside : lumen;
    // The cell's voxel: the face centre moved half a voxel away from the background.
    const h = 0.5 * sign;
    const vx = Math.floor(cx - (axis === 0 ? h : 0));
    const vy = Math.floor(cy - (axis === 1 ? h : 0));
    const vz = Math.floor(cz - (axis === 2 ? h : 0));
    t.area[cell] += faceArea[axis] * normalComponent(vx, vy, vz, axis, kind);
    t.counts[3 * cell + axis]++;
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

  // i: the voxel (x, y, z), z * plane + y * W + x, counted along.
  for (let z = 0, i = 0; z < depth; z++) {
    for (let y = 0; y < height; y++) {
      for (let x = 0; x < W; x++, i++) {
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
