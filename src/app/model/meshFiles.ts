/**
 * The sample meshes of the app's mesh menu. A sample is a URL under /meshes/ (public/meshes/),
 * so a link or a saved session reproduces it. Files the user uploads are kept by
 * src/view/meshFiles.ts, which also fetches a mesh for a run.
 */

/** The sample meshes shipped in public/meshes/ (see its README). */
export const SAMPLE_MESHES = [
  { name: 'organoid.ply', label: 'organoid-like blob (2,562 vertices)' },
  { name: 'egg-chamber.ply', label: 'egg chamber, 2 : 1 : 1 (1,962 vertices)' },
  { name: 'level-set-blob.ply', label: 'level-set blob (9,002 vertices)' },
  { name: 'torus.ply', label: 'torus (genus 1: shows the message)' },
  { name: 'open-sphere.ply', label: 'sphere with a hole (shows the message)' },
] as const;

const SAMPLE_PREFIX = '/meshes/';

export function sampleUrl(name: string): string {
  return `${SAMPLE_PREFIX}${name}`;
}

/** The sample's file name when `src` is a sample URL, else null. */
export function sampleName(src: string): string | null {
  if (!src.startsWith(SAMPLE_PREFIX)) return null;
  const name = src.slice(SAMPLE_PREFIX.length);
  return SAMPLE_MESHES.some((s) => s.name === name) ? name : null;
}
