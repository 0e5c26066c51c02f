/**
 * Which voxels are cells, outside, lumen, or ignored background (docs/measure.md, "Measuring a
 * volume"):
 * - labels are renumbered in place to dense ids 1..n (ascending original label; 0 stays
 *   background), so per-cell tables are small whatever the labels were;
 * - voxels labelled `lumenLabel` are lumen (and no cell);
 * - background (0) voxels form 6-connected components. The outside is the component with the
 *   most voxels on the volume's faces; every other component touching a face is lumen (a tube
 *   cut open by the volume); an enclosed component is lumen too unless it is a pocket: fewer
 *   voxels than half the mean cell's, a gap between cells, not a cavity. Pockets are ignored:
 *   faces with them belong to no surface.
 */
import { MeasureInputError } from '../errors';
import type { LabelVolume, VolumeArray } from './tiffVolume';

/** Most cells a volume may have (pair keys of dense ids stay exact doubles). */
export const MAX_CELLS = 2 ** 24;

export const CELL = 0;
export const OUTSIDE = 1;
export const LUMEN = 2;
export const POCKET = 3;
const UNVISITED = 4;
const PENDING = 5;

export interface BackgroundComponent {
  readonly voxels: number;
  /** Voxels on the volume's faces. */
  readonly faceVoxels: number;
  readonly kind: 'outside' | 'lumen' | 'pocket';
}

export interface VoxelClasses {
  /** Dense cell id per voxel (1..cells), 0 for any background: the input array, renumbered. */
  readonly ids: VolumeArray;
  /** CELL, OUTSIDE, LUMEN or POCKET per voxel. */
  readonly classes: Uint8Array;
  /** Original label of dense id k + 1, ascending. */
  readonly labels: number[];
  /** Voxels per dense id (index 0 unused). */
  readonly cellVoxels: Float64Array;
  readonly components: BackgroundComponent[];
  /** Voxels carrying --lumen-label (0 without it). */
  readonly labelledLumenVoxels: number;
}

/** Renumbers the volume's labels in place and classifies the background. */
export function classifyVoxels(volume: LabelVolume, file: string, lumenLabel: number | undefined): VoxelClasses {
  const { data } = volume;
  const n = data.length;
  const classes = new Uint8Array(n);
  const { labels, denseOf } = distinctLabels(data, lumenLabel);
  if (labels.length === 0) throw new MeasureInputError(file, 'no cell labels (every voxel is 0 or the lumen label)');
  if (labels.length > MAX_CELLS) throw new MeasureInputError(file, `${labels.length} labels, over the limit of ${MAX_CELLS} cells`);
  if (lumenLabel !== undefined && !labelsInclude(data, lumenLabel)) {
    throw new MeasureInputError(file, `no voxel carries --lumen-label ${lumenLabel}`);
  }
  const cellVoxels = new Float64Array(labels.length + 1);
  let labelledLumenVoxels = 0;
  let last = -1;
  let lastDense = 0;
  for (let i = 0; i < n; i++) {
    const v = data[i];
    if (v === 0) {
      classes[i] = UNVISITED;
    } else if (v === lumenLabel) {
      data[i] = 0;
      classes[i] = LUMEN;
      labelledLumenVoxels++;
    } else {
      if (v !== last) {
        last = v;
        lastDense = denseOf(v);
      }
      data[i] = lastDense;
      cellVoxels[lastDense]++;
    }
  }
  let cellTotal = 0;
  for (let k = 1; k < cellVoxels.length; k++) cellTotal += cellVoxels[k];
  const pocketLimit = (0.5 * cellTotal) / labels.length;
  const components = classifyBackground(volume, classes, pocketLimit);
  return { ids: data, classes, labels, cellVoxels, components, labelledLumenVoxels };
}

function labelsInclude(data: VolumeArray, label: number): boolean {
  for (let i = 0; i < data.length; i++) if (data[i] === label) return true;
  return false;
}

/** The distinct non-zero labels (without the lumen label), ascending, and a map to dense ids. */
function distinctLabels(data: VolumeArray, lumenLabel: number | undefined): { labels: number[]; denseOf: (v: number) => number } {
  if (!(data instanceof Uint32Array)) {
    const present = new Uint8Array(data instanceof Uint8Array ? 256 : 65536);
    for (let i = 0; i < data.length; i++) present[data[i]] = 1;
    const dense = new Int32Array(present.length);
    const labels: number[] = [];
    for (let v = 1; v < present.length; v++) if (present[v] && v !== lumenLabel) dense[v] = labels.push(v);
    return { labels, denseOf: (v) => dense[v] };
  }
  // 32-bit labels: a set, visited once per run of equal values.
  const seen = new Set<number>();
  let last = 0;
  for (let i = 0; i < data.length; i++) {
    const v = data[i];
    if (v !== last) {
      last = v;
      if (v !== 0) seen.add(v);
    }
  }
  if (lumenLabel !== undefined) seen.delete(lumenLabel);
  const labels = [...seen].sort((a, b) => a - b);
  const dense = new Map<number, number>();
  labels.forEach((v, k) => dense.set(v, k + 1));
  return { labels, denseOf: (v) => dense.get(v)! };
}

/** Flood-fills the background (6-connected), then marks each component outside, lumen or pocket. */
function classifyBackground(volume: LabelVolume, classes: Uint8Array, pocketLimit: number): BackgroundComponent[] {
  const { width: W, height: H, depth: D } = volume;
  const plane = W * H;
  const seeds: number[] = [];
  const sizes: number[] = [];
  const faces: number[] = [];
  let stack = new Int32Array(1 << 16);
  /** Visits the component of `seed` (voxels of class `from`), relabelling them `to`. */
  const flood = (seed: number, from: number, to: number): { voxels: number; faceVoxels: number } => {
    let top = 0;
    let voxels = 0;
    let faceVoxels = 0;
    classes[seed] = to;
    stack[top++] = seed;
    while (top > 0) {
      const i = stack[--top];
      voxels++;
      const x = i % W;
      const y = Math.floor(i / W) % H;
      const z = Math.floor(i / plane);
      if (x === 0 || x === W - 1 || y === 0 || y === H - 1 || z === 0 || z === D - 1) faceVoxels++;
      if (top + 6 > stack.length) {
        const bigger = new Int32Array(stack.length * 2);
        bigger.set(stack);
        stack = bigger;
      }
      if (x > 0 && classes[i - 1] === from) (classes[i - 1] = to), (stack[top++] = i - 1);
      if (x < W - 1 && classes[i + 1] === from) (classes[i + 1] = to), (stack[top++] = i + 1);
      if (y > 0 && classes[i - W] === from) (classes[i - W] = to), (stack[top++] = i - W);
      if (y < H - 1 && classes[i + W] === from) (classes[i + W] = to), (stack[top++] = i + W);
      if (z > 0 && classes[i - plane] === from) (classes[i - plane] = to), (stack[top++] = i - plane);
      if (z < D - 1 && classes[i + plane] === from) (classes[i + plane] = to), (stack[top++] = i + plane);
    }
    return { voxels, faceVoxels };
  };
  for (let i = 0; i < classes.length; i++) {
    if (classes[i] !== UNVISITED) continue;
    const { voxels, faceVoxels } = flood(i, UNVISITED, PENDING);
    seeds.push(i);
    sizes.push(voxels);
    faces.push(faceVoxels);
  }
  let outside = -1;
  for (let c = 0; c < seeds.length; c++) {
    if (faces[c] > 0 && (outside < 0 || faces[c] > faces[outside] || (faces[c] === faces[outside] && sizes[c] > sizes[outside]))) outside = c;
  }
  return seeds.map((seed, c) => {
    const kind = c === outside ? 'outside' : faces[c] > 0 || sizes[c] >= pocketLimit ? 'lumen' : 'pocket';
    flood(seed, PENDING, kind === 'outside' ? OUTSIDE : kind === 'lumen' ? LUMEN : POCKET);
    return { voxels: sizes[c], faceVoxels: faces[c], kind };
  });
}
