/**
 * Where the 3D view's camera goes: the whole sheet (a tube across the view, a long tube seen
 * along it from above one end, a closed surface whole) or one cell's solid seen from outside the
 * sheet. Pure camera arithmetic on three.js vectors; the view applies the poses.
 */
import * as THREE from 'three';

export interface CameraPose {
  position: THREE.Vector3;
  target: THREE.Vector3;
  /** Near plane distance suited to the pose. */
  near: number;
}

type Kind = 'plane' | 'tube' | 'sphere' | 'ellipsoid' | 'mesh';

/** Distance at which a sphere of `radius` just fills the narrower field of view. */
export function fillDistance(camera: THREE.PerspectiveCamera, radius: number): number {
  const halfV = (camera.fov * Math.PI) / 360;
  const halfH = Math.atan(Math.tan(halfV) * camera.aspect);
  return radius / Math.sin(Math.min(halfV, halfH));
}

/**
 * The whole sheet, centred at the origin with bounding radius `radius`; `elongation` is a tube's
 * length over its diameter (1 otherwise).
 */
export function sheetPose(camera: THREE.PerspectiveCamera, kind: Kind, closed: boolean, radius: number, elongation: number): CameraPose {
  const distance = fillDistance(camera, radius);
  // Look from the side, a little above: a tube lies across the view.
  const direction = new THREE.Vector3(0, 0.45, 1).normalize();
  if (kind === 'plane') direction.set(0.25, 0.5, 1).normalize();
  // A closed surface is seen whole; so is a sheet (the bounding sphere fills the view).
  let closeness = closed ? 0.8 : 0.95;
  if (elongation > 3) {
    // A long tube seen from the side is a sliver: look along it from above one end, so its
    // near part shows its cells and the rest recedes in perspective, still whole in view.
    direction.set(0.8, 0.45, 0.55).normalize();
    closeness = 0.9;
  }
  return { position: direction.multiplyScalar(distance * closeness), target: new THREE.Vector3(), near: distance / 100 };
}

/**
 * One cell's solid (its bounding sphere, world space, the sheet centred at the origin) seen from
 * outside the sheet: along the tube's or the closed surface's outward direction there, a little
 * towards the current view so its sides show (a plane keeps the current direction), near enough
 * that the solid fills about two thirds of the view.
 */
export function solidPose(camera: THREE.PerspectiveCamera, target: THREE.Vector3, kind: Kind, solid: THREE.Sphere): CameraPose {
  const direction = camera.position.clone().sub(target).normalize();
  const outward = solid.center.clone();
  // The view turns a tube's axis to x: outward is the centre's part across the axis.
  if (kind === 'tube') outward.x = 0;
  if (kind !== 'plane' && outward.lengthSq() > 1e-12) direction.copy(outward.normalize().multiplyScalar(3).add(direction).normalize());
  const distance = fillDistance(camera, 1.5 * Math.max(solid.radius, 1e-6));
  return { position: solid.center.clone().addScaledVector(direction, distance), target: solid.center.clone(), near: distance / 100 };
}
