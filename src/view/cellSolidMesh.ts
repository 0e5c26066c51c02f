/**
 * The picked cell's solid (cellSolid.ts) as three.js objects for the 3D view: a lit, flat-shaded
 * mesh in the picked cell's colour with its creases (polygon corners, cap borders) drawn as dark
 * lines, so the scutoid's faces and its Y junction read. It is drawn after the surfaces with the
 * depth buffer cleared first: always in view, in front of the surfaces around it (which would
 * otherwise hide a cell between two cylinders), yet hiding its own back faces.
 */
import * as THREE from 'three';
import type { CellSolid } from './cellSolid';
import { SELECTED_RGB } from './sideColors';

/** Draw order after every surface (the view's meshes use the default 0). */
const SOLID_ORDER = 1000;

/** A group (mesh + crease lines) placed in the sheet's frame at the solid's origin. */
export function cellSolidObject(solid: CellSolid): THREE.Group {
  const geometry = new THREE.BufferGeometry();
  geometry.setAttribute('position', new THREE.BufferAttribute(solid.positions, 3));
  geometry.setAttribute('normal', new THREE.BufferAttribute(solid.normals, 3));
  geometry.setIndex(new THREE.BufferAttribute(solid.indices, 1));
  const [r, g, b] = SELECTED_RGB;
  const material = new THREE.MeshLambertMaterial({
    color: new THREE.Color().setRGB(r / 255, g / 255, b / 255, THREE.SRGBColorSpace),
    flatShading: true,
    polygonOffset: true,
    polygonOffsetFactor: 1,
    polygonOffsetUnits: 1,
  });
  const mesh = new THREE.Mesh(geometry, material);
  mesh.name = 'cell solid';
  mesh.renderOrder = SOLID_ORDER;
  // Drawn over the surfaces: the depth of what was drawn before is forgotten.
  mesh.onBeforeRender = (renderer) => renderer.clearDepth();
  const edges = new THREE.LineSegments(
    new THREE.EdgesGeometry(geometry, 25),
    new THREE.LineBasicMaterial({ color: 0x222222 }),
  );
  edges.name = 'cell solid creases';
  edges.renderOrder = SOLID_ORDER + 1;
  const group = new THREE.Group();
  group.name = `cell ${solid.cell} solid`;
  group.add(mesh, edges);
  group.position.set(solid.origin[0], solid.origin[1], solid.origin[2]);
  return group;
}

/** Frees what `cellSolidObject` allocated. */
export function disposeCellSolidObject(group: THREE.Group): void {
  group.traverse((object) => {
    if (object instanceof THREE.Mesh || object instanceof THREE.LineSegments) {
      object.geometry.dispose();
      (object.material as THREE.Material).dispose();
    }
  });
}

/** The light the solid is shaded with: a headlight on the camera and a soft fill. */
export function cellSolidLights(): { headlight: THREE.DirectionalLight; fill: THREE.HemisphereLight } {
  const headlight = new THREE.DirectionalLight(0xffffff, 2.2);
  headlight.position.set(0.4, 0.8, 0.2);
  const fill = new THREE.HemisphereLight(0xffffff, 0x8a8a80, 1.1);
  return { headlight, fill };
}
