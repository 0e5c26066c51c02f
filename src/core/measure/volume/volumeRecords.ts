/** Parts of the volume result built from the scans: background, centroids, lateral contacts, exclusions. */
import { surfaceArea, VOLUME_FACE_NAMES, type FaceScan, type FaceTally } from './faceScan';
import { LUMEN, type VoxelClasses } from './voxelClasses';
import type { VoxelSize } from './voxelSize';
import type { LateralContactRecord, VolumeExclusion, VolumeMeasuredResult } from './volumeResult';

/** The two layers of a volume, in result order. */
export const LAYER_NAMES = ['basal', 'apical'] as const;

/** Whether any lumen voxel (a background component or --lumen-label) lies on a face of the volume. */
function lumenOnFaces(classes: Uint8Array, W: number, H: number, D: number): boolean {
  const at = (x: number, y: number, z: number) => classes[(z * H + y) * W + x] === LUMEN;
  for (let y = 0; y < H; y++) for (let x = 0; x < W; x++) if (at(x, y, 0) || at(x, y, D - 1)) return true;
  for (let z = 0; z < D; z++) {
    for (let x = 0; x < W; x++) if (at(x, 0, z) || at(x, H - 1, z)) return true;
    for (let y = 0; y < H; y++) if (at(0, y, z) || at(W - 1, y, z)) return true;
  }
  return false;
}

export function backgroundRecord(classes: VoxelClasses, W: number, H: number, D: number): VolumeMeasuredResult['inputs']['background'] {
  const lumenReachesFaces = lumenOnFaces(classes.classes, W, H, D);
  let outsideVoxels = 0;
  let lumenVoxels = classes.labelledLumenVoxels;
  let lumenComponents = 0;
  let pockets = 0;
  let pocketVoxels = 0;
  for (const c of classes.components) {
    if (c.kind === 'outside') outsideVoxels += c.voxels;
    else if (c.kind === 'lumen') {
      lumenVoxels += c.voxels;
      lumenComponents++;
    } else {
      pocketVoxels += c.voxels;
      pockets++;
    }
  }
  return { outsideVoxels, lumenComponents, lumenVoxels, labelledLumenVoxels: classes.labelledLumenVoxels, pockets, pocketVoxels, lumenReachesFaces };
}

/** Area-weighted centroid (µm) of a cell's faces of one tally. */
export function centroid(t: FaceTally, id: number, faceArea: readonly number[], size: VoxelSize): [number, number, number] {
  let weight = 0;
  const c = [0, 0, 0];
  for (let axis = 0; axis < 3; axis++) {
    weight += t.counts[3 * id + axis] * faceArea[axis];
    for (let k = 0; k < 3; k++) c[k] += t.centres[9 * id + 3 * axis + k] * faceArea[axis];
  }
  return [(c[0] / weight) * size.x, (c[1] / weight) * size.y, (c[2] / weight) * size.z];
}

export function lateralContacts(faces: FaceScan, n: number, faceArea: [number, number, number], labels: number[]): LateralContactRecord[][] {
  const out: LateralContactRecord[][] = Array.from({ length: n }, () => []);
  const { keys, faces: f } = faces.lateral;
  const stride = n + 1;
  const counts = new Float64Array(3);
  const signed = new Float64Array(3);
  keys.forEach((key, p) => {
    const a = Math.floor(key / stride) - 1;
    const b = (key % stride) - 1;
    for (let axis = 0; axis < 3; axis++) {
      counts[axis] = f[6 * p + axis];
      signed[axis] = f[6 * p + 3 + axis];
    }
    const area = surfaceArea(counts, signed, 0, faceArea);
    const total = counts[0] + counts[1] + counts[2];
    out[a].push({ label: labels[b], area, faces: total });
    out[b].push({ label: labels[a], area, faces: total });
  });
  for (const list of out) list.sort((x, y) => x.label - y.label);
  return out;
}

export function exclusionOf(id: number, reaches: Uint8Array[], faceBits: number): VolumeExclusion | null {
  const missingFrom = [0, 1].filter((k) => !reaches[k][id]);
  const touchesFaces = VOLUME_FACE_NAMES.filter(([bit]) => faceBits & bit).map(([, name]) => name);
  if (missingFrom.length === 0 && touchesFaces.length === 0) return null;
  const reasons = [
    ...(touchesFaces.length ? [`touches the volume's ${touchesFaces.join(', ')}`] : []),
    ...missingFrom.map((k) => `does not reach the ${LAYER_NAMES[k]} surface`),
  ];
  return { missingFrom, touchesFaces, reason: reasons.join('; ') };
}
