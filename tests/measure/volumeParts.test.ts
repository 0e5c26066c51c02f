/** The volume measurement's parts on inputs whose answers are known by hand. */
import { deflateSync } from 'node:zlib';
import { describe, expect, it } from 'vitest';
import {
  carryAlongNormals,
  curveLength,
  decodeVolumeTiff,
  inspectVolumeTiff,
  lzwDecodeInto,
  maskSurfaceMesh,
  parseVoxelSizeOption,
  prepareMesh,
  quartetFilter,
  randomSitesOnMesh,
} from '../../src/core/measure';
import { meshArea, signedVolume } from '../../src/core/mesh/types';
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
      if (p[a] < total[a] && l > lag) {
        lag = l;
        axis = a;
      }
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
    const c = curveLength(
      v0,
      v1,
      v0.map((_, k) => k),
      a.position,
    );
    expect(c.pieces).toBe(2);
    expect(c.length / (2 * a.euclid)).toBeCloseTo(1, 1);
  });
});

describe('quartet filter', () => {
  const sets = (n: number, pairs: [number, number][]) => {
    const s = Array.from({ length: n }, () => new Set<number>());
    for (const [a, b] of pairs) {
      s[a].add(b);
      s[b].add(a);
    }
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

/**
 * A tiled TIFF of 16-bit pages (tiles 16 x 16, the edge tiles padded), uncompressed or Deflate,
 * optionally with horizontal differencing (predictor 2): what tiffWriter.ts does not write.
 */
function tiledTiff(width: number, height: number, pages: Uint16Array[], options: { deflate: boolean; predictor: boolean; littleEndian: boolean }): Uint8Array {
  const T = 16;
  const across = Math.ceil(width / T);
  const down = Math.ceil(height / T);
  const le = options.littleEndian;
  const chunks: Uint8Array[] = [];
  let size = 8;
  const append = (b: Uint8Array) => {
    const at = size;
    chunks.push(b);
    size += b.length;
    return at;
  };
  const header = new Uint8Array(8);
  header[0] = header[1] = le ? 0x49 : 0x4d;
  new DataView(header.buffer).setUint16(2, 42, le);
  chunks.push(header);
  let nextPointer: [Uint8Array, number] = [header, 4];
  for (const page of pages) {
    const offsets: number[] = [];
    const counts: number[] = [];
    for (let ty = 0; ty < down; ty++) {
      for (let tx = 0; tx < across; tx++) {
        const tile = new Uint16Array(T * T);
        for (let y = 0; y < T; y++)
          for (let x = 0; x < T; x++) if (ty * T + y < height && tx * T + x < width) tile[y * T + x] = page[(ty * T + y) * width + tx * T + x];
        if (options.predictor) for (let y = 0; y < T; y++) for (let x = T - 1; x > 0; x--) tile[y * T + x] = (tile[y * T + x] - tile[y * T + x - 1]) & 0xffff;
        const raw = new Uint8Array(2 * T * T);
        const view = new DataView(raw.buffer);
        tile.forEach((v, k) => view.setUint16(2 * k, v, le));
        const stored = options.deflate ? new Uint8Array(deflateSync(raw)) : raw;
        offsets.push(append(stored));
        counts.push(stored.length);
      }
    }
    const offsetArray = append(new Uint8Array(4 * offsets.length));
    const countArray = append(new Uint8Array(4 * counts.length));
    const oa = chunks[chunks.length - 2];
    const ca = chunks[chunks.length - 1];
    offsets.forEach((o, k) => new DataView(oa.buffer).setUint32(4 * k, o, le));
    counts.forEach((c, k) => new DataView(ca.buffer).setUint32(4 * k, c, le));
    const entries: [number, number, number, number][] = [
      [256, 4, 1, width],
      [257, 4, 1, height],
      [258, 3, 1, 16],
      [259, 3, 1, options.deflate ? 8 : 1],
      [262, 3, 1, 1],
      [277, 3, 1, 1],
      [317, 3, 1, options.predictor ? 2 : 1],
      [322, 3, 1, T],
      [323, 3, 1, T],
      [324, 4, offsets.length, offsets.length === 1 ? offsets[0] : offsetArray],
      [325, 4, counts.length, counts.length === 1 ? counts[0] : countArray],
    ];
    const ifd = new Uint8Array(2 + 12 * entries.length + 4);
    const v = new DataView(ifd.buffer);
    v.setUint16(0, entries.length, le);
    entries.forEach(([tag, type, count, value], e) => {
      v.setUint16(2 + 12 * e, tag, le);
      v.setUint16(4 + 12 * e, type, le);
      v.setUint32(6 + 12 * e, count, le);
      if (type === 3 && count === 1) v.setUint16(10 + 12 * e, value, le);
      else v.setUint32(10 + 12 * e, value, le);
    });
    const at = append(ifd);
    new DataView(nextPointer[0].buffer).setUint32(nextPointer[1], at, le);
    nextPointer = [ifd, ifd.length - 4];
  }
  const out = new Uint8Array(size);
  let o = 0;
  for (const c of chunks) out.set(c, (o += c.length) - c.length);
  return out;
}

describe('volume TIFF decoding', () => {
  it('reads tiled pages (padded edge tiles), Deflate, horizontal differencing, either byte order', () => {
    const width = 37;
    const height = 21;
    const random = createRandom(9);
    const pages = Array.from({ length: 3 }, () => Uint16Array.from({ length: width * height }, () => random.nextInt(65536)));
    for (const deflate of [false, true]) {
      for (const predictor of [false, true]) {
        for (const littleEndian of [true, false]) {
          const bytes = tiledTiff(width, height, pages, { deflate, predictor, littleEndian });
          const header = inspectVolumeTiff(bytes, 't.tif');
          expect([header.width, header.height, header.depth, header.bitsPerSample]).toEqual([width, height, 3, 16]);
          const volume = decodeVolumeTiff(bytes, 't.tif', header);
          pages.forEach((page, z) => expect(Array.from(volume.data.subarray(z * width * height, (z + 1) * width * height))).toEqual(Array.from(page)));
        }
      }
    }
  });
});

describe('surface meshes of a classified volume', () => {
  it('gives a voxelized sphere a closed, outward mesh of its area and volume', () => {
    const voxel = { x: 0.5, y: 0.5, z: 1 };
    const [W, H, D] = [60, 60, 30];
    const R = 11;
    const classes = new Uint8Array(W * H * D);
    for (let z = 0; z < D; z++) {
      for (let y = 0; y < H; y++) {
        for (let x = 0; x < W; x++) {
          const r = Math.hypot((x + 0.5) * voxel.x - 15, (y + 0.5) * voxel.y - 15, (z + 0.5) * voxel.z - 15);
          classes[(z * H + y) * W + x] = r < R ? 2 : 1;
        }
      }
    }
    const mesh = maskSurfaceMesh(classes, W, H, D, voxel, (c) => c === 2, 1.5);
    expect(mesh.blocks).toEqual([3, 3, 2]);
    // Closed: every edge in exactly two triangles, once each way.
    const edges = new Map<string, number>();
    for (let t = 0; t < mesh.indices.length; t += 3) {
      for (let e = 0; e < 3; e++) {
        const key = `${mesh.indices[t + e]},${mesh.indices[t + ((e + 1) % 3)]}`;
        edges.set(key, (edges.get(key) ?? 0) + 1);
      }
    }
    for (const [key, n] of edges) {
      expect(n).toBe(1);
      const [a, b] = key.split(',');
      expect(edges.get(`${b},${a}`)).toBe(1);
    }
    expect(Math.abs(meshArea(mesh.positions, mesh.indices) / (4 * Math.PI * R * R) - 1)).toBeLessThan(0.03);
    expect(Math.abs(signedVolume(mesh) / ((4 / 3) * Math.PI * R ** 3) - 1)).toBeLessThan(0.03);
  });
});

describe('sites carried along the normal to the other surface', () => {
  it('meet the other mesh where the ray reaches it, else land at the local thickness (the parallel surface)', () => {
    const [W, H, D] = [48, 48, 48];
    const classes = new Uint8Array(W * H * D);
    for (let z = 0; z < D; z++) {
      for (let y = 0; y < H; y++) {
        for (let x = 0; x < W; x++) {
          const r = Math.hypot(x + 0.5 - 24, y + 0.5 - 24, z + 0.5 - 24);
          classes[(z * H + y) * W + x] = r < 10 ? 2 : r < 18 ? 0 : 1;
        }
      }
    }
    const voxel = { x: 1, y: 1, z: 1 };
    const inner = prepareMesh(maskSurfaceMesh(classes, W, H, D, voxel, (c) => c === 2, 1.5));
    const outer = prepareMesh(maskSurfaceMesh(classes, W, H, D, voxel, (c) => c !== 1, 1.5));
    const sites = randomSitesOnMesh(inner, 30, 2, 4);
    const radius = (p: Float64Array, i: number) => Math.hypot(p[3 * i] - 24, p[3 * i + 1] - 24, p[3 * i + 2] - 24);
    const hit = carryAlongNormals(inner, sites, outer, 20, () => 5);
    expect([hit.alongNormal, hit.parallel]).toEqual([30, 0]);
    for (let i = 0; i < 30; i++) expect(Math.abs(radius(hit.sites, i) - 18)).toBeLessThan(0.6);
    const missed = carryAlongNormals(inner, sites, outer, 3, () => 5);
    expect([missed.alongNormal, missed.parallel]).toEqual([0, 30]);
    for (let i = 0; i < 30; i++) expect(Math.abs(radius(missed.sites, i) - 15)).toBeLessThan(0.6);
  });
});

describe('contact curve length of a closed loop', () => {
  it('gives a digital circle (a cell enclosed by one other) its circumference, not less', () => {
    for (const R of [4, 10, 25]) {
      // The boundary of the pixels inside the circle, as a loop of pixel edges in the z = 0 plane.
      const inside = (x: number, y: number) => Math.hypot(x + 0.5, y + 0.5) < R;
      const v0: number[] = [];
      const v1: number[] = [];
      const id = (x: number, y: number) => (y + 100) * 1000 + (x + 100);
      for (let y = -R - 2; y <= R + 2; y++) {
        for (let x = -R - 2; x <= R + 2; x++) {
          if (inside(x, y) !== inside(x + 1, y)) {
            v0.push(id(x + 1, y));
            v1.push(id(x + 1, y + 1));
          }
          if (inside(x, y) !== inside(x, y + 1)) {
            v0.push(id(x, y + 1));
            v1.push(id(x + 1, y + 1));
          }
        }
      }
      const position = (v: number, out: Float64Array, o: number) => {
        out[o] = (v % 1000) - 100;
        out[o + 1] = Math.floor(v / 1000) - 100;
        out[o + 2] = 0;
      };
      const c = curveLength(
        v0,
        v1,
        v0.map((_, k) => k),
        position,
      );
      expect(c.pieces).toBe(1);
      expect(Math.abs(c.length / (2 * Math.PI * R) - 1)).toBeLessThan(R < 5 ? 0.12 : 0.03);
      expect(c.staircase / (2 * Math.PI * R)).toBeGreaterThan(1.15);
    }
  });
});
