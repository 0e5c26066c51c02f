/**
 * A small, fast, seeded pseudo-random number generator: the same seed gives the same sequence
 * on every platform, which is what makes a run reproducible from its config.
 *
 * Algorithm: sfc32 (Chris Doty-Humphrey's "Small Fast Counting" generator, 128-bit state,
 * 32-bit output, passes PractRand). The 32-bit seed is expanded into the four state words by
 * splitmix32 (a 32-bit variant of Steele et al.'s SplitMix), so nearby seeds (1, 2, 3...)
 * still start from unrelated states; the first 12 outputs are discarded to mix the state
 * further. All arithmetic is 32-bit integer (`| 0`, `>>> 0`, `Math.imul`), so results are
 * exact and identical in every JS engine.
 */
export class Random {
  private a: number;
  private b: number;
  private c: number;
  private d: number;

  /** `seed` is used modulo 2^32 (the config restricts it to 0..2^32-1). */
  constructor(seed: number) {
    let state = seed >>> 0;
    const next = (): number => {
      // splitmix32: add the golden-ratio increment, then mix (constants from Hash Prospector).
      state = (state + 0x9e3779b9) | 0;
      let t = state ^ (state >>> 16);
      t = Math.imul(t, 0x21f0aaad);
      t ^= t >>> 15;
      t = Math.imul(t, 0x735a2d97);
      return (t ^ (t >>> 15)) >>> 0;
    };
    this.a = next();
    this.b = next();
    this.c = next();
    this.d = next();
    for (let i = 0; i < 12; i++) this.nextUint32();
  }

  /** A uniformly distributed integer in [0, 2^32). */
  nextUint32(): number {
    const t = (((this.a + this.b) | 0) + this.d) | 0;
    this.d = (this.d + 1) | 0; // the counter guarantees a period of at least 2^32
    this.a = this.b ^ (this.b >>> 9);
    this.b = (this.c + (this.c << 3)) | 0;
    this.c = (this.c << 21) | (this.c >>> 11);
    this.c = (this.c + t) | 0;
    return t >>> 0;
  }

  /** A float in [0, 1): a 32-bit output divided by 2^32 (never 1, spacing 2^-32). */
  next(): number {
    return this.nextUint32() / 4294967296;
  }

  /** An integer in [0, n) for 1 <= n <= 2^32, without modulo bias (rejection sampling). */
  nextInt(n: number): number {
    if (!(n >= 1 && n <= 4294967296 && Number.isInteger(n))) throw new RangeError(`nextInt: n must be an integer in 1..2^32 (got ${n})`);
    // Accept only outputs below the largest multiple of n that fits in 2^32.
    const limit = 4294967296 - (4294967296 % n);
    for (;;) {
      const value = this.nextUint32();
      if (value < limit) return value % n;
    }
  }
}

/** Convenience: a generator for `seed`. */
export function createRandom(seed: number): Random {
  return new Random(seed);
}

/**
 * The index of the first entry of the cumulative sums `cdf[0..length)` above `r` (r in
 * [0, cdf[length - 1])): sampling an index with probability proportional to its weight.
 */
export function searchCdf(cdf: ArrayLike<number>, length: number, r: number): number {
  let lo = 0;
  let hi = length - 1;
  while (lo < hi) {
    const mid = (lo + hi) >> 1;
    if (cdf[mid] > r) hi = mid;
    else lo = mid + 1;
  }
  return lo;
}
