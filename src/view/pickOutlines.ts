/**
 * The 3D view's picked cell on planes and tubes (issue 27): its outline (pickOverlay.ts) added to
 * every surface's mesh, replaced on each pick; the surfaces' pictures are never repainted for a
 * pick. One pair of materials per view, kept, with their shaders compiled in the background when
 * the first sheet is shown (compiled at the first pick they held the main thread ~300 ms on a
 * software GPU).
 */
import * as THREE from 'three';
import { disposeOutline, outlineMaterials, outlineObject, surfaceOutline, type OutlineMaterials } from './pickOverlay';
import type { ViewStack } from './stack';

const NAME = 'picked-cell';

export class PickOutlines {
  private readonly materials: OutlineMaterials;
  private warmed = false;

  constructor(
    private readonly renderer: THREE.WebGLRenderer,
    clip: THREE.Plane,
  ) {
    this.materials = outlineMaterials(clip);
  }

  /** Cell `id`'s outline (-1: none) on `meshes`, the surfaces of `stack` in order. */
  place(meshes: readonly THREE.Mesh[], stack: ViewStack | null, id: number): void {
    meshes.forEach((mesh, k) => {
      this.clear(mesh);
      const surface = stack?.surfaces[k];
      const outline = stack && surface ? surfaceOutline(stack, surface, id, this.materials) : null;
      if (outline) mesh.add(outline);
    });
  }

  /** Removes `mesh`'s outline. */
  clear(mesh: THREE.Mesh): void {
    for (const old of mesh.children.filter((c) => c.name === NAME)) {
      mesh.remove(old);
      disposeOutline(old);
    }
  }

  /** Compiles the outline's shaders once, in the background (KHR_parallel_shader_compile where the browser has it). */
  warm(mesh: THREE.Mesh | undefined, camera: THREE.Camera, scene: THREE.Scene): void {
    if (this.warmed || !mesh) return;
    this.warmed = true;
    const warm = outlineObject({ triangles: new Float32Array(9), border: new Float32Array(6) }, this.materials);
    warm.name = 'warm-outline';
    mesh.add(warm);
    void this.renderer
      .compileAsync(warm, camera, scene)
      .catch(() => (this.warmed = false))
      .finally(() => {
        warm.removeFromParent();
        disposeOutline(warm);
      });
  }
}
