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
  /**
   * Set when the file's triangles were oriented inward (negative enclosed volume) and were
   * flipped to point outward: a sentence the result and the page show (issue 26).
   */
  readonly reoriented: string | null;
}

/**
 * The sizes a mesh may have once scaled to µm (its bounding box's longest side): a file in
 * other units with the wrong `surface.scale` (metres, nanometres, a model scaled to 1e30) is
 * refused with a message about its size, not later as a site-placement problem.
 */
export const MESH_EXTENT_UM = { min: 1e-3, max: 1e6 } as const;

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
  checkMeshExtent(mesh, name, surface.scale);
  const inward = signedVolume(mesh) < 0;
  if (inward) mesh = flipOrientation(mesh);
  const reoriented = inward
    ? `${name}: the triangles were oriented inward (normals pointing into the enclosed volume); they were flipped to point outward, so the apical side is the outside as for any closed surface`
    : null;
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
  return { mesh, parameterization, image, parameterizationMs, samplingMs: performance.now() - sampleStart, reoriented };
}

/** Refuses a mesh whose size in µm (after `scale`) is not finite or outside MESH_EXTENT_UM. */
export function checkMeshExtent(mesh: TriangleMesh, name: string, scale: number): void {
  const p = mesh.positions;
  let extent = 0;
  for (let axis = 0; axis < 3; axis++) {
    let lo = Infinity;
    let hi = -Infinity;
    for (let k = axis; k < p.length; k += 3) {
      lo = Math.min(lo, p[k]);
      hi = Math.max(hi, p[k]);
    }
    extent = Math.max(extent, hi - lo);
  }
  const across = Number.isFinite(extent) ? `${sized(extent)} µm across` : 'of no finite size (coordinates overflow)';
  if (Number.isFinite(extent) && extent >= MESH_EXTENT_UM.min && extent <= MESH_EXTENT_UM.max) return;
  const hint =
    Number.isFinite(extent) && extent > 0
      ? `; its coordinates are read as µm times surface.scale (${scale}): set surface.scale to about ${sized(100 / (extent / scale))} for a 100 µm sheet`
      : "; check the file's coordinates";
  throw new ConfigError(
    'surface.src',
    `surface.src: ${name}: the mesh is ${across} after surface.scale ${scale}; a sheet of cells must be ${MESH_EXTENT_UM.min} to ${MESH_EXTENT_UM.max.toLocaleString('en-US')} µm across${hint}`,
  );
}

/** 3 significant digits, in exponent form outside 0.01 .. 10,000. */
function sized(x: number): string {
  return x >= 0.01 && x < 1e4 ? x.toPrecision(3) : x.toExponential(2);
}

function oneLine(text: string): string {
  return text.replace(/\s*\n\s*/g, '; ');
}
