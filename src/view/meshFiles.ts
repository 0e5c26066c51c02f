/**
 * Mesh files for runs in the page. A mesh `surface.src` is a URL (fetched once and kept) or
 * the name of a file the user uploaded: such a file cannot live in a URL, so its bytes stay in
 * memory here, under its name, and the config keeps only the name (`surface.src` without a
 * "/"); a link or a later visit with such a name asks for the file again.
 */
import { ConfigError, type Config } from '../core/config';
import type { MeshFile } from '../run';
import { fetchSourceBytes } from './sources';

/** A src without a "/" (and not a data: URL) names a file the user uploaded. */
export function isUploadName(src: string): boolean {
  return !src.includes('/') && !src.startsWith('data:');
}

const uploaded = new Map<string, ArrayBuffer>();

/** Keeps an uploaded file's bytes for runs of `surface.src = name`. */
export function rememberUpload(file: MeshFile & { name: string; data: ArrayBuffer }): void {
  uploaded.set(file.name, file.data);
}

function uploadedMesh(name: string): MeshFile | null {
  const data = uploaded.get(name);
  return data ? { data, name } : null;
}

const fetched = new Map<string, Promise<MeshFile>>();

/**
 * The mesh file of a mesh config: `given` (the element's meshFile property), an uploaded file
 * of that name, or the URL fetched once and kept. Null for other surfaces.
 */
export async function meshFileFor(config: Config, given?: MeshFile | null): Promise<MeshFile | null> {
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
    // Through the source gate: a foreign URL loads only once the user approved it (sources.ts).
    const job = fetchSourceBytes('surface.src', src).then((data): MeshFile => ({ data, name: src }));
    job.catch(() => fetched.delete(src));
    fetched.set(src, job);
  }
  return fetched.get(src)!;
}
