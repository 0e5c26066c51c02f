/**
 * Writers for the formats `parseMesh` reads besides ASCII PLY (src/core/mesh/write.ts), so the
 * tests round-trip every format through the three.js loaders instead of trusting hand-written
 * fixture files.
 */
import { triangleCross, type TriangleMesh } from '../../src/core/mesh/types';
import { formatCoordinate } from '../../src/core/mesh/write';

export function writePlyBinary(mesh: TriangleMesh): ArrayBuffer {
  const nv = mesh.positions.length / 3;
  const nf = mesh.indices.length / 3;
  const header = new TextEncoder().encode(
    `ply\nformat binary_little_endian 1.0\nelement vertex ${nv}\nproperty float x\nproperty float y\nproperty float z\nelement face ${nf}\nproperty list uchar int vertex_indices\nend_header\n`,
  );
  const buf = new ArrayBuffer(header.length + nv * 12 + nf * 13);
  new Uint8Array(buf).set(header);
  const dv = new DataView(buf);
  let o = header.length;
  for (let i = 0; i < nv * 3; i++, o += 4) dv.setFloat32(o, mesh.positions[i], true);
  for (let f = 0; f < nf; f++) {
    dv.setUint8(o++, 3);
    for (let k = 0; k < 3; k++, o += 4) dv.setInt32(o, mesh.indices[3 * f + k], true);
  }
  return buf;
}

function faceNormal(mesh: TriangleMesh, f: number): [number, number, number] {
  const p = mesh.positions,
    t = mesh.indices;
  const n = triangleCross(p, t, f, new Float64Array(3));
  const l = Math.hypot(n[0], n[1], n[2]) || 1;
  return [n[0] / l, n[1] / l, n[2] / l];
}

/** Binary STL: 80-byte header, uint32 count, then 50 bytes per triangle (no shared vertices). */
export function writeStlBinary(mesh: TriangleMesh): ArrayBuffer {
  const nf = mesh.indices.length / 3;
  const buf = new ArrayBuffer(84 + 50 * nf);
  const dv = new DataView(buf);
  new Uint8Array(buf).set(new TextEncoder().encode('binary STL written by tissue-sheet'));
  dv.setUint32(80, nf, true);
  let o = 84;
  for (let f = 0; f < nf; f++) {
    for (const x of faceNormal(mesh, f)) {
      dv.setFloat32(o, x, true);
      o += 4;
    }
    for (let k = 0; k < 3; k++) {
      const v = mesh.indices[3 * f + k];
      for (let c = 0; c < 3; c++, o += 4) dv.setFloat32(o, mesh.positions[3 * v + c], true);
    }
    o += 2;
  }
  return buf;
}

export function writeStlAscii(mesh: TriangleMesh, name = 'tissue_sheet'): string {
  const out = [`solid ${name}`];
  const nf = mesh.indices.length / 3;
  const p = mesh.positions;
  for (let f = 0; f < nf; f++) {
    out.push(`  facet normal ${faceNormal(mesh, f).map(formatCoordinate).join(' ')}`, '    outer loop');
    for (let k = 0; k < 3; k++) {
      const v = mesh.indices[3 * f + k];
      out.push(`      vertex ${formatCoordinate(p[3 * v])} ${formatCoordinate(p[3 * v + 1])} ${formatCoordinate(p[3 * v + 2])}`);
    }
    out.push('    endloop', '  endfacet');
  }
  out.push(`endsolid ${name}`);
  return out.join('\n') + '\n';
}

export function writeObj(mesh: TriangleMesh): string {
  const out = ['# written by tissue-sheet'];
  const p = mesh.positions,
    t = mesh.indices;
  for (let i = 0; i < p.length; i += 3) out.push(`v ${formatCoordinate(p[i])} ${formatCoordinate(p[i + 1])} ${formatCoordinate(p[i + 2])}`);
  for (let f = 0; f < t.length; f += 3) out.push(`f ${t[f] + 1} ${t[f + 1] + 1} ${t[f + 2] + 1}`);
  return out.join('\n') + '\n';
}
