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
 * Layers are recognized by identity (the same adjacency object: planarFamily keeps one per
 * seeded surface and grid). The carried state only moves forward: a stack that is not the
 * carried prefix plus more layers starts it again from its first surface. The state is kept per
 * first surface in a WeakMap, so it lives as long as the seeded surface's layers do.
 */
import { analyzeLabStack, analyzeSurfaces, invalidOnAnySurface, neighbourSet, toCsr, type ScutoidAnalysis, type SurfaceAdjacency, type SurfaceSummary } from '../core/analysis';
import type { AdjacencyInput } from '../core/analysis/adjacency';

interface Carried {
  readonly count: number;
  /** Adjacency objects of the layers folded in, first surface first. */
  readonly layers: AdjacencyInput[];
  /** Neighbour sets of the first and of the last folded layer. */
  readonly first: Int32Array[];
  last: Int32Array[];
  /** Per cell: sum over consecutive folded layers of |N_k Δ N_k+1|. */
  readonly transitions: Int32Array;
  /** Per cell: the union of the folded layers' neighbour sets. */
  readonly union: Int32Array[];
  /** Per cell: the lab's accumulated lost and won neighbours (ids, no repeats). */
  readonly lost: number[][];
  readonly won: number[][];
  /** Side counts per folded layer. */
  readonly sides: Int32Array[];
  /** Per-surface summaries by adjacency object, for one valid set. */
  readonly summaries: Map<AdjacencyInput, { label: string | undefined; areas: unknown; excluded: Uint8Array; summary: SurfaceSummary }>;
}

const carried = new WeakMap<AdjacencyInput, Carried>();

/** analyzeLabStack(stack, invalid), carrying the shared layers' sums between calls. */
export function analyzeLabStackReusing(stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  if (stack.length < 2 || stack.some((s) => s.count !== stack[0].count)) return analyzeLabStack(stack, invalid);
  const count = stack[0].count;
  // The prefix every stack of the sweep shares: all surfaces but the last (its outer surface).
  const prefix = stack.length - 1;
  let state = carried.get(stack[0].adjacency);
  const matches = state !== undefined && state.count === count && state.layers.length <= prefix && state.layers.every((layer, k) => layer === stack[k].adjacency);
  if (!state || !matches) {
    state = start(stack[0], count);
    carried.set(stack[0].adjacency, state);
  }
  for (let k = state.layers.length; k < prefix; k++) fold(state, stack[k]);
  return finish(state, stack, invalid);
}

function setsOf(surface: SurfaceAdjacency, count: number): Int32Array[] {
  const csr = toCsr(surface.adjacency);
  const sets: Int32Array[] = new Array(count);
  for (let i = 0; i < count; i++) sets[i] = neighbourSet(csr, i);
  return sets;
}

function sidesOf(surface: SurfaceAdjacency, sets: Int32Array[]): Int32Array {
  const out = new Int32Array(sets.length);
  for (let i = 0; i < sets.length; i++) out[i] = surface.sides ? surface.sides[i] : sets[i].length;
  return out;
}

function start(surface: SurfaceAdjacency, count: number): Carried {
  const first = setsOf(surface, count);
  return {
    count,
    layers: [surface.adjacency],
    first,
    last: first,
    transitions: new Int32Array(count),
    union: first.slice(),
    lost: Array.from({ length: count }, () => []),
    won: Array.from({ length: count }, () => []),
    sides: [sidesOf(surface, first)],
    summaries: new Map(),
  };
}

/** Folds one more layer into the carried sums. */
function fold(state: Carried, surface: SurfaceAdjacency): void {
  const next = setsOf(surface, state.count);
  for (let i = 0; i < state.count; i++) {
    const a = state.last[i];
    const b = next[i];
    state.transitions[i] += differenceSize(a, b) + differenceSize(b, a);
    state.union[i] = union(state.union[i], b);
    addDifference(a, b, state.lost[i]);
    addDifference(b, a, state.won[i]);
  }
  state.last = next;
  state.layers.push(surface.adjacency);
  state.sides.push(sidesOf(surface, next));
}

/** The analysis of the carried prefix plus the stack's last surface (the state is not changed). */
function finish(state: Carried, stack: SurfaceAdjacency[], invalid: Uint8Array): ScutoidAnalysis {
  const { count } = state;
  const outer = stack[stack.length - 1];
  const lastSets = setsOf(outer, count);
  const excluded = invalidOnAnySurface(stack, invalid.length, invalid.slice());

  const valid = new Uint8Array(count);
  for (let i = 0; i < count; i++) valid[i] = excluded[i] ? 0 : 1;
  const won = new Int32Array(count);
  const lost = new Int32Array(count);
  const transitions = new Int32Array(count);
  const neighbours3D = new Int32Array(count);
  const changed = new Uint8Array(count);
  const scutoid = new Uint8Array(count);
  const labWon = new Int32Array(count);
  const labLost = new Int32Array(count);
  const extra: number[] = [];
  for (let i = 0; i < count; i++) {
    const first = state.first[i];
    const previous = state.last[i];
    const last = lastSets[i];
    won[i] = differenceSize(last, first);
    lost[i] = differenceSize(first, last);
    const t = state.transitions[i] + differenceSize(previous, last) + differenceSize(last, previous);
    neighbours3D[i] = union(state.union[i], last).length;
    changed[i] = t > 0 ? 1 : 0;
    scutoid[i] = valid[i] && changed[i] ? 1 : 0;
    // The lab's counts: the carried sets plus what the last step adds.
    extra.length = 0;
    for (const v of state.lost[i]) extra.push(v);
    addDifference(previous, last, extra);
    labLost[i] = extra.length;
    extra.length = 0;
    for (const v of state.won[i]) extra.push(v);
    addDifference(last, previous, extra);
    labWon[i] = extra.length;
    transitions[i] = labWon[i] + labLost[i];
  }

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
    sumWon += labWon[i];
    sumLost += labLost[i];
    sum3D += neighbours3D[i];
  }

  const sides = [...state.sides.slice(0, stack.length - 1), sidesOf(outer, lastSets)];
  const perSurface = stack.map((surface) => surfaceSummary(state, surface, excluded));
  return {
    cells: { valid, sides, won, lost, transitions, neighbours3D, changed, scutoid },
    summary: {
      cells: count,
      validCells,
      excludedCells: count - validCells,
      surfaces: stack.length,
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

/** One surface's summary on the valid set (analyzeSurfaces' perSurface entry), once per valid set. */
function surfaceSummary(state: Carried, surface: SurfaceAdjacency, excluded: Uint8Array): SurfaceSummary {
  const kept = state.summaries.get(surface.adjacency);
  if (kept && kept.label === surface.label && kept.areas === surface.areas && sameBytes(kept.excluded, excluded)) return kept.summary;
  // A stack of one surface masked as in the whole stack: the same valid set, sets and sides.
  const summary = analyzeSurfaces([{ ...surface, touchesBorder: excluded }]).summary.perSurface[0];
  state.summaries.set(surface.adjacency, { label: surface.label, areas: surface.areas, excluded, summary });
  return summary;
}

function sameBytes(a: Uint8Array, b: Uint8Array): boolean {
  if (a.length !== b.length) return false;
  for (let i = 0; i < a.length; i++) if (a[i] !== b[i]) return false;
  return true;
}

const mean = (sum: number, n: number): number => (n > 0 ? sum / n : NaN);

/** Sorted arrays a, b: |a \ b|. */
function differenceSize(a: Int32Array, b: Int32Array): number {
  let i = 0;
  let j = 0;
  let n = 0;
  while (i < a.length) {
    if (j >= b.length || a[i] < b[j]) {
      n++;
      i++;
    } else if (a[i] > b[j]) j++;
    else {
      i++;
      j++;
    }
  }
  return n;
}

/** Sorted, deduplicated arrays a, b: their union (sorted). */
function union(a: Int32Array, b: Int32Array): Int32Array {
  const out = new Int32Array(a.length + b.length);
  let i = 0;
  let j = 0;
  let n = 0;
  while (i < a.length || j < b.length) {
    if (j >= b.length || (i < a.length && a[i] < b[j])) out[n++] = a[i++];
    else if (i >= a.length || b[j] < a[i]) out[n++] = b[j++];
    else {
      out[n++] = a[i++];
      j++;
    }
  }
  return out.subarray(0, n);
}

/** Sorted sets a, b: adds the elements of a \ b not yet in `into`. */
function addDifference(a: Int32Array, b: Int32Array, into: number[]): void {
  let j = 0;
  for (let k = 0; k < a.length; k++) {
    const v = a[k];
    while (j < b.length && b[j] < v) j++;
    if (j < b.length && b[j] === v) continue;
    if (!into.includes(v)) into.push(v);
  }
}
