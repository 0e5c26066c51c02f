import { describe, expect, it } from 'vitest';
import { meshTopology } from '../../src/core/mesh/check';
import { bumpySphere, icosphere } from '../../src/core/mesh/generate';
import { detectFormat, MeshParseError, parseMesh, weldVertices } from '../../src/core/mesh/parse';
import type { TriangleMesh } from '../../src/core/mesh/types';
import { writePlyAscii } from '../../src/core/mesh/write';
import { writeObj, writePlyBinary, writeStlAscii, writeStlBinary } from './writers';
import { loadShipped, surfaceArea } from './helpers';

const source = bumpySphere(6, 11);
const topo = meshTopology(source);

function expectSameSurface(m: TriangleMesh) {
  const t = meshTopology(m);
  expect(t.vertices).toBe(topo.vertices);
  expect(t.faces).toBe(topo.faces);
  expect(t.edges).toBe(topo.edges);
  expect(t.genus).toBe(0);
  expect(surfaceArea(m)).toBeCloseTo(surfaceArea(source), 4);
}

const enc = (s: string) => new TextEncoder().encode(s).buffer as ArrayBuffer;

describe('parseMesh round trips through the three.js loaders', () => {
  it('OBJ (text and ArrayBuffer)', () => {
    expectSameSurface(parseMesh(writeObj(source), { format: 'obj' }));
    expectSameSurface(parseMesh(enc(writeObj(source)), { fileName: 'a.OBJ' }));
  });
  it('PLY ascii and binary', () => {
    expectSameSurface(parseMesh(enc(writePlyAscii(source)), { fileName: 'x.ply' }));
    expectSameSurface(parseMesh(writePlyBinary(source), { fileName: 'x.ply' }));
  });
  it('STL ascii and binary: no shared vertices in the file, welding restores the topology', () => {
    const bin = writeStlBinary(source);
    expect(bin.byteLength).toBe(84 + 50 * topo.faces);
    expectSameSurface(parseMesh(bin, { fileName: 'x.stl' }));
    expectSameSurface(parseMesh(enc(writeStlAscii(source)), { fileName: 'x.stl' }));
  });
  it('detects the format from the content when there is no file name', () => {
    expect(detectFormat(writePlyBinary(source))).toBe('ply');
    expect(detectFormat(writeStlBinary(source))).toBe('stl');
    expect(detectFormat(enc(writeStlAscii(source)))).toBe('stl');
    expect(detectFormat(writeObj(source))).toBe('obj');
  });
  it('loads the shipped meshes', () => {
    expect(meshTopology(loadShipped('level-set-blob.ply')).vertices).toBe(9002);
    expect(meshTopology(loadShipped('torus.ply')).genus).toBe(1);
  });
});

describe('weldVertices', () => {
  it('merges copies closer than the relative tolerance and keeps distinct points', () => {
    const s = icosphere(3);
    const nv = s.positions.length / 3;
    // Every triangle with its own corners, jittered by 1e-6 (tolerance: 1e-6 × diagonal 3.46).
    const pos = new Float32Array(s.indices.length * 3);
    s.indices.forEach((v, k) => {
      for (let c = 0; c < 3; c++) pos[3 * k + c] = s.positions[3 * v + c] + (c === 0 && k % 3 === 1 ? 1e-6 : 0);
    });
    const soup = { positions: pos, indices: Uint32Array.from(s.indices, (_, k) => k) };
    expect(weldVertices(soup).positions.length / 3).toBe(nv);
    expect(weldVertices(soup, 1e-9).positions.length / 3).toBeGreaterThan(nv); // too tight: nothing merges
  });
});

describe('corrupt files get a message naming the format and what failed', () => {
  const expectError = (f: () => unknown, format: RegExp, what: RegExp) => {
    try {
      f();
    } catch (e) {
      expect(e).toBeInstanceOf(MeshParseError);
      expect((e as Error).message).toMatch(format);
      expect((e as Error).message).toMatch(what);
      return;
    }
    throw new Error('expected a MeshParseError');
  };
  it('truncated binary STL', () => {
    const bin = writeStlBinary(source).slice(0, 84 + 50 * 10 + 7);
    expectError(() => parseMesh(bin, { fileName: 'x.stl' }), /^STL \(binary\)/, /does not match .*truncated/);
  });
  it('ascii STL with a missing vertex line', () => {
    const text = writeStlAscii(source).replace(/\n\s*vertex [^\n]*/, '');
    expectError(() => parseMesh(enc(text), { fileName: 'x.stl' }), /^STL \(ascii\)/, /vertex x y z/);
  });
  it('PLY without end_header, truncated binary PLY, truncated ascii PLY', () => {
    expectError(() => parseMesh(enc('ply\nformat ascii 1.0\nelement vertex 3\n'), { fileName: 'x.ply' }), /^PLY/, /end_header/);
    const bin = writePlyBinary(source);
    expectError(() => parseMesh(bin.slice(0, bin.byteLength - 100), { fileName: 'x.ply' }), /^PLY \(binary_little_endian\)/, /truncated|could not read/);
    const text = writePlyAscii(source).split('\n').slice(0, 20).join('\n');
    expectError(() => parseMesh(enc(text), { fileName: 'x.ply' }), /^PLY \(ascii\)/, /vertices|could not read|face/);
  });
  it('OBJ with a face referring to a missing vertex, or no faces', () => {
    expectError(() => parseMesh('v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n', { format: 'obj' }), /^OBJ/, /line 4: face refers to vertex "9"/);
    expectError(() => parseMesh('v 0 0 0\nv 1 0 0\n', { format: 'obj' }), /^OBJ/, /no faces/);
    expectError(() => parseMesh('v 0 zero 0\nf 1 1 1\n', { format: 'obj' }), /^OBJ/, /line 1: a vertex needs 3 numeric coordinates/);
  });
  it('unknown content', () => {
    expectError(() => parseMesh(enc('hello world, this is not a mesh')), /^mesh/, /unknown format/);
  });
});
