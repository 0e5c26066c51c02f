import { describe, expect, it } from 'vitest';
import { directionToTexel, texelDirection } from '../../src/core/cubemap/cubemap';
import { BufferAttribute, BufferGeometry, Vector3 } from 'three';
import { MeshBVH } from 'three-mesh-bvh';
import { closestPointOnEllipsoid, sampleSurface } from '../../src/core/cubemap/sample';
import { icosphere, mulberry32 } from '../../src/core/mesh/generate';
import { sphericalParameterization } from '../../src/core/mesh/spherical';
import type { TriangleMesh, Vec3 } from '../../src/core/mesh/types';
import { loadShipped, surfaceArea } from './helpers';

interface ProjectedPoint {
  point: Vec3;
  /** Triangle of the mesh the point lies on. */
  triangle: number;
  distance: number;
}

/**
 * Closest-point projector onto a triangle mesh from three-mesh-bvh's MeshBVH.closestPointToPoint:
 * an oracle independent of the sampler (build once, project many points).
 */
function createMeshProjector(mesh: TriangleMesh): (p: Vec3) => ProjectedPoint {
  const g = new BufferGeometry();
  g.setAttribute('position', new BufferAttribute(mesh.positions.slice(), 3));
  g.setIndex(new BufferAttribute(mesh.indices.slice(), 1));
  const bvh = new MeshBVH(g, { indirect: true });
  const q = new Vector3();
  const target = { point: new Vector3(), distance: 0, faceIndex: 0 };
  return (p: Vec3) => {
    bvh.closestPointToPoint(q.set(p[0], p[1], p[2]), target);
    return { point: [target.point.x, target.point.y, target.point.z], triangle: target.faceIndex, distance: target.distance };
  };
}

/** Ellipsoid area by a fine midpoint rule in (θ, φ) over p = (a sinθ cosφ, b sinθ sinφ, c cosθ). */
function ellipsoidAreaNumerical(a: number, b: number, c: number, nt = 1500, np = 3000): number {
  let s = 0;
  const dt = Math.PI / nt,
    dp = (2 * Math.PI) / np;
  for (let i = 0; i < nt; i++) {
    const th = (i + 0.5) * dt;
    const st = Math.sin(th),
      ct = Math.cos(th);
    for (let j = 0; j < np; j++) {
      const ph = (j + 0.5) * dp;
      const cp = Math.cos(ph),
        sp = Math.sin(ph);
      s += st * Math.sqrt(b * b * c * c * st * st * cp * cp + a * a * c * c * st * st * sp * sp + a * a * b * b * ct * ct);
    }
  }
  return s * dt * dp;
}

describe('sampleSurface area elements sum to the surface area (n = 128)', () => {
  it('sphere: exact', () => {
    const img = sampleSurface({ kind: 'sphere', radius: 3 }, 128);
    expect(Math.abs(img.totalArea / (4 * Math.PI * 9) - 1)).toBeLessThan(1e-10);
    let s = 0;
    for (const x of img.area) s += x;
    expect(Math.abs(s / img.totalArea - 1)).toBeLessThan(1e-6);
  });

  it('triaxial ellipsoid vs a fine numerical integral, and the prolate 2:1:1 closed form', () => {
    const img = sampleSurface({ kind: 'ellipsoid', a: 3, b: 2, c: 1 }, 128);
    expect(Math.abs(img.totalArea / ellipsoidAreaNumerical(3, 2, 1) - 1)).toBeLessThan(0.005);
    const e = Math.sqrt(1 - 1 / 4);
    const prolate = 2 * Math.PI * (1 + (2 / e) * Math.asin(e));
    expect(Math.abs(sampleSurface({ kind: 'ellipsoid', a: 2, b: 1, c: 1 }, 128).totalArea / prolate - 1)).toBeLessThan(0.005);
  });

  it('ellipsoid texels: positions on the surface, normals unit and along the gradient', () => {
    const [a, b, c] = [3, 2, 1];
    const img = sampleSurface({ kind: 'ellipsoid', a, b, c }, 16);
    for (let k = 0; k < img.area.length; k++) {
      const [x, y, z] = [img.position[3 * k], img.position[3 * k + 1], img.position[3 * k + 2]];
      expect((x / a) ** 2 + (y / b) ** 2 + (z / c) ** 2).toBeCloseTo(1, 5);
      const g = [x / (a * a), y / (b * b), z / (c * c)];
      const gl = Math.hypot(...g);
      const n = [img.normal[3 * k], img.normal[3 * k + 1], img.normal[3 * k + 2]];
      expect((g[0] * n[0] + g[1] * n[1] + g[2] * n[2]) / gl).toBeCloseTo(1, 5);
    }
  });

  it('shipped organoid mesh: sum equals the triangle area sum; texels lie on the mesh', () => {
    const mesh = loadShipped('organoid.ply');
    const { sphere } = sphericalParameterization(mesh);
    const img = sampleSurface({ kind: 'mesh', mesh, sphere }, 128);
    expect(Math.abs(img.totalArea / surfaceArea(mesh) - 1)).toBeLessThan(0.005);
    const project = createMeshProjector(mesh);
    const rnd = mulberry32(5);
    for (let s = 0; s < 300; s++) {
      const k = Math.floor(rnd() * img.area.length);
      const q = project([img.position[3 * k], img.position[3 * k + 1], img.position[3 * k + 2]]);
      expect(q.distance).toBeLessThan(1e-5);
      expect(img.barycentric![3 * k] + img.barycentric![3 * k + 1] + img.barycentric![3 * k + 2]).toBeCloseTo(1, 5);
    }
  });

  it('mesh of the unit sphere parameterized to itself: texel positions ≈ texel directions', () => {
    const mesh = icosphere(12);
    const sphere = Float64Array.from(mesh.positions, (x) => x);
    for (let v = 0; v < sphere.length; v += 3) {
      const l = Math.hypot(sphere[v], sphere[v + 1], sphere[v + 2]);
      for (let c = 0; c < 3; c++) sphere[v + c] /= l;
    }
    const n = 32;
    const img = sampleSurface({ kind: 'mesh', mesh, sphere }, n);
    let worst = 0;
    for (let k = 0; k < img.area.length; k++) {
      const p: Vec3 = [img.position[3 * k], img.position[3 * k + 1], img.position[3 * k + 2]];
      const t = directionToTexel(p, n);
      const d = texelDirection(t.face, t.i, t.j, n);
      const l = Math.hypot(...p);
      worst = Math.max(worst, Math.hypot(p[0] / l - d[0], p[1] / l - d[1], p[2] / l - d[2]));
    }
    expect(worst).toBeLessThan(1e-5);
  });
});

describe('closest-point projectors', () => {
  it('closestPointOnEllipsoid: on the surface, p - x along the normal, no surface point closer', () => {
    const rnd = mulberry32(1);
    const axes: Vec3[] = [
      [2, 1, 1],
      [3, 2, 1],
      [1, 1.5, 2],
    ];
    for (const [a, b, c] of axes) {
      for (let s = 0; s < 40; s++) {
        const p: Vec3 = [4 * (rnd() - 0.5) * a, 4 * (rnd() - 0.5) * b, 4 * (rnd() - 0.5) * c];
        if (s % 5 === 0) p[2] = 0; // points in a symmetry plane, including the degenerate case
        const x = closestPointOnEllipsoid(p, a, b, c);
        expect((x[0] / a) ** 2 + (x[1] / b) ** 2 + (x[2] / c) ** 2).toBeCloseTo(1, 9);
        const dist = Math.hypot(p[0] - x[0], p[1] - x[1], p[2] - x[2]);
        // Optimality: p - x is parallel to the surface normal (the gradient) at x.
        const g = [x[0] / (a * a), x[1] / (b * b), x[2] / (c * c)];
        const e = [p[0] - x[0], p[1] - x[1], p[2] - x[2]];
        const cr = Math.hypot(g[1] * e[2] - g[2] * e[1], g[2] * e[0] - g[0] * e[2], g[0] * e[1] - g[1] * e[0]);
        expect(cr / (Math.hypot(...g) * Math.max(dist, 1e-12))).toBeLessThan(1e-6);
        // Brute force over a fine (θ, φ) grid.
        let best = Infinity;
        for (let i = 0; i <= 90; i++) {
          const th = (Math.PI * i) / 90;
          for (let j = 0; j < 180; j++) {
            const ph = (2 * Math.PI * j) / 180;
            const q = [a * Math.sin(th) * Math.cos(ph), b * Math.sin(th) * Math.sin(ph), c * Math.cos(th)];
            best = Math.min(best, Math.hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]));
          }
        }
        expect(dist).toBeLessThanOrEqual(best + 1e-9);
        expect(dist).toBeGreaterThan(best - 0.05 * Math.max(a, b, c));
      }
    }
  });

  it('closestPointOnEllipsoid on a spheroid (b = c), from a point on its long axis: a point of the closest circle', () => {
    // Inside |x| < a - b²/a the closest points to (x, 0, 0) form a circle around the axis; the
    // projector returned the point itself (a Lloyd centroid on a 100:5:5 tip ended the run).
    for (const [a, b, c] of [
      [100, 5, 5],
      [5, 100, 5],
      [5, 5, 100],
    ] as Vec3[]) {
      const long = a > b ? 0 : b > c ? 1 : 2;
      const p: Vec3 = [0, 0, 0];
      p[long] = 96.1;
      const x = closestPointOnEllipsoid(p, a, b, c);
      expect((x[0] / a) ** 2 + (x[1] / b) ** 2 + (x[2] / c) ** 2).toBeCloseTo(1, 12);
      const r = [a, b, c][long];
      const short = 5;
      // The circle: along the axis at r² q / (r² - s²), at radius s·sqrt(1 - (that / r)²).
      const along = (r * r * 96.1) / (r * r - short * short);
      expect(x[long]).toBeCloseTo(along, 9);
      expect(Math.hypot(...x.filter((_, k) => k !== long))).toBeCloseTo(short * Math.sqrt(1 - (along / r) ** 2), 9);
    }
  });

  it('createMeshProjector: points pushed off an icosphere come back to distance ≈ |offset|', () => {
    const mesh = icosphere(8);
    const project = createMeshProjector(mesh);
    const q = project([0, 0, 2]);
    expect(q.distance).toBeGreaterThan(1 - 1e-3);
    expect(q.distance).toBeLessThan(1.01);
    expect(q.point[2]).toBeGreaterThan(0.98);
    expect(q.triangle).toBeGreaterThanOrEqual(0);
  });
});
