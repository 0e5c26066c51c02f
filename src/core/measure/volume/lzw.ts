/**
 * TIFF LZW decoding (MSB-first codes of 9 to 12 bits, Clear 256, EOI 257, the code width
 * growing one code early as libtiff writes it) into a buffer of known size: the output never
 * grows past `expected` bytes, whatever the input claims.
 */

const CLEAR = 256;
const EOI = 257;

/** Decodes `input` into `out` (its length is the expected size); returns the bytes written. */
export function lzwDecodeInto(input: Uint8Array, out: Uint8Array): number {
  const prefix = new Int32Array(4096);
  const suffix = new Uint8Array(4096);
  const lengthOf = new Int32Array(4096);
  for (let i = 0; i < 256; i++) {
    prefix[i] = -1;
    suffix[i] = i;
    lengthOf[i] = 1;
  }
  let next = 258;
  let width = 9;
  let bitBuffer = 0;
  let bits = 0;
  let p = 0;
  let o = 0;
  let old = -1;
  const limit = out.length;

  /** Writes the string of `code` at o (truncated at the buffer's end); returns its first byte. */
  const write = (code: number): number => {
    const len = lengthOf[code];
    let end = o + len - 1;
    let c = code;
    while (c >= 0) {
      if (end < limit) out[end] = suffix[c];
      end--;
      const first = suffix[c];
      c = prefix[c];
      if (c < 0) {
        o += len;
        return first;
      }
    }
    o += len;
    return 0;
  };

  while (o < limit) {
    while (bits < width) {
      if (p >= input.length) return Math.min(o, limit);
      bitBuffer = ((bitBuffer << 8) | input[p++]) & 0xffffff;
      bits += 8;
    }
    const code = (bitBuffer >>> (bits - width)) & ((1 << width) - 1);
    bits -= width;
    if (code === EOI) break;
    if (code === CLEAR) {
      next = 258;
      width = 9;
      old = -1;
      continue;
    }
    if (old < 0) {
      if (code >= 256) throw new Error(`LZW code ${code} before any string`);
      write(code);
      old = code;
      continue;
    }
    let first: number;
    if (code < next) {
      first = write(code);
    } else if (code === next) {
      // The KwKwK case: the old string plus its own first byte.
      first = write(old);
      if (o < limit) out[o] = first;
      o++;
    } else {
      throw new Error(`LZW code ${code} beyond the table (${next})`);
    }
    if (next < 4096) {
      prefix[next] = old;
      suffix[next] = first;
      lengthOf[next] = lengthOf[old] + 1;
      next++;
      if (next + 1 >= 1 << width && width < 12) width++;
    }
    old = code;
  }
  return Math.min(o, limit);
}
