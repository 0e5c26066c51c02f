/**
 * Writes large synthetic 16-bit label images for the memory/time check of docs/measure.md
 * (not a test): two layers of a brick tiling (40 px bricks, odd rows shifted by half a brick:
 * every inner cell has 6 neighbours); on the apical layer the odd rows are shifted by 1 px only,
 * so the diagonal contacts shrink to 1 px (below the default min-contact) and every inner cell
 * has 4 neighbours there. Written as 16-bit PNG, Deflate TIFF, uncompressed TIFF (*-raw.tif)
 * and one two-page Deflate TIFF (stack.tif).
 *
 *   node --import tsx tests/measure/bench8k.ts DIR [SIZE]
 *   /usr/bin/time -v node --import tsx tests/measure/runMeasure.ts measure DIR/basal.png DIR/apical.png --out DIR/r.json --pixel-size 1
 */
import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { encode } from 'fast-png';
import { writeTiff, type TiffPage } from './tiffWriter';

const dir = process.argv[2] ?? '/tmp';
const size = Number(process.argv[3] ?? 8192);
const cell = 40;
const perRow = Math.ceil(size / cell) + 1;

function brick(shiftOdd: number): Uint16Array {
  const data = new Uint16Array(size * size);
  for (let y = 0; y < size; y++) {
    const row = Math.floor(y / cell);
    const shift = row % 2 === 1 ? shiftOdd : 0;
    for (let x = 0; x < size; x++) data[y * size + x] = 1 + row * perRow + Math.floor((x + shift) / cell);
  }
  return data;
}

const pages: TiffPage[] = [];
for (const [name, shift] of [
  ['basal', cell / 2],
  ['apical', 1],
] as const) {
  const data = brick(shift);
  writeFileSync(join(dir, `${name}.png`), encode({ width: size, height: size, data, depth: 16, channels: 1 }));
  writeFileSync(join(dir, `${name}.tif`), writeTiff([{ width: size, height: size, bitsPerSample: 16, data, rowsPerStrip: 64, compression: 8 }]));
  writeFileSync(join(dir, `${name}-raw.tif`), writeTiff([{ width: size, height: size, bitsPerSample: 16, data, rowsPerStrip: 64 }]));
  pages.push({ width: size, height: size, bitsPerSample: 16, data, rowsPerStrip: 64, compression: 8 });
  console.error(`${name}: ${size} x ${size}, labels up to ${data.reduce((a, b) => Math.max(a, b), 0)}`);
}
writeFileSync(join(dir, 'stack.tif'), writeTiff(pages));
