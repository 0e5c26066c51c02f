/**
 * The Node host's mesh loader: reads `surface.src` from disk for the pipeline, which reads no
 * file itself (a run gets the bytes as `meshFile`). The CLI and Node library users load meshes
 * here; the page loads them through its source gate (src/view/sources.ts). Same size limit
 * everywhere (core/inputLimits.ts), checked before the file is read.
 */
import { existsSync, readFileSync, statSync } from 'node:fs';
import { basename, dirname, join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';
import { ConfigError } from '../core/config';
import { MAX_MESH_BYTES } from '../core/inputLimits';
import type { MeshFile } from '../run/index';

/**
 * The mesh file `src` names: a path relative to `baseDir` (a config file's directory), else to
 * the working directory, else one of the package's sample meshes (public/meshes/) by its file
 * name, wherever the command runs. One-line
 * ConfigErrors on `surface.src`.
 */
export function loadMeshFile(src: string, baseDir = '.'): MeshFile {
  const samples = samplesDirectory();
  const candidates = [resolve(baseDir, src), resolve(src), ...(samples ? [join(samples, basename(src))] : [])];
  const path = candidates.find((p) => existsSync(p));
  if (!path) {
    throw new ConfigError(
      'surface.src',
      `surface.src: cannot find "${src}" (looked next to the config, in the working directory and among the samples${samples ? ` in ${samples}` : ''}); give the path of an .obj, .ply or .stl file`,
    );
  }
  const stat = statSync(path);
  if (stat.isDirectory()) throw new ConfigError('surface.src', `surface.src: ${path} is a directory; give the path of an .obj, .ply or .stl file`);
  if (stat.size === 0) throw new ConfigError('surface.src', `surface.src: ${path} is empty; give an .obj, .ply or .stl file`);
  if (stat.size > MAX_MESH_BYTES)
    throw new ConfigError('surface.src', `surface.src: ${path} is ${stat.size} bytes, more than the ${MAX_MESH_BYTES} allowed; simplify the mesh`);
  const bytes = readFileSync(path);
  return { data: bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer, name: path };
}

/**
 * The package's sample meshes (public/meshes/, shipped with the npm package), found from this
 * module's own location, whatever the working directory: the first folder above it that holds
 * the package's package.json. Null when there is none (a bundle copied elsewhere).
 */
function samplesDirectory(): string | null {
  let dir = dirname(fileURLToPath(import.meta.url));
  for (let up = 0; up < 6; up++) {
    const meshes = join(dir, 'public', 'meshes');
    if (existsSync(join(dir, 'package.json')) && existsSync(meshes)) return meshes;
    const parent = dirname(dir);
    if (parent === dir) break;
    dir = parent;
  }
  return null;
}
