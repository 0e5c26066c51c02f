/**
 * Reading OBJ, PLY (ascii / binary) and STL (ascii / binary) into a welded TriangleMesh.
 *
 * The actual decoding is done by the three.js example loaders (they are maintained, handle
 * the many dialects of these formats and run in Node). Around them we add what the loaders
 * do not do, because a biologist's file is often broken in ways that would otherwise surface
 * as a silent NaN much later:
 * - a pre-check of each format's structure, so a corrupt file is rejected with a message that
 *   names the format and what failed (MeshParseError);
 * - welding of duplicate vertices: STL stores every triangle with its own 3 corners, and OBJ /
 *   PLY exporters split vertices at UV or normal seams; without welding no mesh would be
 *   "closed" and the topology checks and Laplacians would be meaningless.
 */
import type { BufferGeometry } from 'three';
import { OBJLoader } from 'three/examples/jsm/loaders/OBJLoader.js';
import { PLYLoader } from 'three/examples/jsm/loaders/PLYLoader.js';
import { STLLoader } from 'three/examples/jsm/loaders/STLLoader.js';
import { boundingBox, mergeMeshes, type TriangleMesh } from './types';

export type MeshFormat = 'obj' | 'ply' | 'stl';

/** A file that could not be read as a mesh; `format` says which reader rejected it. */
export class MeshParseError extends Error {
  constructor(
    readonly format: string,
    detail: string,
  ) {
    super(`${format}: ${detail}`);
    this.name = 'MeshParseError';
  }
}

export interface ParseOptions {
  /** Format; if omitted it is taken from `fileName`'s extension, else sniffed from the content. */
  format?: MeshFormat;
  fileName?: string;
  /**
   * Welding tolerance relative to the bounding-box diagonal (default 1e-6). Relative because
   * meshes come in µm, mm or unit-less coordinates; 1e-6 is far above float32 rounding of
   * re-exported coordinates and far below any real edge length.
   */
  weldTolerance?: number;
}

const decoder = new TextDecoder();

function asText(data: ArrayBuffer | string): string {
  return typeof data === 'string' ? data : decoder.decode(new Uint8Array(data));
}

/** Guesses the format from the file name, then from the first bytes. */
export function detectFormat(data: ArrayBuffer | string, fileName?: string): MeshFormat {
  const ext = fileName?.toLowerCase().match(/\.(obj|ply|stl)$/)?.[1];
  if (ext) return ext as MeshFormat;
  const head = typeof data === 'string' ? data.slice(0, 512) : decoder.decode(new Uint8Array(data, 0, Math.min(512, data.byteLength)));
  if (/^ply\s/.test(head)) return 'ply';
  if (typeof data !== 'string' && data.byteLength >= 84) {
    const count = new DataView(data).getUint32(80, true);
    if (84 + 50 * count === data.byteLength) return 'stl';
  }
  if (/^\s*solid[\s\S]*facet/.test(head)) return 'stl';
  if (/^\s*(v|f|o|g|#|vn|vt|mtllib)\s/m.test(head)) return 'obj';
  throw new MeshParseError('mesh', 'unknown format: not PLY (no "ply" magic), not STL, not OBJ (no "v"/"f" lines); give a .obj, .ply or .stl file');
}

/** Parses a mesh file and welds duplicate vertices. Throws MeshParseError on a corrupt file. */
export function parseMesh(data: ArrayBuffer | string, options: ParseOptions = {}): TriangleMesh {
  const format = options.format ?? detectFormat(data, options.fileName);
  let geometry: BufferGeometry;
  let label: string = format.toUpperCase();
  if (format === 'obj') {
    const text = asText(data);
    precheckObj(text);
    let group;
    try {
      group = new OBJLoader().parse(text);
    } catch (e) {
      throw new MeshParseError('OBJ', `the three.js OBJ loader failed: ${(e as Error).message}`);
    }
    const parts: BufferGeometry[] = [];
    group.traverse((o) => {
      const g = (o as { geometry?: BufferGeometry }).geometry;
      if (g && (o as { isMesh?: boolean }).isMesh) parts.push(g);
    });
    if (parts.length === 0) throw new MeshParseError('OBJ', 'no faces ("f" lines) found');
    return weldVertices(concatGeometries(parts, 'OBJ'), options.weldTolerance);
  } else if (format === 'ply') {
    const header = precheckPly(data);
    label = `PLY (${header.format})`;
    try {
      geometry = new PLYLoader().parse(data as ArrayBuffer);
    } catch (e) {
      throw new MeshParseError(label, `could not read the data after the header (truncated or corrupt file?): ${(e as Error).message}`);
    }
    const nv = geometry.getAttribute('position')?.count ?? 0;
    if (nv !== header.vertices) {
      throw new MeshParseError(label, `the header declares ${header.vertices} vertices but ${nv} could be read (truncated file?)`);
    }
    if (header.faces === 0) throw new MeshParseError(label, 'the file has no faces (a point cloud is not a surface)');
  } else {
    label = precheckStl(data);
    try {
      geometry = new STLLoader().parse(data as ArrayBuffer);
    } catch (e) {
      throw new MeshParseError(label, `could not read the triangles: ${(e as Error).message}`);
    }
  }
  return weldVertices(geometryToMesh(geometry, label), options.weldTolerance);
}

function geometryToMesh(g: BufferGeometry, label: string): TriangleMesh {
  const pos = g.getAttribute('position');
  if (!pos || pos.count === 0) throw new MeshParseError(label, 'no vertices found');
  const positions = new Float32Array(pos.count * 3);
  for (let i = 0; i < pos.count; i++) {
    positions[3 * i] = pos.getX(i);
    positions[3 * i + 1] = pos.getY(i);
    positions[3 * i + 2] = pos.getZ(i);
  }
  let indices: Uint32Array;
  const idx = g.getIndex();
  if (idx) {
    indices = new Uint32Array(idx.count);
    for (let i = 0; i < idx.count; i++) indices[i] = idx.getX(i);
  } else {
    indices = new Uint32Array(pos.count);
    for (let i = 0; i < pos.count; i++) indices[i] = i;
  }
  if (indices.length === 0 || indices.length % 3 !== 0) throw new MeshParseError(label, `no complete triangles found (${indices.length} indices)`);
  for (let i = 0; i < positions.length; i++) {
    if (!Number.isFinite(positions[i])) {
      throw new MeshParseError(label, `vertex ${Math.floor(i / 3)} has a non-finite coordinate (${positions[i]})`);
    }
  }
  for (let i = 0; i < indices.length; i++) {
    if (indices[i] >= pos.count) {
      throw new MeshParseError(label, `face ${Math.floor(i / 3)} refers to vertex ${indices[i]} but there are only ${pos.count} vertices`);
    }
  }
  return { positions, indices };
}

function concatGeometries(parts: BufferGeometry[], label: string): TriangleMesh {
  return mergeMeshes(...parts.map((g) => geometryToMesh(g, label)));
}

function precheckObj(text: string): void {
  let nv = 0;
  let nf = 0;
  const lines = text.split(/\r?\n/);
  for (let ln = 0; ln < lines.length; ln++) {
    const line = lines[ln].trim();
    if (line.startsWith('v ')) {
      const parts = line.split(/\s+/);
      if (parts.length < 4 || parts.slice(1, 4).some((s) => !Number.isFinite(Number(s)))) {
        throw new MeshParseError('OBJ', `line ${ln + 1}: a vertex needs 3 numeric coordinates, got "${line.slice(0, 60)}"`);
      }
      nv++;
    } else if (line.startsWith('f ')) {
      const refs = line.split(/\s+/).slice(1);
      if (refs.length < 3) throw new MeshParseError('OBJ', `line ${ln + 1}: a face needs at least 3 vertices, got "${line.slice(0, 60)}"`);
      for (const r of refs) {
        const k = parseInt(r.split('/')[0], 10);
        const abs = k < 0 ? nv + k + 1 : k;
        if (!Number.isFinite(k) || k === 0 || abs < 1 || abs > nv) {
          throw new MeshParseError('OBJ', `line ${ln + 1}: face refers to vertex "${r}" but only ${nv} vertices are defined before it`);
        }
      }
      nf++;
    }
  }
  if (nv === 0) throw new MeshParseError('OBJ', 'no vertices ("v x y z" lines) found');
  if (nf === 0) throw new MeshParseError('OBJ', 'no faces ("f" lines) found');
}

interface PlyHeader {
  format: string;
  vertices: number;
  faces: number;
}

function precheckPly(data: ArrayBuffer | string): PlyHeader {
  const head = typeof data === 'string' ? data.slice(0, 4096) : decoder.decode(new Uint8Array(data, 0, Math.min(4096, data.byteLength)));
  if (!head.startsWith('ply')) throw new MeshParseError('PLY', 'the file does not start with the "ply" magic word');
  const end = head.indexOf('end_header');
  if (end < 0) throw new MeshParseError('PLY', 'the header has no "end_header" line (truncated or not a PLY file)');
  const lines = head
    .slice(0, end)
    .split(/\r?\n/)
    .map((l) => l.trim());
  const fmt = lines.find((l) => l.startsWith('format '));
  if (!fmt) throw new MeshParseError('PLY', 'the header has no "format" line');
  const format = fmt.split(/\s+/)[1];
  if (!['ascii', 'binary_little_endian', 'binary_big_endian'].includes(format)) {
    throw new MeshParseError('PLY', `unknown format "${format}" (expected ascii, binary_little_endian or binary_big_endian)`);
  }
  if (typeof data === 'string' && format !== 'ascii') {
    throw new MeshParseError(`PLY (${format})`, 'a binary PLY must be given as an ArrayBuffer, not a string');
  }
  let vertices = -1;
  let faces = 0;
  for (const l of lines) {
    const m = l.match(/^element\s+(\S+)\s+(\d+)/);
    if (m?.[1] === 'vertex') vertices = Number(m[2]);
    if (m?.[1] === 'face') faces = Number(m[2]);
  }
  if (vertices < 0) throw new MeshParseError(`PLY (${format})`, 'the header declares no "element vertex"');
  return { format, vertices, faces };
}

function precheckStl(data: ArrayBuffer | string): string {
  if (typeof data !== 'string' && data.byteLength >= 84) {
    const count = new DataView(data).getUint32(80, true);
    const head = decoder.decode(new Uint8Array(data, 0, Math.min(256, data.byteLength)));
    const looksAscii = /^\s*solid/.test(head) && /facet|endsolid/.test(head);
    if (!looksAscii) {
      if (84 + 50 * count !== data.byteLength) {
        throw new MeshParseError(
          'STL (binary)',
          `file size ${data.byteLength} bytes does not match the 84 + 50 × ${count} = ${84 + 50 * count} bytes its header announces (truncated or corrupt file)`,
        );
      }
      if (count === 0) throw new MeshParseError('STL (binary)', 'the file declares 0 triangles');
      return 'STL (binary)';
    }
  } else if (typeof data !== 'string' && !/^\s*solid/.test(asText(data))) {
    throw new MeshParseError('STL (binary)', `file of ${data.byteLength} bytes is shorter than the 84-byte binary header`);
  }
  const text = asText(data);
  if (!/^\s*solid/.test(text)) throw new MeshParseError('STL (ascii)', 'the file does not start with "solid"');
  const facets = (text.match(/\bfacet\b/g) ?? []).length;
  const verts = text.match(/\bvertex\s+\S+\s+\S+\s+\S+/g) ?? [];
  if (facets === 0) throw new MeshParseError('STL (ascii)', 'no "facet" found');
  if (verts.length !== 3 * facets) {
    throw new MeshParseError('STL (ascii)', `${facets} facets need ${3 * facets} "vertex x y z" lines, found ${verts.length} (truncated file?)`);
  }
  for (const v of verts) {
    if (
      v
        .split(/\s+/)
        .slice(1)
        .some((s) => !Number.isFinite(Number(s)))
    ) {
      throw new MeshParseError('STL (ascii)', `non-numeric vertex "${v.slice(0, 60)}"`);
    }
  }
  return 'STL (ascii)';
}

/**
 * Merges vertices closer than `relativeTolerance` × bounding-box diagonal and drops vertices
 * no face uses. Uses a hash grid with cells of the tolerance size (checking the 27 cells
 * around a vertex), so it is O(V) and does not depend on the input order.
 * Faces are kept as they are, even if welding makes them degenerate: `checkMesh` reports them,
 * silently deleting them would hide a broken file.
 */
export function weldVertices(mesh: TriangleMesh, relativeTolerance = 1e-6): TriangleMesh {
  const { positions: p, indices } = mesh;
  const nv = p.length / 3;
  const tol = Math.max(boundingBox(p).diagonal * relativeTolerance, 1e-30);
  const tol2 = tol * tol;
  const cell = new Map<string, number[]>();
  const remap = new Int32Array(nv).fill(-1);
  const kept: number[] = [];
  const used = new Uint8Array(nv);
  for (const i of indices) used[i] = 1;
  for (let i = 0; i < nv; i++) {
    if (!used[i]) continue;
    const x = p[3 * i],
      y = p[3 * i + 1],
      z = p[3 * i + 2];
    const cx = Math.floor(x / tol),
      cy = Math.floor(y / tol),
      cz = Math.floor(z / tol);
    let found = -1;
    search: for (let dx = -1; dx <= 1; dx++) {
      for (let dy = -1; dy <= 1; dy++) {
        for (let dz = -1; dz <= 1; dz++) {
          const list = cell.get(`${cx + dx},${cy + dy},${cz + dz}`);
          if (!list) continue;
          for (const k of list) {
            const j = kept[k];
            const ex = p[3 * j] - x,
              ey = p[3 * j + 1] - y,
              ez = p[3 * j + 2] - z;
            if (ex * ex + ey * ey + ez * ez <= tol2) {
              found = k;
              break search;
            }
          }
        }
      }
    }
    if (found < 0) {
      found = kept.length;
      kept.push(i);
      const key = `${cx},${cy},${cz}`;
      const list = cell.get(key);
      if (list) list.push(found);
      else cell.set(key, [found]);
    }
    remap[i] = found;
  }
  const positions = new Float32Array(kept.length * 3);
  kept.forEach((j, k) => {
    positions[3 * k] = p[3 * j];
    positions[3 * k + 1] = p[3 * j + 1];
    positions[3 * k + 2] = p[3 * j + 2];
  });
  const out = new Uint32Array(indices.length);
  for (let i = 0; i < indices.length; i++) out[i] = remap[indices[i]];
  return { positions, indices: out };
}
