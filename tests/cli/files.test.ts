import { mkdirSync, mkdtempSync, readFileSync, symlinkSync, writeFileSync } from 'node:fs';
import { hostname, tmpdir } from 'node:os';
import { join } from 'node:path';
import { deflateSync } from 'node:zlib';
import { encode } from 'fast-png';
import { describe, expect, it } from 'vitest';
import { lockDirectory, LOCK_NAME } from '../../src/cli/lock';
import { checkOutDir, checkOutFile, writeFileAtomic } from '../../src/cli/output';
import { readPngHeader } from '../../src/core/grayPng';
import { decodeGrayPng, ImageError, loadGrayImage } from '../../src/node/image';

const dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-files-'));

/** A PNG whose header declares `width` x `height` pixels, with a tiny IDAT: a decompression bomb. */
function declaredPng(width: number, height: number): Buffer {
  const crcTable = Array.from({ length: 256 }, (_, n) => {
    let c = n;
    for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1;
    return c >>> 0;
  });
  const crc = (bytes: Buffer) => {
    let c = 0xffffffff;
    for (const b of bytes) c = crcTable[(c ^ b) & 0xff] ^ (c >>> 8);
    return (c ^ 0xffffffff) >>> 0;
  };
  const chunk = (type: string, data: Buffer) => {
    const body = Buffer.concat([Buffer.from(type, 'ascii'), data]);
    const out = Buffer.alloc(8 + data.length + 4);
    out.writeUInt32BE(data.length, 0);
    body.copy(out, 4);
    out.writeUInt32BE(crc(body), 8 + data.length);
    return out;
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0);
  ihdr.writeUInt32BE(height, 4);
  ihdr[8] = 8; // bit depth
  const idat = deflateSync(Buffer.alloc(48 * 1024 * 20)); // compresses to a few tens of KB
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', ihdr),
    chunk('IDAT', idat),
    chunk('IEND', Buffer.alloc(0)),
  ]);
}

function grayPng(width: number, height: number): Buffer {
  return Buffer.from(encode({ width, height, data: new Uint8Array(4 * width * height).fill(255), depth: 8, channels: 4 }));
}

describe('density images: header first', () => {
  it('refuses a small PNG declaring 20000 x 20000 pixels in milliseconds, without decoding it', () => {
    const bomb = declaredPng(20000, 20000);
    expect(bomb.length).toBeLessThan(64 * 1024);
    const path = join(dir, 'bomb.png');
    writeFileSync(path, bomb);
    const before = process.memoryUsage().rss;
    const start = performance.now();
    expect(() => loadGrayImage(path)).toThrow(/bomb\.png: 20000 x 20000 pixels is more than the 67108864 allowed/);
    expect(performance.now() - start).toBeLessThan(200);
    expect(process.memoryUsage().rss - before).toBeLessThan(200 * 2 ** 20);
    expect(readPngHeader(bomb.subarray(0, 33), 'x', Infinity)).toEqual({ width: 20000, height: 20000, bitDepth: 8, colorType: 0 });
  });
  it('names the file for an empty file, a directory, a truncated PNG and a non-PNG', () => {
    writeFileSync(join(dir, 'empty.png'), '');
    expect(() => loadGrayImage(join(dir, 'empty.png'))).toThrow(/empty\.png: the file is empty/);
    mkdirSync(join(dir, 'folder.png'));
    expect(() => loadGrayImage(join(dir, 'folder.png'))).toThrow(/folder\.png: is a directory/);
    expect(() => loadGrayImage(join(dir, 'missing.png'))).toThrow(/missing\.png: cannot read it \(no such file\)/);
    const good = grayPng(4, 3);
    expect(decodeGrayPng(good).luminance.every((v) => v === 1)).toBe(true);
    expect(() => decodeGrayPng(good.subarray(0, good.length - 20), 'cut.png')).toThrow(ImageError);
    expect(() => decodeGrayPng(good.subarray(0, good.length - 20), 'cut.png')).toThrow(/cut\.png: truncated PNG/);
    expect(() => decodeGrayPng(Buffer.from('GIF89a...'), 'a.gif')).toThrow(/a\.gif: not a PNG file/);
  });
});

describe('--out', () => {
  const input = join(dir, 'config.json');
  writeFileSync(input, '{}');
  it('never names the input, never follows a link, never overwrites a file of someone else without --force', () => {
    expect(() => checkOutFile(input, [input], true)).toThrow(/that is the input file/);
    const other = join(dir, 'precious.txt');
    writeFileSync(other, 'keep me');
    const link = join(dir, 'link.json');
    symlinkSync(other, link);
    expect(() => checkOutFile(link, [input], true)).toThrow(/symbolic link/);
    expect(() => checkOutFile(other, [input], false)).toThrow(/exists and is not a tissue-sheet result; pass --force/);
    expect(() => checkOutFile(other, [input], true)).not.toThrow();
    const ours = join(dir, 'result.json');
    writeFileSync(ours, JSON.stringify({ software: { name: 'tissue-sheet', version: '0' } }, null, 2));
    expect(() => checkOutFile(ours, [input], false)).not.toThrow();
    expect(() => checkOutFile(join(dir, 'new.json'), [input], false)).not.toThrow();
    writeFileAtomic(link, 'replaced');
    expect(readFileSync(other, 'utf8')).toBe('keep me'); // the rename replaced the link, not its target
  });
  it('refuses a non-empty directory that is not a sweep of ours, and links inside one', () => {
    const foreign = join(dir, 'foreign');
    mkdirSync(foreign);
    writeFileSync(join(foreign, 'thesis.tex'), '');
    expect(() => checkOutDir(foreign, [input], false)).toThrow(/not a tissue-sheet sweep; pass --force/);
    const sweep = join(dir, 'sweep');
    mkdirSync(sweep);
    writeFileSync(join(sweep, 'sweep.json'), JSON.stringify({ software: { name: 'tissue-sheet' } }));
    expect(() => checkOutDir(sweep, [input], false)).not.toThrow();
    symlinkSync(input, join(sweep, 'runs.csv'));
    expect(() => checkOutDir(sweep, [input], true)).toThrow(/would overwrite the input|symbolic link/);
  });
});

describe('output directory lock', () => {
  it('refuses a second holder, naming the first, and takes over a dead one', () => {
    const out = join(dir, 'locked');
    mkdirSync(out);
    const release = lockDirectory(out, () => {});
    expect(() => lockDirectory(out, () => {})).toThrow(new RegExp(`another sweep is writing here \\(process ${process.pid} on ${hostname()}`));
    release();
    writeFileSync(join(out, LOCK_NAME), JSON.stringify({ pid: 2 ** 22 + 12345, host: hostname(), started: 'then' }));
    const warnings: string[] = [];
    const again = lockDirectory(out, (w) => warnings.push(w));
    expect(warnings[0]).toMatch(/no longer runs/);
    again();
  });
});
