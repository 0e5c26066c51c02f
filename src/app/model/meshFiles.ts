/**
 * Mesh files in the page. A sample is a URL under /meshes/ (public/meshes/), so a link or a
 * saved session reproduces it. A user's file cannot live in a URL: its bytes stay in memory
 * here, under its name, and the config keeps only the name (`surface.src` without a "/"); a
 * link or a later visit with such a name asks for the file again.
 */
import { ConfigError, type AnyConfig } from '../../core/config';
import type { MeshFile } from '../../run/closedMesh';

export type { MeshFile } from '../../run/closedMesh';

/** The sample meshes shipped in public/meshes/ (see its README). */
export const SAMPLE_MESHES = [
  { name: 'organoid.ply', label: 'organoid-like blob (2,562 vertices)' },
  { name: 'egg-chamber.ply', label: 'egg chamber, 2 : 1 : 1 (1,962 vertices)' },
  { name: 'level-set-blob.ply', label: 'level-set blob (9,002 vertices)' },
  { name: 'torus.ply', label: 'torus (genus 1: shows the message)' },
  { name: 'open-sphere.ply', label: 'sphere with a hole (shows the message)' },
] as const;

export const SAMPLE_PREFIX = '/meshes/';

export function sampleUrl(name: string): string {
  return `${SAMPLE_PREFIX}${name}`;
}

/** The sample's file name when `src` is a sample URL, else null. */
export function sampleName(src: string): string | null {
  if (!src.startsWith(SAMPLE_PREFIX)) return null;
  const name = src.slice(SAMPLE_PREFIX.length);
  return SAMPLE_MESHES.some((s) => s.name === name) ? name : null;
}

/** A src without a "/" (and not a data: URL) names a file the user uploaded. */
export function isUploadName(src: string): boolean {
  return !src.includes('/') && !src.startsWith('data:');
}

const uploaded = new Map<string, ArrayBuffer>();

/** Keeps an uploaded file's bytes for runs of `surface.src = name`. */
export function rememberUpload(file: MeshFile & { name: string; data: ArrayBuffer }): void {
  uploaded.set(file.name, file.data);
}

export function uploadedMesh(name: string): MeshFile | null {
  const data = uploaded.get(name);
  return data ? { data, name } : null;
}

const fetched = new Map<string, Promise<MeshFile>>();

async function fetchMesh(src: string): Promise<MeshFile> {
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
 * The mesh file of a mesh config: `given` (the element's meshFile property), an uploaded file
 * of that name, or the URL fetched once and kept. Null for other surfaces.
 */
export async function meshFileFor(config: AnyConfig, given?: MeshFile | null): Promise<MeshFile | null> {
  if (config.surface.kind !== 'mesh') return null;
  if (given) return given;
  const { src } = config.surface;
  if (isUploadName(src)) {
    const file = uploadedMesh(src);
    if (file) return file;
    throw new ConfigError(
      'surface.src',
      `surface.src: "${src}" is a file uploaded from a computer; a link or a saved session keeps only its name, not the file: upload it again (Mesh file) or choose a sample mesh`,
    );
  }
  if (!fetched.has(src)) {
    if (fetched.size > 8) fetched.clear();
    const job = fetchMesh(src);
    job.catch(() => fetched.delete(src));
    fetched.set(src, job);
  }
  return fetched.get(src)!;
}
