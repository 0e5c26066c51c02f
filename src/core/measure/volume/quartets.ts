/**
 * The lab's quartet filter: a neighbour exchange counts only when an intercalating quartet
 * confirms it (segmentation noise makes spurious short contacts on one surface only).
 *
 * Cells a, b, c, d form a quartet when a-b are neighbours on one surface and not the other,
 * c-d on the other and not the first, and each of c, d is a neighbour of each of a, b on both
 * surfaces (a T1 transition between the two surfaces: a-b's shared edge shrinks to a vertex
 * and c-d's grows from it). An exchanged pair (a-b, or c-d) belonging to no quartet is
 * unconfirmed: it is removed from the surface it appears on, so the two neighbour sets agree
 * on it and it makes no scutoid.
 */

export interface QuartetFilterResult {
  /** The neighbour sets per surface after the filter (same layout as the input). */
  readonly sets: [Set<number>[], Set<number>[]];
  /** Quartets found, each as [a, b, c, d] (a-b on surface 0 only, c-d on surface 1 only). */
  readonly quartets: [number, number, number, number][];
  /** Pairs removed, [a, b, surface] with a < b. */
  readonly removed: [number, number, number][];
}

/** `sets[k][i]`: neighbours of cell i on surface k (0 and 1). */
export function quartetFilter(sets: [Set<number>[], Set<number>[]]): QuartetFilterResult {
  const count = sets[0].length;
  const onlyOn = (k: 0 | 1): [number, number][] => {
    const out: [number, number][] = [];
    for (let a = 0; a < count; a++) for (const b of sets[k][a]) if (a < b && !sets[1 - k][a].has(b)) out.push([a, b]);
    return out;
  };
  const exchanged = [onlyOn(0), onlyOn(1)];
  const onBoth = (a: number, c: number) => sets[0][a].has(c) && sets[1][a].has(c);
  const confirmed = new Set<string>();
  const quartets: [number, number, number, number][] = [];
  for (const [a, b] of exchanged[0]) {
    // c, d: common neighbours of a and b on both surfaces, themselves neighbours on surface 1 only.
    const common = [...sets[0][a]].filter((c) => c !== b && onBoth(a, c) && onBoth(b, c));
    for (let i = 0; i < common.length; i++) {
      for (let j = i + 1; j < common.length; j++) {
        const c = Math.min(common[i], common[j]);
        const d = Math.max(common[i], common[j]);
        if (sets[1][c].has(d) && !sets[0][c].has(d)) {
          quartets.push([a, b, c, d]);
          confirmed.add(`0:${a}:${b}`);
          confirmed.add(`1:${c}:${d}`);
        }
      }
    }
  }
  const filtered: [Set<number>[], Set<number>[]] = [sets[0].map((s) => new Set(s)), sets[1].map((s) => new Set(s))];
  const removed: [number, number, number][] = [];
  ([0, 1] as const).forEach((k) => {
    for (const [a, b] of exchanged[k]) {
      if (confirmed.has(`${k}:${a}:${b}`)) continue;
      filtered[k][a].delete(b);
      filtered[k][b].delete(a);
      removed.push([a, b, k]);
    }
  });
  return { sets: filtered, quartets, removed };
}
