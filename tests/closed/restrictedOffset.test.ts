import { describe, expect, it } from 'vitest';
import { ConfigError } from '../../src/core/config';
import { analyzeSurfaces, withMinBoundaryLength } from '../../src/core/analysis';
import { offsetClosedSurface } from '../../src/core/closed/closedOffset';
import { ellipsoidArea } from '../../src/core/closed/conicArc';
import { randomSequentialSites } from './randomSequentialSites';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import type { MeshGeometry } from '../../src/core/closed/restrictedSurface';
import { closestPointOnEllipsoid } from '../../src/core/cubemap/sample';
import { vertexNormals } from '../../src/core/mesh/types';
import { createRandom } from '../../src/core/random';
import { loadShipped } from '../mesh/helpers';

const dist = (p: ArrayLike<number>, q: ArrayLike<number>, i = 0, j = 0) => Math.hypot(p[i] - q[j], p[i + 1] - q[j + 1], p[i + 2] - q[j + 2]);

describe('offset surfaces of the stack', () => {
  it('"axes": sites lie on the ellipsoid (a + t, b + t, c + t) and are the closest points to the basal sites', () => {
    const a = 90,
      b = 45,
      c = 45,
      t = 12,
      count = 150;
    const basal = randomSequentialSites({ kind: 'ellipsoid', a, b, c }, count, 5, 4);
    const outer = offsetClosedSurface({ kind: 'ellipsoid', a, b, c }, basal.positions, basal.normals, count, t, 'axes');
    expect(outer.surface).toEqual({ kind: 'ellipsoid', a: a + t, b: b + t, c: c + t });
    // Closest: no point of the outer ellipsoid (dense random sample) is nearer to a basal site.
    const random = createRandom(1);
    const samples: number[] = [];
    for (let k = 0; k < 200000; k++) {
      const z = 2 * random.next() - 1,
        l = 2 * Math.PI * random.next(),
        r = Math.sqrt(1 - z * z);
      samples.push((a + t) * r * Math.cos(l), (b + t) * r * Math.sin(l), (c + t) * z);
    }
    let worstOn = 0,
      worstGap = Infinity,
      worstNormal = 0;
    for (let i = 0; i < count; i++) {
      const [x, y, z] = [outer.sites[3 * i], outer.sites[3 * i + 1], outer.sites[3 * i + 2]];
      worstOn = Math.max(worstOn, Math.abs(Math.hypot(x / (a + t), y / (b + t), z / (c + t)) - 1));
      const d = dist(basal.positions, outer.sites, 3 * i, 3 * i);
      let best = Infinity;
      for (let k = 0; k < samples.length; k += 3) best = Math.min(best, dist(basal.positions, samples, 3 * i, k));
      worstGap = Math.min(worstGap, best - d); // ≥ 0: nothing sampled is closer
      // Closest-point condition: basal - moved is along the outer normal.
      const n = [x / (a + t) ** 2, y / (b + t) ** 2, z / (c + t) ** 2];
      const nl = Math.hypot(n[0], n[1], n[2]);
      const v = [basal.positions[3 * i] - x, basal.positions[3 * i + 1] - y, basal.positions[3 * i + 2] - z];
      const cross = Math.hypot(v[1] * n[2] - v[2] * n[1], v[2] * n[0] - v[0] * n[2], v[0] * n[1] - v[1] * n[0]) / nl;
      worstNormal = Math.max(worstNormal, cross);
      expect(
        Math.abs(outer.normals[3 * i] - n[0] / nl) + Math.abs(outer.normals[3 * i + 1] - n[1] / nl) + Math.abs(outer.normals[3 * i + 2] - n[2] / nl),
      ).toBeLessThan(1e-9);
    }
    console.log(
      `axes offset +${t} µm: sites off the outer ellipsoid ≤ ${worstOn.toExponential(2)} (relative), sampled points at least ${worstGap.toExponential(2)} µm farther, tangential part of (basal - moved) ≤ ${worstNormal.toExponential(2)} µm`,
    );
    expect(worstOn).toBeLessThan(1e-12);
    expect(worstGap).toBeGreaterThanOrEqual(-1e-9);
    expect(worstNormal).toBeLessThan(1e-8);
    // And the diagram on it is the analytic one: areas add up to the outer ellipsoid's.
    const rvd = restrictedVoronoi(outer.surface, outer.sites, count);
    expect(Math.abs(rvd.adjacency.areas.reduce((s, v) => s + v, 0) / ellipsoidArea(a + t, b + t, c + t) - 1)).toBeLessThan(1e-9);
  });

  it('an inward parallel ellipsoid too close to its curvature radius for the triangle budget: a ConfigError on sheet.thickness saying what fits', () => {
    // 40:20:20 curves down to b²/a = 10 µm; at 9.99 µm inward the parallel surface needs > 2e6 triangles.
    let error: unknown;
    try {
      offsetClosedSurface({ kind: 'ellipsoid', a: 40, b: 20, c: 20 }, [40, 0, 0], [1, 0, 0], 30, -9.99, 'normal');
    } catch (e) {
      error = e;
    }
    expect(error).toBeInstanceOf(ConfigError);
    expect((error as ConfigError).field).toBe('sheet.thickness');
    const fits = Number((error as Error).message.match(/up to about ([\d.]+) µm/)![1]);
    expect(fits).toBeGreaterThan(5);
    expect(fits).toBeLessThan(9.99);
    expect((error as Error).message).toMatch(/or sheet\.adjacency "labels"$/);
  });

  it('"normal" on a sphere is the concentric sphere; on a mesh the vertices move along the area-weighted vertex normals', () => {
    const sphere = offsetClosedSurface({ kind: 'ellipsoid', a: 30, b: 30, c: 30 }, [30, 0, 0], [1, 0, 0], 1, -5, 'normal');
    expect(sphere.surface).toEqual({ kind: 'ellipsoid', a: 25, b: 25, c: 25 });
    expect(Array.from(sphere.sites)).toEqual([25, 0, 0]);
    const mesh = loadShipped('organoid.ply');
    const normals = vertexNormals(mesh); // today's rule (geometry image normals)
    const moved = offsetClosedSurface({ kind: 'mesh', positions: mesh.positions, indices: mesh.indices }, [], [], 0, 0.1, 'normal').surface as MeshGeometry;
    let worst = 0;
    for (let k = 0; k < mesh.positions.length; k++) worst = Math.max(worst, Math.abs(moved.positions[k] - (mesh.positions[k] + 0.1 * normals[k])));
    expect(worst).toBeLessThan(1e-6);
    expect(() => offsetClosedSurface({ kind: 'mesh', positions: mesh.positions, indices: mesh.indices }, [], [], 0, 1, 'axes')).toThrow(
      /^sheet\.offset: "axes"/,
    );
  });

  it('"normal" on an ellipsoid: a triangulated parallel surface within its stated deviation, sites on the exact one', () => {
    const a = 60,
      b = 40,
      c = 30,
      t = 8,
      count = 100;
    const basal = randomSequentialSites({ kind: 'ellipsoid', a, b, c }, count, 4, 6);
    const outer = offsetClosedSurface({ kind: 'ellipsoid', a, b, c }, basal.positions, basal.normals, count, t, 'normal', { maxDeviation: 0.01 });
    expect(outer.representation).toBe('triangulated');
    const m = outer.surface as MeshGeometry;
    // Distance to the base ellipsoid is t at the vertices (exact) and within t ± deviation at
    // the triangles' centroids and edge midpoints.
    let worstVertex = 0,
      worstInside = 0;
    const P = m.positions,
      T = m.indices;
    for (let v = 0; v < P.length; v += 3) {
      const q = closestPointOnEllipsoid([P[v], P[v + 1], P[v + 2]], a, b, c);
      worstVertex = Math.max(worstVertex, Math.abs(dist(P, q, v) - t));
    }
    for (let f = 0; f < T.length; f += 9) {
      const g = [0, 1, 2].map((k) => (P[3 * T[f] + k] + P[3 * T[f + 1] + k] + P[3 * T[f + 2] + k]) / 3);
      worstInside = Math.max(worstInside, Math.abs(dist(g, closestPointOnEllipsoid(g as [number, number, number], a, b, c)) - t));
    }
    let worstSite = 0;
    for (let i = 0; i < count; i++) {
      const q = closestPointOnEllipsoid([outer.sites[3 * i], outer.sites[3 * i + 1], outer.sites[3 * i + 2]], a, b, c);
      worstSite = Math.max(worstSite, Math.abs(dist(outer.sites, q, 3 * i) - t));
    }
    console.log(
      `parallel ellipsoid ${a}:${b}:${c} +${t} µm: ${T.length / 3} triangles, stated deviation ${outer.deviation.toExponential(2)} µm; vertices off by ≤ ${worstVertex.toExponential(2)}, centroids ≤ ${worstInside.toExponential(2)}, sites ≤ ${worstSite.toExponential(2)} µm`,
    );
    expect(worstVertex).toBeLessThan(1e-9);
    expect(worstSite).toBeLessThan(1e-9);
    expect(worstInside).toBeLessThanOrEqual(outer.deviation + 1e-9);
    expect(outer.deviation).toBeLessThanOrEqual(0.01);
    const rvd = restrictedVoronoi(outer.surface, outer.sites, count);
    expect(Array.from(rvd.adjacency.areas).every((v) => v > 0)).toBe(true);
    expect(() => offsetClosedSurface({ kind: 'ellipsoid', a, b, c }, basal.positions, basal.normals, count, -20, 'normal')).toThrow(
      /^sheet\.thickness: .*smallest radius of curvature/,
    );
  });
});

describe('the diagrams of a stack feed the analysis', () => {
  it('concentric spheres keep every neighbour (0 % scutoids); an ellipsoid under "axes" 20 µm out changes some', () => {
    const count = 200;
    const basal = randomSequentialSites({ kind: 'ellipsoid', a: 40, b: 40, c: 40 }, count, 3, 8);
    const stack = [0, 10, 20].map((t) => offsetClosedSurface({ kind: 'ellipsoid', a: 40, b: 40, c: 40 }, basal.positions, basal.normals, count, t, 'normal'));
    const surfaces = stack.map((s) => restrictedVoronoi(s.surface, s.sites, count).adjacency);
    expect(analyzeSurfaces(surfaces).summary.percentScutoids).toBe(0);
    const e = randomSequentialSites({ kind: 'ellipsoid', a: 90, b: 45, c: 45 }, count, 6, 8);
    const outer = offsetClosedSurface({ kind: 'ellipsoid', a: 90, b: 45, c: 45 }, e.positions, e.normals, count, 20, 'axes');
    const pair = [
      restrictedVoronoi({ kind: 'ellipsoid', a: 90, b: 45, c: 45 }, e.positions, count).adjacency,
      restrictedVoronoi(outer.surface, outer.sites, count).adjacency,
    ];
    const min = 0.5;
    const summary = analyzeSurfaces(pair.map((s) => withMinBoundaryLength(s, min))).summary;
    console.log(`ellipsoid 90:45:45, 200 RSA cells, "axes" +20 µm, contacts ≥ ${min} µm: ${summary.percentScutoids.toFixed(1)} % scutoids`);
    expect(summary.cells).toBe(count);
    expect(summary.percentScutoids).toBeGreaterThan(0);
  });
});

describe("the tests' random sequential addition (randomSequentialSites.ts)", () => {
  it('keeps the minimum distance, is reproducible, and is uniform in area on an ellipsoid', () => {
    const a = 80,
      b = 40,
      c = 40,
      count = 400,
      d = 4;
    const s1 = randomSequentialSites({ kind: 'ellipsoid', a, b, c }, count, d, 42);
    const s2 = randomSequentialSites({ kind: 'ellipsoid', a, b, c }, count, d, 42);
    expect(Array.from(s1.positions)).toEqual(Array.from(s2.positions));
    let closest = Infinity;
    for (let i = 0; i < count; i++) for (let j = i + 1; j < count; j++) closest = Math.min(closest, dist(s1.positions, s1.positions, 3 * i, 3 * j));
    expect(closest).toBeGreaterThanOrEqual(d);
    // Uniform in area: the share of sites with |x| < a/2 matches that band's share of the area
    // (computed from the prolate area formula of zones: area of |x| < h on a spheroid), 4 SE.
    const e = Math.sqrt(1 - (b * b) / (a * a));
    const zone = (h: number) => {
      const u = (e * h) / a;
      return 2 * Math.PI * b * (a / e) * (u * Math.sqrt(1 - u * u) + Math.asin(u));
    }; // ∫_{-h}^{h}
    const share = zone(a / 2) / zone(a);
    const inBand = Array.from({ length: count }, (_, i) => Math.abs(s1.positions[3 * i]) < a / 2).filter(Boolean).length / count;
    console.log(
      `RSA: ${count} sites ≥ ${d} µm apart (closest ${closest.toFixed(3)}), share in |x| < a/2: ${inBand.toFixed(3)} vs area share ${share.toFixed(3)}`,
    );
    expect(Math.abs(inBand - share)).toBeLessThan(4 * Math.sqrt((share * (1 - share)) / count));
    for (let i = 0; i < count; i++)
      expect(Math.abs(Math.hypot(s1.positions[3 * i] / a, s1.positions[3 * i + 1] / b, s1.positions[3 * i + 2] / c) - 1)).toBeLessThan(1e-12);
  });

  it('stops with a message naming minSpacing when the spacing cannot be reached', () => {
    // 200 discs of 20 µm on a sphere of radius 30 µm (area 11,310 µm²) would cover 5.6 times the surface.
    expect(() => randomSequentialSites({ kind: 'ellipsoid', a: 30, b: 30, c: 30 }, 200, 20, 1, { maxFailures: 2000 })).toThrow(
      /^minSpacing: placed only \d+ of 200 sites at least 20 µm apart.*fit up to about/,
    );
  });

  it('places sites on a mesh, on its triangles', () => {
    const mesh = loadShipped('egg-chamber.ply');
    const s = randomSequentialSites({ kind: 'mesh', positions: mesh.positions, indices: mesh.indices }, 100, 0.05, 3);
    let closest = Infinity;
    for (let i = 0; i < 100; i++) for (let j = i + 1; j < 100; j++) closest = Math.min(closest, dist(s.positions, s.positions, 3 * i, 3 * j));
    expect(closest).toBeGreaterThanOrEqual(0.05);
    for (let i = 0; i < 100; i++) expect(Math.abs(Math.hypot(s.normals[3 * i], s.normals[3 * i + 1], s.normals[3 * i + 2]) - 1)).toBeLessThan(1e-12);
  });
});
