import * as THREE from 'three';
import { describe, expect, it } from 'vitest';
import { fillDistance, fitPointsDistance, sheetBounds, sheetPose, solidPose } from '../../src/view/cameraFit';

/**
 * The camera poses (issue 14: "fit the whole sheet on every geometry change; long tubes get a
 * sensible view"): every point of the sheet projects inside the view, the sheet is not a speck,
 * and a picked cell's solid fills a good part of the view. Pure arithmetic, no GPU.
 */

function cameraAt(pose: { position: THREE.Vector3; target: THREE.Vector3; near: number }, aspect: number): THREE.PerspectiveCamera {
  const camera = new THREE.PerspectiveCamera(45, aspect, pose.near, pose.near * 1000);
  camera.position.copy(pose.position);
  camera.lookAt(pose.target);
  camera.updateMatrixWorld();
  camera.updateProjectionMatrix();
  return camera;
}

/** Points of a tube's surface as the view shows it: axis along x, centred at the origin. */
function tubePoints(radius: number, length: number): THREE.Vector3[] {
  const points: THREE.Vector3[] = [];
  for (let i = 0; i <= 20; i++) {
    for (let k = 0; k < 24; k++) {
      const a = (2 * Math.PI * k) / 24;
      points.push(new THREE.Vector3(-length / 2 + (length * i) / 20, radius * Math.cos(a), radius * Math.sin(a)));
    }
  }
  return points;
}

/**
 * The projected points' extent as fractions of the view's width and height, and whether all
 * are in view.
 */
function projection(camera: THREE.PerspectiveCamera, points: THREE.Vector3[]): { inside: boolean; width: number; height: number } {
  let minX = Infinity;
  let maxX = -Infinity;
  let minY = Infinity;
  let maxY = -Infinity;
  let inside = true;
  for (const p of points) {
    const ndc = p.clone().project(camera);
    if (Math.abs(ndc.x) > 1 || Math.abs(ndc.y) > 1 || ndc.z < -1 || ndc.z > 1) inside = false;
    minX = Math.min(minX, ndc.x);
    maxX = Math.max(maxX, ndc.x);
    minY = Math.min(minY, ndc.y);
    maxY = Math.max(maxY, ndc.y);
  }
  return { inside, width: (maxX - minX) / 2, height: (maxY - minY) / 2 };
}

describe('camera poses', () => {
  it('fillDistance: a sphere of that radius just touches the narrower side of the view', () => {
    for (const aspect of [0.5, 1, 1.6, 3]) {
      const camera = new THREE.PerspectiveCamera(45, aspect, 0.01, 1000);
      const d = fillDistance(camera, 2);
      camera.position.set(0, 0, d);
      camera.lookAt(0, 0, 0);
      camera.updateMatrixWorld();
      // The tangent from the camera to the sphere makes the half angle of the narrower side.
      const halfV = (camera.fov * Math.PI) / 360;
      const halfH = Math.atan(Math.tan(halfV) * aspect);
      expect(Math.asin(2 / d)).toBeCloseTo(Math.min(halfV, halfH), 10);
    }
  });

  it("sheetBounds: a tube's axis turned to x, every vertex within the radius about the box's centre", () => {
    // Two coaxial open cylinders along z (three.js builds them along y: turn them), off the origin.
    const geometries = [10, 20].map((r) => new THREE.CylinderGeometry(r, r, 120, 32, 1, true).rotateX(Math.PI / 2).translate(5, -3, 40));
    const box = new THREE.Box3();
    for (const g of geometries) {
      g.computeBoundingBox();
      box.union(g.boundingBox!);
    }
    const bounds = sheetBounds(geometries, box, true);
    expect(bounds.halfSize.x).toBeCloseTo(60, 9);
    expect(bounds.halfSize.y).toBeCloseTo(20, 3);
    expect(bounds.halfSize.z).toBeCloseTo(20, 3);
    const centre = box.getCenter(new THREE.Vector3());
    let farthest = 0;
    for (const g of geometries) {
      const p = g.getAttribute('position');
      for (let k = 0; k < p.count; k++) farthest = Math.max(farthest, new THREE.Vector3().fromBufferAttribute(p, k).distanceTo(centre));
    }
    expect(bounds.radius).toBeGreaterThanOrEqual(farthest - 1e-9);
    expect(bounds.radius).toBeLessThan(1.05 * farthest);
  });

  it('fitPointsDistance: every point inside, and one on the edge of the view', () => {
    const camera = new THREE.PerspectiveCamera(45, 1.4, 0.1, 1000);
    const direction = new THREE.Vector3(0.3, 0.5, 1).normalize();
    const points = [new THREE.Vector3(12, -3, 4), new THREE.Vector3(-7, 9, -2), new THREE.Vector3(1, 1, 15), new THREE.Vector3(-20, -1, 0)];
    const d = fitPointsDistance(camera, direction, points);
    const view = cameraAt({ position: direction.clone().multiplyScalar(d), target: new THREE.Vector3(), near: 0.1 }, 1.4);
    const ndc = points.map((p) => p.clone().project(view));
    for (const p of ndc) expect(Math.max(Math.abs(p.x), Math.abs(p.y))).toBeLessThanOrEqual(1 + 1e-9);
    expect(Math.max(...ndc.map((p) => Math.max(Math.abs(p.x), Math.abs(p.y))))).toBeCloseTo(1, 9);
  });

  it('a tube of any length and a wide or narrow view: the whole tube in view, and not a sliver', () => {
    for (const aspect of [0.6, 1, 1.55, 2.5]) {
      for (const [radius, length] of [
        [10, 20],
        [10, 60],
        [8, 200],
        [5, 600],
      ]) {
        const points = tubePoints(radius, length);
        const camera = new THREE.PerspectiveCamera(45, aspect, 0.1, 1000);
        const bounds = { halfSize: new THREE.Vector3(length / 2, radius, radius), radius: Math.hypot(radius, length / 2) };
        const pose = sheetPose(camera, 'tube', false, bounds);
        const view = projection(cameraAt(pose, aspect), points);
        expect(view.inside, `tube r ${radius} L ${length} aspect ${aspect}`).toBe(true);
        // The tube spans a good part of the view in both directions: a long tube seen along it
        // from above one end is not a sliver across the middle.
        expect(Math.max(view.width, view.height)).toBeGreaterThan(0.6);
        expect(Math.min(view.width, view.height)).toBeGreaterThan(length > 8 * radius ? 0.2 : 0.1);
      }
    }
  });

  it('a plane and a closed surface: every point in view, filling most of it', () => {
    for (const aspect of [0.7, 1.55]) {
      const camera = new THREE.PerspectiveCamera(45, aspect, 0.1, 1000);
      const square: THREE.Vector3[] = [];
      for (let i = 0; i <= 10; i++) for (let k = 0; k <= 10; k++) square.push(new THREE.Vector3(-50 + 10 * i, -50 + 10 * k, 0));
      const plane = projection(
        cameraAt(sheetPose(camera, 'plane', false, { halfSize: new THREE.Vector3(50, 50, 0), radius: Math.SQRT2 * 50 }), aspect),
        square,
      );
      expect(plane.inside).toBe(true);
      expect(Math.max(plane.width, plane.height)).toBeGreaterThan(0.6);

      const sphere: THREE.Vector3[] = [];
      for (let k = 0; k < 400; k++) {
        const z = 1 - (2 * (k + 0.5)) / 400;
        const a = k * 2.399963;
        sphere.push(new THREE.Vector3(Math.sqrt(1 - z * z) * Math.cos(a), Math.sqrt(1 - z * z) * Math.sin(a), z).multiplyScalar(30));
      }
      const closed = projection(cameraAt(sheetPose(camera, 'sphere', true, { halfSize: new THREE.Vector3(30, 30, 30), radius: 30 }), aspect), sphere);
      expect(closed.inside).toBe(true);
      // Whole, with a little room: most of the narrower side of the view.
      const narrower = aspect >= 1 ? closed.height : closed.width;
      expect(narrower).toBeGreaterThan(0.75);
      expect(narrower).toBeLessThan(0.95);
    }
  });

  it("a cell's solid: seen from outside the tube or sphere, in view, filling a good part of it", () => {
    const aspect = 1.55;
    const cases: { kind: 'tube' | 'sphere' | 'plane'; centre: THREE.Vector3 }[] = [
      { kind: 'tube', centre: new THREE.Vector3(40, 0, -12) },
      { kind: 'sphere', centre: new THREE.Vector3(0, 20, 22) },
      { kind: 'plane', centre: new THREE.Vector3(10, -5, 0) },
    ];
    for (const { kind, centre } of cases) {
      const camera = new THREE.PerspectiveCamera(45, aspect, 0.1, 1000);
      camera.position.set(0, 50, 200);
      const solid = new THREE.Sphere(centre, 3);
      const pose = solidPose(camera, new THREE.Vector3(), kind, solid);
      expect(pose.target.distanceTo(centre)).toBeLessThan(1e-9);
      if (kind !== 'plane') {
        // Outside the sheet: the camera is farther from the axis (tube) or centre (sphere).
        const away = pose.position.clone();
        const inCentre = centre.clone();
        if (kind === 'tube') {
          away.x = 0;
          inCentre.x = 0;
        }
        expect(away.length()).toBeGreaterThan(inCentre.length());
      }
      const points: THREE.Vector3[] = [];
      for (let k = 0; k < 200; k++) {
        const z = 1 - (2 * (k + 0.5)) / 200;
        const a = k * 2.399963;
        points.push(new THREE.Vector3(Math.sqrt(1 - z * z) * Math.cos(a), Math.sqrt(1 - z * z) * Math.sin(a), z).multiplyScalar(3).add(centre));
      }
      const view = projection(cameraAt(pose, aspect), points);
      expect(view.inside, kind).toBe(true);
      // About two thirds of the narrower side (the height, in this wide view).
      expect(view.height, kind).toBeGreaterThan(0.5);
    }
  });
});
