/**
 * A large picture uploaded to its texture a band of rows per frame (issue 27): one texSubImage2D
 * of a 100,000-cell result's two pictures (3.3 + 4.9 million texels) held the main thread
 * ~300 ms on a software GPU, where the page allows no task over 50 ms. The texture is a
 * DataTexture whose update ranges (three.js: one per row) name the next band; the view renders
 * again while bands are left (`uploadNextBand`), and the picture fills in within a few frames.
 */
import * as THREE from 'three';

/** Bytes uploaded per texture per frame (~10 ms on SwiftShader). */
const BAND_BYTES = 1 << 20;

interface Banded {
  nextRow: number;
}

/** A texture of `rgba` (row 0 = y 0), its first band queued. */
export function bandedTexture(rgba: Uint8Array | Uint8ClampedArray, width: number, height: number): THREE.DataTexture {
  const texture = new THREE.DataTexture(rgba, width, height, THREE.RGBAFormat, THREE.UnsignedByteType);
  (texture.userData as Banded).nextRow = 0;
  uploadNextBand(texture);
  return texture;
}

/** Queues `texture`'s next band of rows (when it is a banded texture with rows left); whether one was queued. */
function uploadNextBand(texture: THREE.Texture | null | undefined): boolean {
  const state = texture?.userData as Banded | undefined;
  if (!texture || !(texture instanceof THREE.DataTexture) || typeof state?.nextRow !== 'number') return false;
  const { width, height } = texture.image;
  if (state.nextRow >= height) return false;
  const rows = bandRows(width, height, state.nextRow);
  for (let y = rows[0]; y < rows[1]; y++) texture.addUpdateRange(y * width * 4, width * 4);
  state.nextRow = rows[1];
  texture.needsUpdate = true;
  return true;
}

/** The rows [from, to) of the band starting at `row` of a `width` x `height` picture. */
function bandRows(width: number, height: number, row: number): [number, number] {
  const perBand = Math.max(1, Math.floor(BAND_BYTES / (4 * Math.max(1, width))));
  return [row, Math.min(height, row + perBand)];
}

/** uploadNextBand of every mesh's map; whether any band was queued. */
export function uploadNextBands(meshes: readonly THREE.Mesh[]): boolean {
  let queued = false;
  for (const mesh of meshes) queued = uploadNextBand((mesh.material as THREE.MeshBasicMaterial).map) || queued;
  return queued;
}
