/**
 * e^x computed in plain IEEE double arithmetic (fdlibm's algorithm: x = k ln2 + r with ln2 in
 * two parts, a degree-5 rational remez approximation of r, then 2^k; error under 1 ulp), so
 * that it gives the same bits in every JavaScript engine. Math.exp does not: Node's V8 and
 * Chromium's differed in the last bit, and the page's Flintstones fits then differed from the
 * CLI's in their last digits for the same rows. JavaScript arithmetic is IEEE double without
 * fused multiply-add, so every step below rounds alike everywhere.
 */
const LN2_HI = 6.9314718036912381649e-1;
const LN2_LO = 1.90821492927058770002e-10;
const INV_LN2 = 1.442695040888963387;
const P1 = 1.66666666666666019037e-1;
const P2 = -2.77777777770155933842e-3;
const P3 = 6.61375632143793436117e-5;
const P4 = -1.6533902205465251539e-6;
const P5 = 4.13813679705723846039e-8;
/** Above this e^x overflows; below the other it is 0. */
const OVERFLOW = 7.09782712893383973096e2;
const UNDERFLOW = -7.4513321910194110842e2;

/** 2^k as a double, k a whole number from -1022 to 1023 (its exponent bits set directly). */
const scaleBits = new Float64Array(1);
const scaleWords = new Int32Array(scaleBits.buffer);
const HIGH = new Uint8Array(new Uint16Array([1]).buffer)[0] === 1 ? 1 : 0;
function powerOfTwo(k: number): number {
  scaleWords[HIGH] = (k + 1023) << 20;
  scaleWords[1 - HIGH] = 0;
  return scaleBits[0];
}

export function exp(x: number): number {
  if (Number.isNaN(x)) return x;
  if (x > OVERFLOW) return Infinity;
  if (x < UNDERFLOW) return 0;
  const size = Math.abs(x);
  if (size < 2 ** -28) return 1 + x;
  let hi = x;
  let lo = 0;
  let k = 0;
  if (size > 0.5 * Math.LN2) {
    // Argument reduction: x = k ln2 + r, |r| <= ln2 / 2, r = hi - lo exactly enough.
    k = size < 1.5 * Math.LN2 ? (x > 0 ? 1 : -1) : Math.trunc(INV_LN2 * x + (x > 0 ? 0.5 : -0.5));
    hi = x - k * LN2_HI;
    lo = k * LN2_LO;
    x = hi - lo;
  }
  const t = x * x;
  const c = x - t * (P1 + t * (P2 + t * (P3 + t * (P4 + t * P5))));
  if (k === 0) return 1 - ((x * c) / (c - 2) - x);
  const y = 1 - (lo - (x * c) / (2 - c) - hi);
  // y * 2^k in two exact factors where 2^k alone would leave the normal range.
  if (k >= -1021) return k === 1024 ? y * 2 * powerOfTwo(1023) : y * powerOfTwo(k);
  return y * powerOfTwo(k + 1000) * powerOfTwo(-1000);
}
