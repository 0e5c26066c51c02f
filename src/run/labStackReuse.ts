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
import { addDifference, differenceSize, isCanonical, newDifference } from '../core/analysis/sortedSets';
import { analyzeLabStack, invalidOnAnySurface, neighbourSet, type ScutoidAnalysis, type SurfaceAdjacency, type SurfaceSummary } from '../core/analysis';
import { cellArrays, countWonLost, summarizeCells, summarizeSurface } from '../core/analysis/scutoids';

/** Neighbour sets of one surface as CSR: each cell's ids ascending, once, without the cell. */
interface Sets {
  readonly offsets: Int32Array;
  readonly ids: Int32Array;
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
  /** Per cell: the union of the folded layers' neighbour sets (ids, no repeats). */
  readonly union: number[][];
  /** Per cell: the lab's accumulated lost and won neighbours (ids, no repeats). */
  readonly lost: number[][];
  readonly won: number[][];
  /** Side counts per folded layer. */
  readonly sides: Int32Array[];
  /** Per-surface summaries by adjacency object, for one valid set. */
  readonly summaries: Map<Int32Array, { areas: unknown; sides: unknown; excluded: Uint8Array; summary: SurfaceSummary }>;
}

const carried = new WeakMap<Int32Array, Carried>();
const canonical = new WeakMap<Int32Array, Sets>();

/** analyzeLabStack(stack, invalid), carrying the shared layers' sums between calls. */
export function analyzeLabStackReusing(stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  if (stack.length < 2 || stack.some((s) => s.count !== stack[0].count || s.offsets.length !== s.count + 1)) return analyzeLabStack(stack, invalid);
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

function sidesOf(surface: SurfaceAdjacency, sets: Sets, count: number): Int32Array {
  const out = new Int32Array(count);
  for (let i = 0; i < count; i++) out[i] = surface.sides ? surface.sides[i] : sets.offsets[i + 1] - sets.offsets[i];
  return out;
}

function start(surface: SurfaceAdjacency, count: number): Carried {
  const first = setsOf(surface);
  return {
    count,
    layers: [surface.neighbours],
    first,
    last: first,
    transitions: new Int32Array(count),
    union: Array.from({ length: count }, (_, i) => Array.from(first.ids.subarray(first.offsets[i], first.offsets[i + 1]))),
    lost: Array.from({ length: count }, () => []),
    won: Array.from({ length: count }, () => []),
    sides: [sidesOf(surface, first, count)],
    summaries: new Map(),
  };
}

/** Folds one more layer into the carried sums. */
function fold(state: Carried, surface: SurfaceAdjacency): void {
  const a = state.last;
  const b = setsOf(surface);
  for (let i = 0; i < state.count; i++) {
    const a0 = a.offsets[i];
    const a1 = a.offsets[i + 1];
    const b0 = b.offsets[i];
    const b1 = b.offsets[i + 1];
    // Most cells keep their neighbours from one layer to the next: nothing to add (the last
    // layer's set is already in the union, the differences are empty).
    if (sameRange(a.ids, a0, a1, b.ids, b0, b1)) continue;
    state.transitions[i] += differenceSize(a.ids, a0, a1, b.ids, b0, b1) + differenceSize(b.ids, b0, b1, a.ids, a0, a1);
    const u = state.union[i];
    for (let k = b0; k < b1; k++) if (!u.includes(b.ids[k])) u.push(b.ids[k]);
    addDifference(a.ids, a0, a1, b.ids, b0, b1, state.lost[i]);
    addDifference(b.ids, b0, b1, a.ids, a0, a1, state.won[i]);
  }
  state.last = b;
  state.layers.push(surface.neighbours);
  state.sides.push(sidesOf(surface, b, state.count));
}

/** The analysis of the carried prefix plus the stack's last surface (the state is not changed). */
function finish(state: Carried, stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  const { count, first, last: previous } = state;
  const outer = stack[stack.length - 1];
  const last = setsOf(outer);
  const excluded = invalidOnAnySurface(stack, invalid.length, invalid.slice());

  const valid = new Uint8Array(count);
  for (let i = 0; i < count; i++) valid[i] = excluded[i] ? 0 : 1;
  const { won, lost, transitions, neighbours3D, changed, scutoid } = cellArrays(count);
  const labWon = new Int32Array(count);
  const labLost = new Int32Array(count);
  for (let i = 0; i < count; i++) {
    countWonLost(first, last, i, won, lost);
    const p0 = previous.offsets[i];
    const p1 = previous.offsets[i + 1];
    const l0 = last.offsets[i];
    const l1 = last.offsets[i + 1];
    // The last step changes nothing where the outer surface keeps the previous layer's set.
    const same = sameRange(previous.ids, p0, p1, last.ids, l0, l1);
    const t = same
      ? state.transitions[i]
      : state.transitions[i] + differenceSize(previous.ids, p0, p1, last.ids, l0, l1) + differenceSize(last.ids, l0, l1, previous.ids, p0, p1);
    const u = state.union[i];
    let all = u.length;
    if (!same) for (let k = l0; k < l1; k++) if (!u.includes(last.ids[k])) all++;
    neighbours3D[i] = all;
    changed[i] = t > 0 ? 1 : 0;
    scutoid[i] = valid[i] && changed[i] ? 1 : 0;
    // The lab's counts: the carried sets plus what the last step adds.
    labLost[i] = state.lost[i].length + (same ? 0 : newDifference(previous.ids, p0, p1, last.ids, l0, l1, state.lost[i]));
    labWon[i] = state.won[i].length + (same ? 0 : newDifference(last.ids, l0, l1, previous.ids, p0, p1, state.won[i]));
    transitions[i] = labWon[i] + labLost[i];
  }

  let validCells = 0;
  for (let i = 0; i < count; i++) validCells += valid[i];

  // Carried side counts, except where a surface brings its own (`sides`).
  const sides = stack.map((surface, k) =>
    k === stack.length - 1 ? sidesOf(outer, last, count) : surface.sides ? sidesOf(surface, setsOf(surface), count) : state.sides[k],
  );
  const perSurface = stack.map((surface, k) =>
    surfaceSummary(state, surface, k === stack.length - 1 ? last : k === 0 ? first : setsOf(surface), sides[k], excluded, valid, validCells),
  );
  // Means of won and lost the lab's way (accumulated over the layers), as analyzeLabStack gives.
  return summarizeCells({ valid, sides, won, lost, transitions, neighbours3D, changed, scutoid }, perSurface, { won: labWon, lost: labLost });
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
  if (kept && kept.areas === surface.areas && kept.sides === surface.sides && sameBytes(kept.excluded, excluded)) {
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
