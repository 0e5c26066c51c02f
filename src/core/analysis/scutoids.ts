/**
 * Statistics of the scutoid model over a stack of surfaces.
 *
 * Input: a list of surfaces ordered from the seeded surface, through K >= 0 intermediate layers,
 * to the other surface (basal -> apical or apical -> basal; the order only matters for "won" and
 * "lost"). Every surface describes the same cells 0..count-1 (cell i on every surface comes from
 * site i and its projections).
 *
 * Definitions (matching the released code of the lab that published the scutoid model):
 * - N_k(i): the neighbour set of cell i on surface k: the ids in its adjacency list,
 *   deduplicated, without i itself.
 * - Border cell: a cell with a `border` bit (src/core/border.ts: it touches an open edge of the
 *   domain, or its producer excluded it) on ANY surface or layer. Border cells are excluded from every statistic below, but they stay in
 *   the neighbour sets of other cells (they count as neighbours, and their sides count in
 *   Aboav-Weaire unless `aboavNeighbours: 'valid'`). Valid cell = not a border cell.
 *   `validCells + excludedCells = cells`.
 * - Sides of cell i on surface k: `sides[i]` when the surface supplies it, otherwise |N_k(i)|.
 * - Won: |N_last(i) \ N_first(i)|. Lost: |N_first(i) \ N_last(i)|.
 * - Apico-basal transitions: sum over consecutive surfaces k = 0..S-2 of
 *   |N_k(i) Δ N_{k+1}(i)| (symmetric difference). With two surfaces this is won + lost; with
 *   layers a neighbour won and lost again between layers counts twice, while won/lost miss it.
 * - 3D neighbours: |N_0(i) ∪ N_1(i) ∪ ... ∪ N_{S-1}(i)|.
 * - Changed: the neighbour set is not the same on all surfaces (N_k(i) != N_l(i) for some k, l,
 *   equivalently transitions > 0). Scutoid: a valid cell that changed. `percentScutoids` uses
 *   this; `percentScutoidsEnds` uses only the first and last surfaces (won + lost > 0), which is
 *   the same number when there are no intermediate layers.
 * - Means (transitions, won, lost, 3D neighbours, sides, areas) are over valid cells.
 * - Polygon distribution on each surface: fraction of valid cells with 3, 4, ..., 9 sides and
 *   with 10 or more ("10+"); valid cells with fewer than 3 sides are counted in `below3` and are
 *   in the denominator (so the fractions sum to 1 - below3 / validCells).
 * - Lewis's law per side class (same classes): count, mean area (µm²) of the class and that mean
 *   divided by the mean area of all valid cells on that surface.
 * - Aboav-Weaire per side class: m(n) = mean over the class's cells of the mean number of sides
 *   of their neighbours (all neighbours by default; only valid ones with
 *   `aboavNeighbours: 'valid'`; cells without counted neighbours are skipped).
 * - With no valid cells every mean and percentage is NaN (never 0 by default).
 */
import { differenceSize, mean, unionInto } from './sortedSets';
import { neighbourSet, type SurfaceAdjacency } from './adjacency';

export interface AnalysisOptions {
  /** Which neighbours enter Aboav-Weaire: 'all' (default) or only 'valid' cells. */
  aboavNeighbours?: 'all' | 'valid';
}

/** Side classes of the polygon distribution, Lewis and Aboav-Weaire: 3..9 then "10+". */
export const SIDE_CLASSES = ['3', '4', '5', '6', '7', '8', '9', '10+'] as const;
type SideClass = (typeof SIDE_CLASSES)[number];

/** Index into SIDE_CLASSES, or -1 for fewer than 3 sides. */
export function sideClassIndex(sides: number): number {
  if (sides < 3) return -1;
  return Math.min(sides, 10) - 3;
}

interface LewisEntry {
  sides: SideClass;
  count: number;
  /** Mean area of the class, µm² (NaN when empty). */
  meanArea: number;
  /** meanArea / mean area of all valid cells (NaN when empty). */
  normalizedArea: number;
}

interface AboavEntry {
  sides: SideClass;
  /** Cells of the class that entered the mean. */
  count: number;
  /** Mean number of sides of the neighbours, m(n) (NaN when empty). */
  meanNeighbourSides: number;
}

export interface SurfaceSummary {
  label?: string;
  meanSides: number;
  meanArea: number;
  /** Fractions of valid cells per class of SIDE_CLASSES. */
  polygonDistribution: number[];
  /** Counts of valid cells per class of SIDE_CLASSES. */
  polygonCounts: number[];
  /** Valid cells with fewer than 3 sides. */
  below3: number;
  lewis: LewisEntry[];
  aboavWeaire: AboavEntry[];
}

export interface ScutoidSummary {
  cells: number;
  validCells: number;
  excludedCells: number;
  surfaces: number;
  scutoids: number;
  /** 100 * scutoids / validCells (neighbour set differs between any two surfaces). */
  percentScutoids: number;
  /** 100 * (valid cells with won + lost > 0) / validCells (first vs last surface only). */
  percentScutoidsEnds: number;
  meanTransitions: number;
  meanWon: number;
  meanLost: number;
  meanNeighbours3D: number;
  perSurface: SurfaceSummary[];
}

export interface CellStatistics {
  /** 1 for valid cells (no border contact on any surface). */
  valid: Uint8Array;
  /** Sides per surface, per cell. */
  sides: Int32Array[];
  won: Int32Array;
  lost: Int32Array;
  transitions: Int32Array;
  neighbours3D: Int32Array;
  /** 1 when the neighbour set is not the same on every surface (any cell, valid or not). */
  changed: Uint8Array;
  /** valid && changed. */
  scutoid: Uint8Array;
}

export interface ScutoidAnalysis {
  cells: CellStatistics;
  summary: ScutoidSummary;
}

/**
 * Every cell's neighbour set (sorted, deduplicated, without the cell: neighbourSet's form) in one
 * flat list: cell i's is ids[offsets[i] .. offsets[i + 1]). Segments that are already strictly
 * ascending without the cell (the exact methods') are copied as they are, others sorted.
 */
function neighbourSets(adj: SurfaceAdjacency, count: number): { offsets: Int32Array; ids: Int32Array } {
  const offsets = new Int32Array(count + 1);
  const ids = new Int32Array(adj.offsets[count] - adj.offsets[0]);
  let n = 0;
  for (let i = 0; i < count; i++) {
    const from = adj.offsets[i];
    const to = adj.offsets[i + 1];
    let canonical = true;
    for (let k = from; k < to; k++) {
      const v = adj.neighbours[k];
      if (v === i || (k > from && adj.neighbours[k - 1] >= v)) {
        canonical = false;
        break;
      }
    }
    if (canonical) {
      for (let k = from; k < to; k++) ids[n++] = adj.neighbours[k];
    } else {
      const set = neighbourSet(adj, i);
      ids.set(set, n);
      n += set.length;
    }
    offsets[i + 1] = n;
  }
  return { offsets, ids };
}

/** Per-cell statistics and summary of a stack of surfaces (see the module comment). */
export function analyzeSurfaces(surfaces: SurfaceAdjacency[], options: AnalysisOptions = {}): ScutoidAnalysis {
  if (surfaces.length === 0) throw new Error('analyzeSurfaces needs at least one surface');
  const count = surfaces[0].count;
  surfaces.forEach((s, k) => {
    if (s.count !== count || s.offsets.length !== count + 1 || s.areas.length !== count || s.border.length !== count) {
      throw new Error(`surface ${k} does not describe ${count} cells`);
    }
  });
  const S = surfaces.length;

  // Neighbour sets per surface (flat: no object per cell).
  const sets = surfaces.map((adj) => neighbourSets(adj, count));
  const sides: Int32Array[] = surfaces.map((s, k) => {
    const out = new Int32Array(count);
    const o = sets[k].offsets;
    for (let i = 0; i < count; i++) out[i] = s.sides ? s.sides[i] : o[i + 1] - o[i];
    return out;
  });

  const valid = new Uint8Array(count);
  for (let i = 0; i < count; i++) {
    let border = false;
    for (const s of surfaces) if (s.border[i] !== 0) border = true;
    valid[i] = border ? 0 : 1;
  }

  const { won, lost, transitions, neighbours3D, changed, scutoid } = cellArrays(count);
  // The union of a cell's sets over the surfaces, merged in two scratch lists.
  let largest = 0;
  for (const set of sets) for (let i = 0; i < count; i++) largest = Math.max(largest, set.offsets[i + 1] - set.offsets[i]);
  let all = new Int32Array(S * largest);
  let merged = new Int32Array(S * largest);
  const first = sets[0];
  const last = sets[S - 1];
  for (let i = 0; i < count; i++) {
    countWonLost(first, last, i, won, lost);
    const f0 = first.offsets[i];
    const f1 = first.offsets[i + 1];
    let t = 0;
    let n = f1 - f0;
    for (let e = f0; e < f1; e++) all[e - f0] = first.ids[e];
    for (let k = 0; k + 1 < S; k++) {
      const a = sets[k];
      const b = sets[k + 1];
      const a0 = a.offsets[i];
      const a1 = a.offsets[i + 1];
      const b0 = b.offsets[i];
      const b1 = b.offsets[i + 1];
      t += differenceSize(a.ids, a0, a1, b.ids, b0, b1) + differenceSize(b.ids, b0, b1, a.ids, a0, a1);
      n = unionInto(all, n, b.ids, b0, b1, merged);
      [all, merged] = [merged, all];
    }
    transitions[i] = t;
    neighbours3D[i] = n;
    changed[i] = t > 0 ? 1 : 0;
    scutoid[i] = valid[i] && changed[i] ? 1 : 0;
  }

  let validCells = 0;
  for (let i = 0; i < count; i++) validCells += valid[i];
  const perSurface = surfaces.map((s, k) => summarizeSurface(s, sets[k], sides[k], valid, validCells, options));
  return summarizeCells({ valid, sides, won, lost, transitions, neighbours3D, changed, scutoid }, perSurface);
}

/** Cell i's neighbours on `last` that are not on `first` into won[i], and the other way round into lost[i] (sets as neighbourSets gives). */
function countWonLost(
  first: { readonly offsets: Int32Array; readonly ids: Int32Array },
  last: { readonly offsets: Int32Array; readonly ids: Int32Array },
  i: number,
  won: Int32Array,
  lost: Int32Array,
): void {
  const f0 = first.offsets[i];
  const f1 = first.offsets[i + 1];
  const l0 = last.offsets[i];
  const l1 = last.offsets[i + 1];
  won[i] = differenceSize(last.ids, l0, l1, first.ids, f0, f1);
  lost[i] = differenceSize(first.ids, f0, f1, last.ids, l0, l1);
}

/** The per-cell arrays of CellStatistics that an analysis fills (validity and sides come first). */
export function cellArrays(count: number): Omit<CellStatistics, 'valid' | 'sides'> {
  return {
    won: new Int32Array(count),
    lost: new Int32Array(count),
    transitions: new Int32Array(count),
    neighbours3D: new Int32Array(count),
    changed: new Uint8Array(count),
    scutoid: new Uint8Array(count),
  };
}

/**
 * The analysis of per-cell statistics: counts and means over the valid cells. `means` gives the
 * won and lost counts the means are taken of (the lab protocol's accumulated ones; default the
 * cells' own, first vs last surface).
 */
export function summarizeCells(cells: CellStatistics, perSurface: SurfaceSummary[], means: { won: Int32Array; lost: Int32Array } = cells): ScutoidAnalysis {
  const { valid, won, lost, transitions, neighbours3D, scutoid } = cells;
  const count = valid.length;
  let validCells = 0;
  let scutoids = 0;
  let ends = 0;
  let sumT = 0;
  let sumWon = 0;
  let sumLost = 0;
  let sum3D = 0;
  for (let i = 0; i < count; i++) {
    if (!valid[i]) continue;
    validCells++;
    scutoids += scutoid[i];
    if (won[i] + lost[i] > 0) ends++;
    sumT += transitions[i];
    sumWon += means.won[i];
    sumLost += means.lost[i];
    sum3D += neighbours3D[i];
  }
  return {
    cells,
    summary: {
      cells: count,
      validCells,
      excludedCells: count - validCells,
      surfaces: cells.sides.length,
      scutoids,
      percentScutoids: mean(100 * scutoids, validCells),
      percentScutoidsEnds: mean(100 * ends, validCells),
      meanTransitions: mean(sumT, validCells),
      meanWon: mean(sumWon, validCells),
      meanLost: mean(sumLost, validCells),
      meanNeighbours3D: mean(sum3D, validCells),
      perSurface,
    },
  };
}

/** One surface of a stack over the valid cells: analyzeSurfaces' perSurface entry. */
export function summarizeSurface(
  surface: SurfaceAdjacency,
  sets: { offsets: Int32Array; ids: Int32Array },
  sides: Int32Array,
  valid: Uint8Array,
  validCells: number,
  options: AnalysisOptions,
): SurfaceSummary {
  const classes = SIDE_CLASSES.length;
  const counts = new Array<number>(classes).fill(0);
  const areaSums = new Array<number>(classes).fill(0);
  const aboavSums = new Array<number>(classes).fill(0);
  const aboavCounts = new Array<number>(classes).fill(0);
  let below3 = 0;
  let sumSides = 0;
  let sumArea = 0;
  const validOnly = options.aboavNeighbours === 'valid';
  for (let i = 0; i < sides.length; i++) {
    if (!valid[i]) continue;
    const n = sides[i];
    const area = surface.areas[i];
    sumSides += n;
    sumArea += area;
    const c = sideClassIndex(n);
    if (c < 0) {
      below3++;
      continue;
    }
    counts[c]++;
    areaSums[c] += area;
    let m = 0;
    let q = 0;
    for (let e = sets.offsets[i]; e < sets.offsets[i + 1]; e++) {
      const j = sets.ids[e];
      if (validOnly && !valid[j]) continue;
      m += sides[j];
      q++;
    }
    if (q > 0) {
      aboavSums[c] += m / q;
      aboavCounts[c]++;
    }
  }
  const meanArea = mean(sumArea, validCells);
  return {
    label: surface.label,
    meanSides: mean(sumSides, validCells),
    meanArea,
    polygonDistribution: counts.map((c) => mean(c, validCells)),
    polygonCounts: counts,
    below3,
    lewis: SIDE_CLASSES.map((label, c) => ({
      sides: label,
      count: counts[c],
      meanArea: mean(areaSums[c], counts[c]),
      normalizedArea: mean(areaSums[c], counts[c]) / meanArea,
    })),
    aboavWeaire: SIDE_CLASSES.map((label, c) => ({
      sides: label,
      count: aboavCounts[c],
      meanNeighbourSides: mean(aboavSums[c], aboavCounts[c]),
    })),
  };
}
