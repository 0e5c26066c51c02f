/**
 * Fast picking on large meshes. Hover picks cost one raycast per frame: brute force on a closed
 * surface's mesh is ~23 ms at 500k triangles (bench/hoverPick.ts), three-mesh-bvh ~0.04 ms once
 * its hierarchy is built (~160 ms at 500k). The hierarchies are built in idle time, one mesh per
 * idle callback, so no frame pays for them; until then picks fall back to brute force.
 */
import type * as THREE from 'three';
import { acceleratedRaycast, MeshBVH } from 'three-mesh-bvh';

/** Meshes with fewer triangles get no hierarchy (bench/hoverPick.ts measures picking). */
const MIN_TRIANGLES = 50_000;

/**
 * Builds, in idle time, a bounding-volume hierarchy for each mesh of `meshes` with at least
 * MIN_TRIANGLES triangles that still `isCurrent` when its turn comes (a newer result may have
 * replaced it). `indirect`: the triangle order, which picking reads, is left as it is.
 */
export function acceleratePicking(meshes: readonly THREE.Mesh[], isCurrent: (mesh: THREE.Mesh) => boolean): void {
  const pending = meshes.filter((m) => !m.geometry.boundsTree && (m.geometry.index?.count ?? 0) / 3 >= MIN_TRIANGLES);
  const idle = (callback: () => void) =>
    typeof requestIdleCallback === 'function' ? requestIdleCallback(callback, { timeout: 2000 }) : setTimeout(callback, 50);
  const next = () => {
    const mesh = pending.shift();
    if (!mesh) return;
    if (isCurrent(mesh) && !mesh.geometry.boundsTree) {
      mesh.geometry.boundsTree = new MeshBVH(mesh.geometry, { indirect: true });
      mesh.raycast = acceleratedRaycast;
    }
    if (pending.length) idle(next);
  };
  if (pending.length) idle(next);
}
