/** Scale bars: a round length (1, 2 or 5 times a power of ten) no longer than `atMost`. */
export function niceScaleLength(atMost: number): number {
  if (!(atMost > 0) || !Number.isFinite(atMost)) throw new Error(`scale bar: no length fits in ${atMost}`);
  const power = 10 ** Math.floor(Math.log10(atMost));
  for (const step of [5, 2, 1]) if (step * power <= atMost) return step * power;
  return power;
}
