/**
 * The lab protocol's analysis of a stack, reusing what the previous call on the same layers
 * computed: `analyzeLabStackReusing(stack, invalid)` returns exactly `analyzeLabStack(stack,
 * invalid)` (tested field by field), but a sweep over surface ratios asks for stacks that share
 * their layers (s = 1, 1.25, ..., the ratio: each run's stack is the previous one's plus a few
 * layers and its own outer surface), so the per-cell sums over consecutive layers (transitions,
 * 3D neighbours, the lab's accumulated won and lost neighbours) are carried from one call to the
 * next instead of recomputed from the seeded surface, and each layer's summary (polygons, Lewis,
 * Aboav-Weaire) is computed once per valid set.
 *
 * Layers are recognized by identity (the same `neighbours` array of the adjacency record, which
 * a relabelled copy shares: planarFamily keeps one record per seeded surface and grid). The carried state only moves forward: a stack that is not the
 * carried prefix plus more layers starts it again from its first surface. The state is kept per
 * first surface in a WeakMap, so it lives as long as the seeded surface's layers do.
 */
import { addDifference, intersectionSize, isCanonical, newDifference } from '../core/analysis/sortedSets';
import { analyzeLabStack, neighbourSet, type ScutoidAnalysis, type SurfaceAdjacency, type SurfaceSummary } from '../core/analysis';
import { cellArrays, summarizeCells, summarizeSurface } from '../core/analysis/scutoids';

/** Neighbour sets of one surface as CSR: each cell's ids ascending, once, without the cell. */
interface Sets {
  readonly offsets: Int32Array;
  readonly ids: Int32Array;
  /** The side counts these sets give (their sizes), made on first use: for surfaces without their own `sides`. */
  sizes?: Int32Array;
}

interface Carried {
  readonly count: number;
  /** The layers folded in (their `neighbours` arrays), first surface first. */
  readonly layers: Int32Array[];
  /** Neighbour sets of the first and of the last folded layer. */
  readonly first: Sets;
  last: Sets;
  /** Per cell: sum over consecutive folded layers of |N_k Δ N_k+1|. */
  readonly transitions: Int32Array;
  /**
   * Per cell: how many of its won neighbours (`won`) are not in its first set. The union of the
   * folded layers' sets is the first set plus the won neighbours (a neighbour of some layer and
   * not of the first entered at some step, between a layer without it and one with it), so its
   * size is |N_first| + this.
   */
  readonly beyondFirst: Int32Array;
  /** Per cell: the lab's accumulated lost and won neighbours (ids, no repeats). */
  readonly lost: number[][];
  readonly won: number[][];
  /** Side counts per folded layer, and the `sides` array of the surface they were read from (undefined: the set sizes). */
  readonly sides: Int32Array[];
  readonly sideSources: (Int32Array | undefined)[];
  /** Per cell: 1 where a folded layer has a border bit (invalidOnAnySurface over the folded layers). */
  readonly border: Uint8Array;
  /** The last call's excluded cells (never written after: a summary keeps it as its valid set's mark). */
  excluded: Uint8Array | null;
  /** Per-surface summaries by adjacency object, for one valid set. */
  readonly summaries: Map<Int32Array, { areas: unknown; sides: unknown; excluded: Uint8Array; summary: SurfaceSummary }>;
}

const carried = new WeakMap<Int32Array, Carried>();
const canonical = new WeakMap<Int32Array, Sets>();

/** analyzeLabStack(stack, invalid), carrying the shared layers' sums between calls. */
export function analyzeLabStackReusing(stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  if (stack.length < 2 || invalid.length !== stack[0].count || stack.some((s) => s.count !== stack[0].count || s.offsets.length !== s.count + 1)) {
    return analyzeLabStack(stack, invalid);
  }
  const count = stack[0].count;
  // The prefix every stack of the sweep shares: all surfaces but the last (its outer surface).
  const prefix = stack.length - 1;
  let state = carried.get(stack[0].neighbours);
  const matches =
    state !== undefined && state.count === count && state.layers.length <= prefix && state.layers.every((layer, k) => layer === stack[k].neighbours);
  if (!state || !matches) {
    state = start(stack[0], count);
    carried.set(stack[0].neighbours, state);
  }
  for (let k = state.layers.length; k < prefix; k++) fold(state, stack[k]);
  return finish(state, stack, invalid);
}

/** The surface's neighbour sets (neighbourSet of every cell), once per record. */
function setsOf(surface: SurfaceAdjacency): Sets {
  const kept = canonical.get(surface.neighbours);
  if (kept) return kept;
  const count = surface.count;
  let sets: Sets;
  if (isCanonical(surface)) sets = { offsets: surface.offsets, ids: surface.neighbours };
  else {
    const lists = Array.from({ length: count }, (_, i) => neighbourSet(surface, i));
    const offsets = new Int32Array(count + 1);
    for (let i = 0; i < count; i++) offsets[i + 1] = offsets[i] + lists[i].length;
    const ids = new Int32Array(offsets[count]);
    lists.forEach((list, i) => ids.set(list, offsets[i]));
    sets = { offsets, ids };
  }
  canonical.set(surface.neighbours, sets);
  return sets;
}

/**
 * The surface's side counts: its own `sides` (copied), else its set sizes (made once per record
 * and shared: no caller writes into the analysis's arrays).
 */
function sidesOf(surface: SurfaceAdjacency, sets: Sets, count: number): Int32Array {
  const own = surface.sides;
  if (own) return Int32Array.from({ length: count }, (_, i) => own[i]);
  if (sets.sizes) return sets.sizes;
  const out = new Int32Array(count);
  const offsets = sets.offsets;
  for (let i = 0; i < count; i++) out[i] = offsets[i + 1] - offsets[i];
  sets.sizes = out;
  return out;
}

function start(surface: SurfaceAdjacency, count: number): Carried {
  const first = setsOf(surface);
  const border = new Uint8Array(count);
  orBorder(border, surface, count);
  return {
    count,
    layers: [surface.neighbours],
    first,
    last: first,
    transitions: new Int32Array(count),
    beyondFirst: new Int32Array(count),
    lost: Array.from({ length: count }, () => []),
    won: Array.from({ length: count }, () => []),
    sides: [sidesOf(surface, first, count)],
    sideSources: [surface.sides],
    border,
    excluded: null,
    summaries: new Map(),
  };
}

/** Marks in `into` the cells with a border bit on `surface` (invalidOnAnySurface's test). */
function orBorder(into: Uint8Array, surface: SurfaceAdjacency, count: number): void {
  const border = surface.border;
  for (let i = 0; i < count; i++) if (border[i] !== 0) into[i] = 1;
}

/** Folds one more layer into the carried sums. */
function fold(state: Carried, surface: SurfaceAdjacency): void {
  const { count, first, transitions, beyondFirst } = state;
  const a = state.last;
  const b = setsOf(surface);
  const { ids: aIds, offsets: aOffsets } = a;
  const { ids: bIds, offsets: bOffsets } = b;
  const firstOffsets = first.offsets;
  for (let i = 0; i < count; i++) {
    const a0 = aOffsets[i];
    const a1 = aOffsets[i + 1];
    const b0 = bOffsets[i];
    const b1 = bOffsets[i + 1];
    // Most cells keep their neighbours from one layer to the next: nothing to add (the
    // differences are empty).
    if (sameRange(aIds, a0, a1, bIds, b0, b1)) continue;
    // |a Δ b| = |a| + |b| - 2 |a ∩ b| (sets without repeats).
    transitions[i] += a1 - a0 + (b1 - b0) - 2 * intersectionSize(aIds, a0, a1, bIds, b0, b1);
    addDifference(aIds, a0, a1, bIds, b0, b1, state.lost[i]);
    // addDifference(b, a, won[i]), counting the new ones that are not in the first set.
    const won = state.won[i];
    const f0 = firstOffsets[i];
    const f1 = firstOffsets[i + 1];
    let j = a0;
    for (let k = b0; k < b1; k++) {
      const v = bIds[k];
      while (j < a1 && aIds[j] < v) j++;
      if ((j < a1 && aIds[j] === v) || won.includes(v)) continue;
      won.push(v);
      if (!inRange(first.ids, f0, f1, v)) beyondFirst[i]++;
    }
  }
  state.last = b;
  state.layers.push(surface.neighbours);
  state.sides.push(sidesOf(surface, b, count));
  state.sideSources.push(surface.sides);
  orBorder(state.border, surface, count);
}

/** The analysis of the carried prefix plus the stack's last surface (the state is not changed). */
function finish(state: Carried, stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  const { count, first, last: previous } = state;
  const outer = stack[stack.length - 1];
  const last = setsOf(outer);
  // invalidOnAnySurface(stack, count, invalid.slice()): the folded layers' borders are carried.
  let excluded: Uint8Array = invalid.slice();
  for (let i = 0; i < count; i++) if (state.border[i] !== 0) excluded[i] = 1;
  orBorder(excluded, outer, count);
  // The previous call's array where the bytes are the same (the usual case): the kept summaries
  // then match it by identity, not byte by byte per surface.
  if (state.excluded && sameBytes(state.excluded, excluded)) excluded = state.excluded;
  else state.excluded = excluded;

  const valid = new Uint8Array(count);
  for (let i = 0; i < count; i++) valid[i] = excluded[i] ? 0 : 1;
  const { won, lost, transitions, neighbours3D, changed, scutoid } = cellArrays(count);
  const labWon = new Int32Array(count);
  const labLost = new Int32Array(count);
  const fIds = first.ids;
  const pIds = previous.ids;
  const lIds = last.ids;
  for (let i = 0; i < count; i++) {
    const f0 = first.offsets[i];
    const f1 = first.offsets[i + 1];
    const p0 = previous.offsets[i];
    const p1 = previous.offsets[i + 1];
    const l0 = last.offsets[i];
    const l1 = last.offsets[i + 1];
    // Won and lost from the first to the last surface (countWonLost): |l \ f| and |f \ l|.
    const kept = intersectionSize(fIds, f0, f1, lIds, l0, l1);
    won[i] = l1 - l0 - kept;
    lost[i] = f1 - f0 - kept;
    const carriedLost = state.lost[i];
    const carriedWon = state.won[i];
    let t = state.transitions[i];
    let all = f1 - f0 + state.beyondFirst[i];
    let newLost = 0;
    let newWon = 0;
    // The last step changes nothing where the outer surface keeps the previous layer's set.
    if (!sameRange(pIds, p0, p1, lIds, l0, l1)) {
      t += p1 - p0 + (l1 - l0) - 2 * intersectionSize(pIds, p0, p1, lIds, l0, l1);
      newLost = newDifference(pIds, p0, p1, lIds, l0, l1, carriedLost);
      // The last step's won neighbours not won before; those not in the first set are new to the union.
      let j = p0;
      for (let k = l0; k < l1; k++) {
        const v = lIds[k];
        while (j < p1 && pIds[j] < v) j++;
        if ((j < p1 && pIds[j] === v) || carriedWon.includes(v)) continue;
        newWon++;
        if (!inRange(fIds, f0, f1, v)) all++;
      }
    }
    neighbours3D[i] = all;
    changed[i] = t > 0 ? 1 : 0;
    scutoid[i] = valid[i] && changed[i] ? 1 : 0;
    // The lab's counts: the carried sets plus what the last step adds.
    labLost[i] = carriedLost.length + newLost;
    labWon[i] = carriedWon.length + newWon;
    transitions[i] = labWon[i] + labLost[i];
  }

  let validCells = 0;
  for (let i = 0; i < count; i++) validCells += valid[i];

  // Carried side counts, except where a surface brings other `sides` than the folded layer's.
  const sides = stack.map((surface, k) =>
    k === stack.length - 1 ? sidesOf(outer, last, count) : surface.sides === state.sideSources[k] ? state.sides[k] : sidesOf(surface, setsOf(surface), count),
  );
  const perSurface = stack.map((surface, k) =>
    surfaceSummary(state, surface, k === stack.length - 1 ? last : k === 0 ? first : setsOf(surface), sides[k], excluded, valid, validCells),
  );
  // Means of won and lost the lab's way (accumulated over the layers), as analyzeLabStack gives.
  return summarizeCells({ valid, sides, won, lost, transitions, neighbours3D, changed, scutoid }, perSurface, { won: labWon, lost: labLost });
}

/** Whether the ascending range ids[from, to) holds v. */
function inRange(ids: Int32Array, from: number, to: number, v: number): boolean {
  for (let k = from; k < to; k++) {
    if (ids[k] >= v) return ids[k] === v;
  }
  return false;
}

/**
 * One surface's summary on the valid set (analyzeSurfaces' perSurface entry: summarizeSurface of
 * the surface's neighbour sets and sides), once per surface and valid set; a surface met again
 * under another label (a ratio's outer surface is a layer of the larger ratios' stacks) gets
 * the same numbers with its own label.
 */
function surfaceSummary(
  state: Carried,
  surface: SurfaceAdjacency,
  sets: Sets,
  sides: Int32Array,
  excluded: Uint8Array,
  valid: Uint8Array,
  validCells: number,
): SurfaceSummary {
  const kept = state.summaries.get(surface.neighbours);
  if (kept && kept.areas === surface.areas && kept.sides === surface.sides && (kept.excluded === excluded || sameBytes(kept.excluded, excluded))) {
    return kept.summary.label === surface.label ? kept.summary : { ...kept.summary, label: surface.label };
  }
  const summary = summarizeSurface(surface, sets, sides, valid, validCells, {});
  state.summaries.set(surface.neighbours, { areas: surface.areas, sides: surface.sides, excluded, summary });
  return summary;
}

/** Whether a[a0, a1) and b[b0, b1) hold the same ids in the same order. */
function sameRange(a: Int32Array, a0: number, a1: number, b: Int32Array, b0: number, b1: number): boolean {
  if (a1 - a0 !== b1 - b0) return false;
  for (let k = 0; k < a1 - a0; k++) if (a[a0 + k] !== b[b0 + k]) return false;
  return true;
}

function sameBytes(a: Uint8Array, b: Uint8Array): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}
