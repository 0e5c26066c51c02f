import { ConfigError, type MeshSurface } from '../core/config';
import { MAX_MESH_BYTES } from '../core/inputLimits';
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

/**
 * A browser library user's mesh loader: fetches `src` (a URL the caller chose) with the size
 * limit every host shares; errors are one-line ConfigErrors on `surface.src`. The pipeline never
 * calls it: hosts load inputs and hand them to runSheet as `meshFile`.
 */
export async function fetchMeshFile(src: string): Promise<MeshFile> {
  let response: Response;
  try {
    response = await fetch(src);
  } catch (error) {
    throw new ConfigError(
      'surface.src',
      `surface.src: cannot fetch "${src}" (${(error as Error).message}); give a reachable URL of an .obj, .ply or .stl file`,
    );
  }
  if (!response.ok)
    throw new ConfigError('surface.src', `surface.src: fetching "${src}" gave HTTP ${response.status}; give a reachable URL of an .obj, .ply or .stl file`);
  const declared = Number(response.headers.get('content-length') ?? 0);
  if (declared > MAX_MESH_BYTES)
    throw new ConfigError('surface.src', `surface.src: "${src}" is ${declared} bytes, more than the ${MAX_MESH_BYTES} allowed; simplify the mesh`);
  const data = await response.arrayBuffer();
  if (data.byteLength > MAX_MESH_BYTES)
    throw new ConfigError('surface.src', `surface.src: "${src}" is ${data.byteLength} bytes, more than the ${MAX_MESH_BYTES} allowed; simplify the mesh`);
  return { data, name: src };
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
    throw new ConfigError(
      'surface.src',
      `surface.src: ${name}: the spherical parameterization folded ${parameterization.flipped} triangles over; remesh the surface more evenly`,
    );
  }
  const sampleStart = performance.now();
  const image = sampleSurface({ kind: 'mesh', mesh, sphere: parameterization.sphere }, n);
  return { mesh, parameterization, image, parameterizationMs, samplingMs: performance.now() - sampleStart };
}

function oneLine(text: string): string {
  return text.replace(/\s*\n\s*/g, '; ');
}
