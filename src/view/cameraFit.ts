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

/** What the whole-sheet fit needs of the sheet, in the view's frame (centred at the origin). */
export interface SheetBounds {
  /** Half the size of the sheet's bounding box (a tube's axis along x). */
  halfSize: THREE.Vector3;
  /** Radius of a sphere about the origin that holds every vertex. */
  radius: number;
}

/**
 * The bounds of a sheet made of `geometries` whose bounding box is `box`, in the view's frame:
 * centred at the box's centre, a tube's axis (z) turned to x. The vertex radius comes from the
 * geometries' bounding spheres (three.js needs them for culling anyway).
 */
export function sheetBounds(geometries: readonly THREE.BufferGeometry[], box: THREE.Box3, tube: boolean): SheetBounds {
  const centre = box.getCenter(new THREE.Vector3());
  const halfSize = box.getSize(new THREE.Vector3()).multiplyScalar(0.5);
  if (tube) halfSize.set(halfSize.z, halfSize.y, halfSize.x);
  let radius = 0;
  for (const geometry of geometries) {
    geometry.computeBoundingSphere();
    const sphere = geometry.boundingSphere!;
    radius = Math.max(radius, sphere.center.distanceTo(centre) + sphere.radius);
  }
  return { halfSize, radius: Math.max(1e-6, radius) };
}

/**
 * The camera distance along `direction` (unit, from the target at the origin to the camera) at
 * which every one of `points` lies inside the view: a point at lateral offsets (u, v) and depth
 * w from the camera is inside when |u| <= w tan(half width) and |v| <= w tan(half height).
 */
export function fitPointsDistance(camera: THREE.PerspectiveCamera, direction: THREE.Vector3, points: readonly THREE.Vector3[]): number {
  const forward = direction.clone().negate();
  const right = new THREE.Vector3().crossVectors(forward, camera.up).normalize();
  const up = new THREE.Vector3().crossVectors(right, forward);
  const tanV = Math.tan((camera.fov * Math.PI) / 360);
  const tanH = tanV * camera.aspect;
  let distance = 0;
  for (const p of points) {
    const along = p.dot(direction);
    distance = Math.max(distance, along + Math.abs(p.dot(right)) / tanH, along + Math.abs(p.dot(up)) / tanV);
  }
  return distance;
}

/** The eight corners of a box centred at the origin. */
function boxCorners(halfSize: THREE.Vector3): THREE.Vector3[] {
  const corners: THREE.Vector3[] = [];
  for (const x of [-1, 1]) for (const y of [-1, 1]) for (const z of [-1, 1]) corners.push(new THREE.Vector3(x * halfSize.x, y * halfSize.y, z * halfSize.z));
  return corners;
}

/**
 * The whole sheet in view, for any window shape: a closed surface whole (its vertex sphere just
 * fits), a plane or a tube as close as its bounding box still fits (the box holds the sheet and
 * the view is convex, so the sheet is inside too), with a small margin.
 */
export function sheetPose(camera: THREE.PerspectiveCamera, kind: Kind, closed: boolean, bounds: SheetBounds): CameraPose {
  // A closed surface touches its vertex sphere's rim: leave a little room around it. A box's
  // corners lie outside a plane or tube, which needs less.
  const margin = closed ? 1.15 : 1.04;
  // Look from the side, a little above: a tube lies across the view.
  const direction = new THREE.Vector3(0, 0.45, 1).normalize();
  if (kind === 'plane') direction.set(0.25, 0.5, 1).normalize();
  const elongation = kind === 'tube' ? bounds.halfSize.x / Math.max(1e-9, bounds.halfSize.y, bounds.halfSize.z) : 1;
  // A long tube seen from the side is a sliver: look along it from above one end, so its near
  // part shows its cells and the rest recedes in perspective, still whole in view.
  if (elongation > 3) direction.set(0.8, 0.45, 0.55).normalize();
  const sphereFit = fillDistance(camera, bounds.radius);
  const distance = margin * (closed ? sphereFit : Math.min(sphereFit, fitPointsDistance(camera, direction, boxCorners(bounds.halfSize))));
  return { position: direction.multiplyScalar(distance), target: new THREE.Vector3(), near: distance / 100 };
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
