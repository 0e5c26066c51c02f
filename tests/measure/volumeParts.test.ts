/** The volume measurement's parts on inputs whose answers are known by hand. */
import { describe, expect, it } from 'vitest';
import { curveLength, lzwDecodeInto, parseVoxelSizeOption, quartetFilter } from '../../src/core/measure';
import { createRandom } from '../../src/core/random';
import { lzwEncode } from './tiffWriter';

describe('LZW decoding', () => {
  it('inverts the TIFF LZW encoder on random, repetitive and long inputs (table resets)', () => {
    const random = createRandom(4);
    const inputs = [
      Uint8Array.from({ length: 3000 }, () => random.nextInt(256)),
      Uint8Array.from({ length: 20000 }, (_, k) => (k >> 7) & 3),
      new Uint8Array(20000).fill(7),
      Uint8Array.from({ length: 20000 }, () => random.nextInt(5)),
    ];
    for (const input of inputs) {
      const out = new Uint8Array(input.length);
      expect(lzwDecodeInto(lzwEncode(input), out)).toBe(input.length);
      expect(out).toEqual(input);
    }
  });

  it('never writes past the expected size', () => {
    const input = new Uint8Array(5000).fill(3);
    const out = new Uint8Array(100);
    expect(lzwDecodeInto(lzwEncode(input), out)).toBe(100);
    expect(out.every((v) => v === 3)).toBe(true);
  });
});

/** A 6-connected staircase from the origin towards (dx, dy, dz) * repeats, as vertex ids on a 1000^2 grid. */
function staircase(dx: number, dy: number, dz: number, repeats: number) {
  const VX = 1000;
  const VXY = 1000 * 1000;
  const id = (x: number, y: number, z: number) => (z * 1000 + y) * VX + x;
  const v0: number[] = [];
  const v1: number[] = [];
  let p = [0, 0, 0];
  const total = [dx * repeats, dy * repeats, dz * repeats];
  const steps = total[0] + total[1] + total[2];
  for (let s = 0; s < steps; s++) {
    // Step along the axis that lags most behind the straight line.
    const t = (s + 1) / steps;
    let axis = 0;
    let lag = -Infinity;
    for (let a = 0; a < 3; a++) {
      const l = total[a] * t - p[a];
      if (p[a] < total[a] && l > lag) (lag = l), (axis = a);
    }
    const q = [...p];
    q[axis]++;
    v0.push(id(p[0], p[1], p[2]));
    v1.push(id(q[0], q[1], q[2]));
    p = q;
  }
  const position = (v: number, out: Float64Array, o: number) => {
    out[o] = v % VX;
    out[o + 1] = Math.floor(v / VX) % 1000;
    out[o + 2] = Math.floor(v / VXY);
  };
  return { v0, v1, list: v0.map((_, k) => k), position, euclid: Math.hypot(total[0], total[1], total[2]), steps };
}

describe('contact curve length', () => {
  it('gives a digital straight line its Euclidean length, not its staircase length', () => {
    for (const [dx, dy, dz] of [
      [1, 1, 0],
      [1, 1, 1],
      [3, 2, 1],
      [5, 1, 0],
      [1, 0, 0],
    ]) {
      const s = staircase(dx, dy, dz, 12);
      const c = curveLength(s.v0, s.v1, s.list, s.position);
      expect(c.staircase).toBe(s.steps);
      expect(c.edges).toBe(s.steps);
      expect(c.pieces).toBe(1);
      expect(Math.abs(c.length / s.euclid - 1)).toBeLessThan(0.02);
    }
  });

  it('counts separate pieces and adds their lengths', () => {
    const a = staircase(1, 1, 0, 10);
    const shifted = a.v1.map((v) => v + 500);
    const v0 = [...a.v0, ...a.v0.map((v) => v + 500)];
    const v1 = [...a.v1, ...shifted];
    const c = curveLength(v0, v1, v0.map((_, k) => k), a.position);
    expect(c.pieces).toBe(2);
    expect(c.length / (2 * a.euclid)).toBeCloseTo(1, 1);
  });
});

describe('quartet filter', () => {
  const sets = (n: number, pairs: [number, number][]) => {
    const s = Array.from({ length: n }, () => new Set<number>());
    for (const [a, b] of pairs) s[a].add(b), s[b].add(a);
    return s;
  };
  it('keeps a T1 exchange confirmed by its quartet and removes a lone one', () => {
    // Cells 0,1 touch basally, 2,3 apically; 2 and 3 touch 0 and 1 on both. 4-5 touch basally only, alone.
    const ring: [number, number][] = [
      [0, 2],
      [0, 3],
      [1, 2],
      [1, 3],
      [4, 0],
      [5, 1],
    ];
    const basal = sets(6, [...ring, [0, 1], [4, 5]]);
    const apical = sets(6, [...ring, [2, 3]]);
    const r = quartetFilter([basal, apical]);
    expect(r.quartets).toEqual([[0, 1, 2, 3]]);
    expect(r.removed).toEqual([[4, 5, 0]]);
    expect([...r.sets[0][4]]).toEqual([0]);
    expect(r.sets[0][0].has(1)).toBe(true);
    expect(r.sets[1][2].has(3)).toBe(true);
  });
});

describe('--voxel-size', () => {
  it('takes three numbers > 0', () => {
    expect(parseVoxelSizeOption('0.2, 0.2,0.5')).toEqual({ x: 0.2, y: 0.2, z: 0.5 });
    for (const bad of ['0.2,0.2', '1,1,0', '1,,1', 'a,b,c', '1,1,1,1', '-1,1,1']) expect(parseVoxelSizeOption(bad)).toBeNull();
  });
});
