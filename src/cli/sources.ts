/**
 * Loading what a config points to — a density image (`density.src`) or a mesh (`surface.src`) —
 * once per file, before any run, with one-line errors naming the field and the file.
 *
 * - Paths are relative to the config (or sweep spec) file; a mesh is also looked for as given
 *   (working directory) and under public/meshes/ (the Node host's loader, node/meshFile.ts).
 * - An http(s) source is a network request: refused unless --allow-network (alias
 *   --allow-fetch), then fetched here with a byte cap, so the pipeline never fetches anything.
 * - A mesh is parsed and checked here (finite coordinates, closed genus 0, consistent PLY
 *   element counts), so a broken mesh fails in a second, not when its run starts.
 */
import { createHash } from 'node:crypto';
import { resolve } from 'node:path';
import type { GrayImage } from '../core/density';
import { checkMesh } from '../core/mesh/check';
import { parseMesh } from '../core/mesh/parse';
import { MAX_MESH_BYTES, MAX_PNG_BYTES } from '../core/inputLimits';
import { decodeGrayPng, ImageError, readImageFile } from '../node/image';
import { loadMeshFile } from '../node/meshFile';
import type { MeshFile } from '../run/index';
import type { InputFileRecord } from '../run/result';
import { InputError } from './errors';

const isUrl = (src: string): boolean => /^https?:\/\//i.test(src);

export interface SourceOptions {
  /** Directory of the config or spec file: relative paths start there. */
  baseDir: string;
  allowNetwork: boolean;
}

/** Caches per resolved source, so a sweep reads each file once. */
export class Sources {
  private readonly images = new Map<string, Promise<GrayImage>>();
  private readonly meshes = new Map<string, Promise<MeshFile>>();
  private readonly records = new Map<string, InputFileRecord>();
  constructor(private readonly options: SourceOptions) {}

  /** The files read so far, one record each (field, src, size, SHA-256), in a fixed order. */
  files(): InputFileRecord[] {
    return [...this.records.values()].sort((a, b) => (a.field + a.src < b.field + b.src ? -1 : a.field + a.src > b.field + b.src ? 1 : 0));
  }

  private record(field: InputFileRecord['field'], src: string, bytes: Uint8Array | string): void {
    const data = typeof bytes === 'string' ? Buffer.from(bytes, 'utf8') : bytes;
    this.records.set(`${field} ${src}`, { field, src, bytes: data.byteLength, sha256: createHash('sha256').update(data).digest('hex') });
  }

  densityImage(src: string): Promise<GrayImage> {
    const key = isUrl(src) ? src : resolve(this.options.baseDir, src);
    let image = this.images.get(key);
    if (!image) this.images.set(key, (image = this.loadImage(src, key)));
    return image;
  }

  mesh(src: string): Promise<MeshFile> {
    const key = isUrl(src) ? src : resolve(this.options.baseDir, src);
    let mesh = this.meshes.get(key);
    if (!mesh) this.meshes.set(key, (mesh = this.loadMesh(src)));
    return mesh;
  }

  private async loadImage(src: string, path: string): Promise<GrayImage> {
    try {
      const bytes = isUrl(src) ? await this.fetchBytes(src, 'density.src', MAX_PNG_BYTES) : readImageFile(path);
      const image = decodeGrayPng(bytes, isUrl(src) ? src : path);
      this.record('density.src', src, bytes);
      return image;
    } catch (error) {
      if (error instanceof ImageError) throw new InputError(`density.src: ${error.message}`);
      throw error;
    }
  }

  private async loadMesh(src: string): Promise<MeshFile> {
    let file: MeshFile;
    if (isUrl(src)) {
      const bytes = await this.fetchBytes(src, 'surface.src', MAX_MESH_BYTES);
      file = { data: bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer, name: src };
    } else {
      file = loadMeshFile(src, this.options.baseDir);
    }
    checkMeshFile(file);
    this.record('surface.src', src, typeof file.data === 'string' ? file.data : new Uint8Array(file.data));
    return file;
  }

  private async fetchBytes(url: string, field: string, maxBytes: number): Promise<Uint8Array> {
    if (!this.options.allowNetwork) {
      throw new InputError(`${field}: "${url}" is a network address; download the file and give its path, or pass --allow-network to fetch it`);
    }
    let response: Response;
    try {
      response = await fetch(url, { redirect: 'follow' });
    } catch (error) {
      throw new InputError(`${field}: cannot fetch "${url}" (${(error as Error).message}); check the address`);
    }
    if (!response.ok || !response.body) throw new InputError(`${field}: fetching "${url}" gave HTTP ${response.status}; check the address`);
    const declared = Number(response.headers.get('content-length') ?? NaN);
    if (declared > maxBytes) throw new InputError(`${field}: "${url}" is ${declared} bytes, more than the ${maxBytes} allowed`);
    const chunks: Uint8Array[] = [];
    let total = 0;
    const reader = response.body.getReader();
    for (let part = await reader.read(); !part.done; part = await reader.read()) {
      total += part.value.length;
      if (total > maxBytes) {
        await reader.cancel();
        throw new InputError(`${field}: "${url}" is more than the ${maxBytes} bytes allowed`);
      }
      chunks.push(part.value);
    }
    return Buffer.concat(chunks);
  }
}

/** Parses and checks a mesh file; every problem is one InputError line on surface.src. */
function checkMeshFile(file: MeshFile): void {
  const name = file.name ?? 'mesh';
  checkPlyCounts(file, name);
  let mesh;
  // three.js's loaders print whole objects to the console for some bad files (a NaN vertex
  // dumps its BufferGeometry); the checks below say what is wrong in one line instead.
  const { warn, error: printError } = console;
  console.warn = console.error = () => {};
  try {
    mesh = parseMesh(file.data, { fileName: name });
  } catch (error) {
    throw new InputError(`surface.src: ${name}: ${oneLine(error instanceof Error ? error.message : 'cannot be read as a mesh')}`);
  } finally {
    console.warn = warn;
    console.error = printError;
  }
  const p = mesh.positions;
  for (let k = 0; k < p.length; k++) {
    if (!Number.isFinite(p[k])) {
      throw new InputError(`surface.src: ${name}: vertex ${Math.floor(k / 3)} has a non-finite coordinate (${String(p[k])}); fix or remove that vertex`);
    }
  }
  const errors = checkMesh(mesh).filter((problem) => problem.severity === 'error');
  if (errors.length > 0) throw new InputError(`surface.src: ${name}: ${errors.map((e) => oneLine(e.message)).join('; ')}`);
}

/**
 * An ASCII PLY whose header declares other element counts than its body holds would be read
 * off by a line and reported as holes; say what is wrong instead.
 */
function checkPlyCounts(file: MeshFile, name: string): void {
  const text = typeof file.data === 'string' ? file.data : new TextDecoder().decode(new Uint8Array(file.data, 0, Math.min(file.data.byteLength, 64 * 2 ** 20)));
  if (!/^ply\r?\n/.test(text) || !/^format ascii/m.test(text)) return;
  const end = text.indexOf('end_header');
  if (end < 0) return;
  const elements = [...text.slice(0, end).matchAll(/^element\s+(\w+)\s+(\d+)/gm)].map((m) => ({ name: m[1], count: Number(m[2]) }));
  const body = text
    .slice(end)
    .split(/\r?\n/)
    .slice(1)
    .filter((line) => line.trim() !== '');
  const declared = elements.reduce((a, e) => a + e.count, 0);
  if (declared !== body.length) {
    const list = elements.map((e) => `${e.count} ${e.name}`).join(' + ');
    throw new InputError(
      `surface.src: ${name}: the PLY header declares ${list} = ${declared} lines but the body has ${body.length}; correct the element counts in the header`,
    );
  }
}

function oneLine(text: string): string {
  return text.replace(/\s*\n\s*/g, '; ');
}
