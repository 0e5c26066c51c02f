import { describe, expect, it } from 'vitest';
import { crc32, withPngText } from '../../src/app/model/pngText';
import { readPngText } from './pngRead';
import { decode, encode } from 'fast-png';

describe('PNG tEXt provenance', () => {
  it('crc32 matches the published check value and the IEND chunk', () => {
    // The CRC-32 check value of "123456789" (ISO 3309 / ITU-T V.42) is 0xCBF43926.
    expect(crc32(new TextEncoder().encode('123456789'))).toBe(0xcbf43926);
    expect(crc32(new TextEncoder().encode('IEND'))).toBe(0xae426082);
  });

  it('inserts text an independent decoder reads, leaving the pixels unchanged', () => {
    const pixels = new Uint8Array(4 * 3 * 2).map((_, i) => (i * 37) % 256);
    const png = encode({ width: 3, height: 2, data: pixels, channels: 4, depth: 8 });
    const config = JSON.stringify({ surface: { kind: 'tube', radius: 40.7 }, note: 'µm, "quoted"' });
    const tagged = withPngText(png, [
      ['Software', 'tissue-sheet 0.1.0'],
      ['tissue-sheet:config', config],
    ]);
    const decoded = decode(tagged);
    expect(Array.from(decoded.data)).toEqual(Array.from(pixels));
    expect(decoded.text.Software).toBe('tissue-sheet 0.1.0');
    const text = readPngText(tagged);
    expect(JSON.parse(text['tissue-sheet:config'])).toEqual(JSON.parse(config));
    // Latin-1 text as it is (a reader shows "µm", not "\u00b5m"); beyond Latin-1, escaped.
    const method = withPngText(png, [['tissue-sheet:method', 'contact curves in µm, areas in µm² ≥ 0']]);
    expect(decode(method).text['tissue-sheet:method']).toBe('contact curves in µm, areas in µm² \\u2265 0');
  });

  it('refuses what is not a PNG and bad keywords', () => {
    expect(() => withPngText(new Uint8Array(40), [['a', 'b']])).toThrow('not a PNG');
    const png = encode({ width: 1, height: 1, data: new Uint8Array(4), channels: 4, depth: 8 });
    expect(() => withPngText(png, [['', 'b']])).toThrow('keyword');
  });
});
