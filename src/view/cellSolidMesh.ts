/**
 * The picked cell's solid (cellSolid.ts) as three.js objects for the 3D view: a lit, flat-shaded
 * mesh in the picked cell's colour with its creases (polygon corners, cap borders) drawn as dark
 * lines, so the scutoid's faces and its Y junction read. It is drawn after the surfaces with the
 * depth buffer cleared first: always in view, in front of the surfaces around it (which would
 * otherwise hide a cell between two cylinders), yet hiding its own back faces.
 */
import * as THREE from 'three';
import { cellSolid, type CellSolid } from './cellSolid';
import type { ViewStack } from './stack';
import { SELECTED_RGB } from './sideColors';

/** Draw order after every surface (the view's meshes use the default 0). */
const SOLID_ORDER = 1000;

/** A group (mesh + crease lines) placed in the sheet's frame at the solid's origin. */
function cellSolidObject(solid: CellSolid): THREE.Group {
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
  const edges = new THREE.LineSegments(new THREE.EdgesGeometry(geometry, 25), new THREE.LineBasicMaterial({ color: 0x222222 }));
  edges.name = 'cell solid creases';
  edges.renderOrder = SOLID_ORDER + 1;
  const group = new THREE.Group();
  group.name = `cell ${solid.cell} solid`;
  group.add(mesh, edges);
  group.position.set(solid.origin[0], solid.origin[1], solid.origin[2]);
  return group;
}

/** Frees what `cellSolidObject` allocated. */
function disposeCellSolidObject(group: THREE.Group): void {
  group.traverse((object) => {
    if (object instanceof THREE.Mesh || object instanceof THREE.LineSegments) {
      object.geometry.dispose();
      (object.material as THREE.Material).dispose();
    }
  });
}

/** The light the solid is shaded with: a headlight on the camera and a soft fill. */
function cellSolidLights(): { headlight: THREE.DirectionalLight; fill: THREE.HemisphereLight } {
  const headlight = new THREE.DirectionalLight(0xffffff, 2.2);
  headlight.position.set(0.4, 0.8, 0.2);
  const fill = new THREE.HemisphereLight(0xffffff, 0x8a8a80, 1.1);
  return { headlight, fill };
}

/**
 * The solid shown in a view: at most one, a group of its own in the sheet's frame (`parent`),
 * kept apart from the surfaces' meshes (a rebuild of the surfaces leaves it). The lights are
 * added on first use: a headlight on the camera (the camera joins the scene to carry it) and a
 * soft fill; the surfaces' unlit materials ignore both.
 */
export class CellSolidDisplay {
  private object: THREE.Group | null = null;
  private lit = false;

  constructor(
    private readonly scene: THREE.Scene,
    private readonly camera: THREE.Camera,
    private readonly parent: THREE.Object3D,
  ) {}

  /** Shows cell `id` of `stack` as a solid (-1 or no stack: none); the solid, or null. */
  show(stack: ViewStack | null, id: number): CellSolid | null {
    if (this.object) {
      this.parent.remove(this.object);
      disposeCellSolidObject(this.object);
      this.object = null;
    }
    const solid = stack && id >= 0 ? cellSolid(stack, id) : null;
    if (!solid) return null;
    if (!this.lit) {
      const { headlight, fill } = cellSolidLights();
      this.camera.add(headlight);
      this.scene.add(this.camera, fill);
      this.lit = true;
    }
    this.object = cellSolidObject(solid);
    this.parent.add(this.object);
    return solid;
  }

  /** The solid's bounding sphere in world space, or null when none is shown. */
  bounds(): THREE.Sphere | null {
    return this.object ? new THREE.Box3().setFromObject(this.object).getBoundingSphere(new THREE.Sphere()) : null;
  }
}
