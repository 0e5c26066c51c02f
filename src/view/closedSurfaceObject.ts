/**
 * A closed surface of the stack as a three.js geometry for the 3D view: the atlas mesh
 * (cubeAtlasMesh.ts) with each vertex's candidate cells (closedCandidates.ts) as an attribute,
 * the surface's sites and cell colours put into its material (closedMaterial.ts), and picking by
 * the same rule the fragment shader draws with.
 */
import * as THREE from 'three';
import { atlasTopology, closedSurfaceMesh } from './cubeAtlasMesh';
import { nearestCandidate, sitePositions, vertexCandidates } from './closedCandidates';
import { setClosedCells } from './closedMaterial';
import type { ViewStack, ViewSurface } from './stack';

/** What picking on a closed surface needs: the rule its fragments are drawn by. */
interface ClosedPickData {
  candidates: Float32Array;
  sites: Float32Array;
}

/** Surface `surface`'s triangles and candidates; `material` gets its sites and cell colours. */
export function closedSurfaceGeometry(stack: ViewStack, surface: ViewSurface, material: THREE.ShaderMaterial): THREE.BufferGeometry {
  const built = closedSurfaceMesh(surface.image);
  const sites = sitePositions(surface.cells);
  const candidates = vertexCandidates(built.positions, built.cells, atlasTopology(surface.image.grid.width).neighbours, sites);
  setClosedCells(material, { sites, sides: surface.sides, scutoid: stack.scutoid, stripePeriod: 3 * built.edgeLength });
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(built.positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(built.normals, 3));
  geometry.setAttribute('candidates', new THREE.BufferAttribute(candidates, 4));
  geometry.setIndex(new THREE.BufferAttribute(built.indices, 1));
  const pick: ClosedPickData = { candidates, sites };
  geometry.userData.closed = pick;
  return geometry;
}

/**
 * The cell drawn at a ray's hit on a closed surface's mesh: the nearest candidate of the hit
 * triangle's provoking (last) vertex to the hit point; null when the hit is not on one.
 */
export function closedCellAt(hit: THREE.Intersection): number | null {
  const pick = (hit.object as THREE.Mesh).geometry?.userData.closed as ClosedPickData | undefined;
  if (!pick || !hit.face) return null;
  const p = hit.object.worldToLocal(hit.point.clone());
  return nearestCandidate(pick.candidates, hit.face.c, pick.sites, p.x, p.y, p.z);
}
