import { ConfigError, type MeshSurface } from '../core/config';
import { sampleSurface, type CubeGeometryImage } from '../core/cubemap/sample';
import { checkMesh } from '../core/mesh/check';
import { flipOrientation } from '../core/mesh/generate';
import { MeshParseError, parseMesh } from '../core/mesh/parse';
import { sphericalParameterization, type SphericalParameterization } from '../core/mesh/spherical';
import { signedVolume, type TriangleMesh } from '../core/mesh/types';

/** A mesh file handed over directly (a user's File in the browser, read into memory). */
export interface MeshFile {
  readonly data: ArrayBuffer | string;
  readonly name?: string;
}

/** A checked, outward-oriented mesh, its spherical parameterization and its geometry image. */
export interface PreparedMesh {
  readonly mesh: TriangleMesh;
  readonly parameterization: SphericalParameterization;
  readonly image: CubeGeometryImage;
  readonly parameterizationMs: number;
  readonly samplingMs: number;
}

// No Node typings here: this module is also part of the browser bundle and the library's types.
interface NodeFs {
  readFile(path: string): Promise<Uint8Array>;
}
interface NodePath {
  join(...parts: string[]): string;
  basename(path: string): string;
}
const isNode = () =>
  !!(globalThis as { process?: { versions?: { node?: string } } }).process?.versions?.node && typeof window === 'undefined';

/**
 * Reads `surface.src`: in Node a file path (as given, then under public/meshes/ for a bare
 * name); in a browser a URL. Errors become one-line ConfigErrors on `surface.src`.
 */
export async function readMeshSource(src: string): Promise<MeshFile> {
  if (isNode() && !/^https?:\/\//.test(src)) {
    const fsName = 'node:fs/promises';
    const pathName = 'node:path';
    const fs = (await import(/* @vite-ignore */ fsName)) as NodeFs;
    const path = (await import(/* @vite-ignore */ pathName)) as NodePath;
    const candidates = [src, path.join('public', 'meshes', path.basename(src)), path.join('public', src.replace(/^\/+/, ''))];
    for (const file of candidates) {
      try {
        const buffer = await fs.readFile(file);
        return { data: buffer.buffer.slice(buffer.byteOffset, buffer.byteOffset + buffer.byteLength) as ArrayBuffer, name: file };
      } catch {
        // try the next candidate
      }
    }
    throw new ConfigError('surface.src', `surface.src: cannot read "${src}" (looked in the working directory and public/meshes/); give the path of an .obj, .ply or .stl file`);
  }
  return fetchMeshFile(src);
}

/** Fetches a mesh file from a URL; errors are one-line ConfigErrors on `surface.src`. */
export async function fetchMeshFile(src: string): Promise<MeshFile> {
  let response: Response;
  try {
    response = await fetch(src);
  } catch (error) {
    throw new ConfigError('surface.src', `surface.src: cannot fetch "${src}" (${(error as Error).message}); give a reachable URL of an .obj, .ply or .stl file`);
  }
  if (!response.ok) throw new ConfigError('surface.src', `surface.src: fetching "${src}" gave HTTP ${response.status}; give a reachable URL of an .obj, .ply or .stl file`);
  return { data: await response.arrayBuffer(), name: src };
}

/**
 * Parses, scales and checks a mesh, orients it outward, maps it onto the sphere and samples it
 * into an n-texel cube-map geometry image. Every problem is a one-line ConfigError on
 * `surface.src` naming the file: parse errors, then checkMesh's errors (all of them, "; "-joined,
 * e.g. "genus 1: this mesh has a hole through it ...").
 */
export function prepareMesh(file: MeshFile, surface: MeshSurface, n: number): PreparedMesh {
  const name = file.name ?? surface.src;
  let mesh: TriangleMesh;
  try {
    mesh = parseMesh(file.data, { fileName: name });
  } catch (error) {
    const message = error instanceof MeshParseError ? error.message : (error as Error).message;
    throw new ConfigError('surface.src', `surface.src: ${name}: ${oneLine(message)}`);
  }
  const errors = checkMesh(mesh).filter((p) => p.severity === 'error');
  if (errors.length > 0) {
    throw new ConfigError('surface.src', `surface.src: ${name}: ${errors.map((p) => oneLine(p.message)).join('; ')}`);
  }
  if (surface.scale !== 1) {
    const p = mesh.positions.slice();
    for (let k = 0; k < p.length; k++) p[k] *= surface.scale;
    mesh = { positions: p, indices: mesh.indices };
  }
  if (signedVolume(mesh) < 0) mesh = flipOrientation(mesh);
  const start = performance.now();
  const parameterization = sphericalParameterization(mesh);
  const parameterizationMs = performance.now() - start;
  if (parameterization.flipped > 0) {
    throw new ConfigError('surface.src', `surface.src: ${name}: the spherical parameterization folded ${parameterization.flipped} triangles over; remesh the surface more evenly`);
  }
  const sampleStart = performance.now();
  const image = sampleSurface({ kind: 'mesh', mesh, sphere: parameterization.sphere }, n);
  return { mesh, parameterization, image, parameterizationMs, samplingMs: performance.now() - sampleStart };
}

function oneLine(text: string): string {
  return text.replace(/\s*\n\s*/g, '; ');
}
