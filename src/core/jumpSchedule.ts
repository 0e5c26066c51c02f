/**
 * Step sizes of a jump flood over a grid, in the order they run.
 *
 * - "jfa":   N/2, N/4, ..., 1            (Rong & Tan; a few texels end up mislabeled)
 * - "jfa+2": N/2, ..., 1, then 2, 1      (two extra passes fix almost all of them)
 * - "1+jfa": 1, then N/2, ..., 1         (one pass of step 1 first)
 * where N is the grid's larger side rounded up to a power of two.
 *
 * A warm start begins from the previous iteration's labels: sites moved by at most
 * `maxDisplacement` = D texels, so every boundary moved by about D, and a label has to travel
 * at most about D texels. Steps k, k/2, ..., 1 carry a label up to 2k - 1 texels, so k is the
 * first power of two with 2k - 1 >= D + 1 (one texel of slack for rounding). No extra step 1 as
 * in jfa+2: that pass repairs labels that a long jump carried past their cell, which a warm
 * flood's short jumps hardly do: over 20-iteration Lloyd runs on open and periodic grids the
 * mislabeled fraction from iteration 5 on was the same with and without it (see tests/gpu/jumpFlood.test.ts, which
 * checks warm floods against brute force and against a cold flood of the same sites).
 *
 * A cube map floods each face's n x n square (floodWidth = n): steps n/2, ..., 1 carry a label
 * at most n - 1 texels, across a whole face but not across the next one, so texels far from
 * every site stayed unlabelled (1 site on a sphere: about 40 % of it; a few sites: the far
 * part of a face without a site). A cold flood therefore starts with cubeFaceHops
 * (src/core/cubemap/cubemap.ts) steps of n, each to the neighbouring faces (the largest step the
 * cube map's stepTexel follows: at most one face beyond an edge). After them every face holds
 * a label, and the halving steps spread it over the whole face: a chain of steps from any
 * texel of a face to any other stays inside that face, and labels are replaced, never
 * removed. With a site on every face (almost every run of a few dozen cells or more) no hop
 * runs and the schedule is the plain one. A warm flood starts from complete labels: no hop.
 */
export type JumpFloodVariant = 'jfa' | 'jfa+2' | '1+jfa';

export function coldSchedule(width: number, height: number, variant: JumpFloodVariant): number[] {
  const halving: number[] = [];
  for (let step = nextPowerOfTwo(Math.max(width, height)) >> 1; step >= 1; step >>= 1) halving.push(step);
  if (halving.length === 0) halving.push(1);
  switch (variant) {
    case 'jfa':
      return halving;
    case 'jfa+2':
      return [...halving, 2, 1];
    case '1+jfa':
      return [1, ...halving];
  }
}

export function warmSchedule(width: number, height: number, maxDisplacement: number): number[] {
  const steps: number[] = [];
  for (let step = warmFirstStep(width, height, maxDisplacement); step >= 1; step >>= 1) steps.push(step);
  return steps;
}

/**
 * The flood schedules of one grid, built once each: the cold one, and a warm one per first step
 * (the only thing a warm schedule depends on), so a Lloyd loop asking for them allocates nothing.
 * Both GPU engines (planar grid, cube map) take their schedules from here.
 */
export class FloodSchedules {
  readonly cold: readonly number[];
  private readonly warm = new Map<number, readonly number[]>();
  /** The cold schedule after 1 and 2 hops of a whole side (cube faces). */
  private readonly hopped: readonly (readonly number[])[];

  constructor(
    private readonly width: number,
    private readonly height: number,
    variant: JumpFloodVariant,
  ) {
    this.cold = coldSchedule(width, height, variant);
    this.hopped = [this.cold, [width, ...this.cold], [width, width, ...this.cold]];
  }

  /**
   * The cold schedule (after `hops` steps of the whole width: see cubeFaceHops), or the warm
   * one for sites that moved at most `maxDisplacement` texels.
   */
  steps(maxDisplacement?: number, hops = 0): readonly number[] {
    if (maxDisplacement === undefined) return this.hopped[hops];
    const first = warmFirstStep(this.width, this.height, maxDisplacement);
    let steps = this.warm.get(first);
    if (!steps) {
      steps = warmSchedule(this.width, this.height, maxDisplacement);
      this.warm.set(first, steps);
    }
    return steps;
  }
}

/** The first (largest) step of a warm schedule; the rest follows from it. */
export function warmFirstStep(width: number, height: number, maxDisplacement: number): number {
  const limit = nextPowerOfTwo(Math.max(width, height)) >> 1;
  return Math.max(1, Math.min(limit, nextPowerOfTwo(Math.ceil((maxDisplacement + 2) / 2))));
}

export function nextPowerOfTwo(value: number): number {
  let power = 1;
  while (power < value) power <<= 1;
  return power;
}
