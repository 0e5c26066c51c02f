import { readFileSync } from 'node:fs';
import { join } from 'node:path';
import type { Config } from '../../src/core/config';
import { parseMesh } from '../../src/core/mesh/parse';
import { loadMeshFile } from '../../src/node/meshFile';
import type { RunInputs } from '../../src/run';
import { faceAreas, type TriangleMesh } from '../../src/core/mesh/types';

export const MESH_DIR = join(__dirname, '..', '..', 'public', 'meshes');

/** Loads a shipped sample mesh through the real parser (as the app would). */
export function loadShipped(file: string): TriangleMesh {
  const buf = readFileSync(join(MESH_DIR, file));
  const ab = buf.buffer.slice(buf.byteOffset, buf.byteOffset + buf.byteLength) as ArrayBuffer;
  return parseMesh(ab, { fileName: file });
}

export const GENUS_ZERO_SHIPPED = ['organoid.ply', 'egg-chamber.ply', 'level-set-blob.ply'];

/** What a host hands runSheet for a mesh config: the file, loaded by the Node host's loader (the pipeline reads none). */
export function meshInputs(config: Config): RunInputs {
  return config.surface.kind === 'mesh' ? { meshFile: loadMeshFile(config.surface.src) } : {};
}

/** Total area of a mesh's triangles. */
export function surfaceArea(mesh: TriangleMesh): number {
  let s = 0;
  for (const a of faceAreas(mesh)) s += a;
  return s;
}
