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
import { disjointSets } from './disjointSets';

/** Most cells a volume may have (pair keys of dense ids stay exact doubles). */
const MAX_CELLS = 2 ** 24;

export const CELL = 0;
export const OUTSIDE = 1;
export const LUMEN = 2;
const POCKET = 3;
const UNVISITED = 4;

interface BackgroundComponent {
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

/**
 * Connected components of the background (6-connected) over runs: each row's maximal runs of
 * background voxels are joined (union-find) with the runs they overlap in the row above and in
 * the same row of the slice before. A shell's rows hold a few runs each, so this touches each
 * voxel once and keeps only per-run tables; each component's runs are then filled with its class.
 */
function classifyBackground(volume: LabelVolume, classes: Uint8Array, pocketLimit: number): BackgroundComponent[] {
  const { width: W, height: H, depth: D } = volume;
  const rows = H * D;
  const rowStart = new Int32Array(rows + 1);
  let starts = new Int32Array(1 << 16);
  let ends = new Int32Array(1 << 16);
  let runs = 0;
  for (let r = 0; r < rows; r++) {
    rowStart[r] = runs;
    const base = r * W;
    let x = 0;
    while (x < W) {
      if (classes[base + x] !== UNVISITED) {
        x++;
        continue;
      }
      const x0 = x;
      while (x < W && classes[base + x] === UNVISITED) x++;
      if (runs === starts.length) {
        const s2 = new Int32Array(runs * 2);
        s2.set(starts);
        starts = s2;
        const e2 = new Int32Array(runs * 2);
        e2.set(ends);
        ends = e2;
      }
      starts[runs] = x0;
      ends[runs] = x; // exclusive
      runs++;
    }
  }
  rowStart[rows] = runs;
  const { parent, find } = disjointSets(runs);
  /** Joins the overlapping runs of rows r and q (both sorted by x). */
  const joinRows = (r: number, q: number) => {
    let i = rowStart[r];
    let j = rowStart[q];
    const iEnd = rowStart[r + 1];
    const jEnd = rowStart[q + 1];
    while (i < iEnd && j < jEnd) {
      if (ends[i] <= starts[j]) i++;
      else if (ends[j] <= starts[i]) j++;
      else {
        const a = find(i);
        const b = find(j);
        if (a !== b) parent[a < b ? b : a] = a < b ? a : b;
        if (ends[i] < ends[j]) i++;
        else j++;
      }
    }
  };
  for (let r = 0; r < rows; r++) {
    const y = r % H;
    if (y > 0) joinRows(r, r - 1);
    if (r >= H) joinRows(r, r - H);
  }
  // Per component (root run): voxels and voxels on the volume's faces.
  const rootIndex = new Int32Array(runs).fill(-1);
  const sizes: number[] = [];
  const faces: number[] = [];
  const componentOf = new Int32Array(runs);
  for (let r = 0; r < rows; r++) {
    const y = r % H;
    const z = Math.floor(r / H);
    const wholeRowOnFace = y === 0 || y === H - 1 || z === 0 || z === D - 1;
    for (let k = rowStart[r]; k < rowStart[r + 1]; k++) {
      const root = find(k);
      if (rootIndex[root] < 0) {
        rootIndex[root] = sizes.length;
        sizes.push(0);
        faces.push(0);
      }
      const c = rootIndex[root];
      componentOf[k] = c;
      const length = ends[k] - starts[k];
      sizes[c] += length;
      if (wholeRowOnFace) faces[c] += length;
      else {
        if (starts[k] === 0) faces[c]++;
        if (ends[k] === W && !(starts[k] === 0 && W === 1)) faces[c]++;
      }
    }
  }
  let outside = -1;
  for (let c = 0; c < sizes.length; c++) {
    if (faces[c] > 0 && (outside < 0 || faces[c] > faces[outside] || (faces[c] === faces[outside] && sizes[c] > sizes[outside]))) outside = c;
  }
  const kinds = sizes.map((size, c): BackgroundComponent['kind'] => (c === outside ? 'outside' : faces[c] > 0 || size >= pocketLimit ? 'lumen' : 'pocket'));
  const code = kinds.map((kind) => (kind === 'outside' ? OUTSIDE : kind === 'lumen' ? LUMEN : POCKET));
  for (let r = 0; r < rows; r++) {
    const base = r * W;
    for (let k = rowStart[r]; k < rowStart[r + 1]; k++) classes.fill(code[componentOf[k]], base + starts[k], base + ends[k]);
  }
  return sizes.map((voxels, c) => ({ voxels, faceVoxels: faces[c], kind: kinds[c] }));
}
