import { describe, expect, it } from 'vitest';
import { flipOrientation, icosphere, torusMesh } from '../../src/core/mesh/generate';
import { applyMobius, countFlipped, sphereCenterOfMass, sphericalParameterization, sphericalTriangleArea } from '../../src/core/mesh/spherical';
import { faceAreas } from '../../src/core/mesh/types';
import { GENUS_ZERO_SHIPPED, loadShipped } from './helpers';

describe('sphericalParameterization', () => {
  for (const file of GENUS_ZERO_SHIPPED) {
    it(`${file}: unit sphere, no flipped triangle, centred mass, spherical areas sum to 4π`, () => {
      const mesh = loadShipped(file);
      const r = sphericalParameterization(mesh);
      const s = r.sphere;
      for (let v = 0; v < s.length; v += 3) expect(Math.hypot(s[v], s[v + 1], s[v + 2])).toBeCloseTo(1, 12);
      expect(r.flipped).toBe(0);
      expect(countFlipped(mesh.indices, s)).toBe(0);
      // Centre of mass recomputed independently of the returned value.
      const mu = sphereCenterOfMass(mesh.indices, s, faceAreas(mesh));
      expect(Math.hypot(...mu)).toBeLessThan(1e-6);
      let omega = 0;
      for (let f = 0; f < mesh.indices.length; f += 3) omega += sphericalTriangleArea(s, mesh.indices[f], mesh.indices[f + 1], mesh.indices[f + 2]);
      expect(omega).toBeCloseTo(4 * Math.PI, 8);
      expect(r.areaDistortion.min).toBeGreaterThan(0.1);
      expect(r.areaDistortion.max).toBeLessThan(10);
    });
  }

  it('an icosphere maps close to itself (up to rotation): near area preserving', () => {
    const r = sphericalParameterization(icosphere(10));
    expect(r.flipped).toBe(0);
    expect(r.areaDistortion.meanAbsLog).toBeLessThan(0.05);
    expect(r.areaDistortion.min).toBeGreaterThan(0.8);
    expect(r.areaDistortion.max).toBeLessThan(1.25);
  });

  it('handles an inward-oriented mesh (reports it, still no flip relative to its faces reversed)', () => {
    const mesh = flipOrientation(icosphere(6));
    const r = sphericalParameterization(mesh);
    expect(r.inward).toBe(true);
    expect(r.flipped).toBe(0);
    expect(countFlipped(flipOrientation(mesh).indices, r.sphere)).toBe(0);
  });

  it('refuses a torus with the genus message', () => {
    expect(() => sphericalParameterization(torusMesh(1, 0.4, 24, 12))).toThrow(/genus 1: this mesh has a hole through it/);
  });
});

describe('Möbius map of Baden et al.', () => {
  const c: [number, number, number] = [0.3, -0.2, 0.1];
  /** Largest change of a triangle corner angle under the Möbius map, on an icosphere. */
  function worstAngleChange(frequency: number): number {
    const mesh = icosphere(frequency);
    const s = Float64Array.from(mesh.positions);
    const before = s.slice();
    applyMobius(s, c);
    const t = mesh.indices;
    let worst = 0;
    for (let f = 0; f < t.length; f += 3) {
      const ang = (q: Float64Array) => {
        const [a, b, cc] = [t[f], t[f + 1], t[f + 2]];
        const u = [0, 1, 2].map((k) => q[3 * b + k] - q[3 * a + k]);
        const w = [0, 1, 2].map((k) => q[3 * cc + k] - q[3 * a + k]);
        return Math.acos((u[0] * w[0] + u[1] * w[1] + u[2] * w[2]) / Math.hypot(...u) / Math.hypot(...w));
      };
      worst = Math.max(worst, Math.abs(ang(s) - ang(before)));
    }
    return worst;
  }

  it('keeps points on the unit sphere and moves mass towards c', () => {
    const mesh = icosphere(4);
    const s = Float64Array.from(mesh.positions);
    applyMobius(s, c);
    for (let v = 0; v < s.length; v += 3) expect(Math.hypot(s[v], s[v + 1], s[v + 2])).toBeCloseTo(1, 12);
    const mu = sphereCenterOfMass(mesh.indices, s, faceAreas(mesh));
    expect(mu[0] * c[0] + mu[1] * c[1] + mu[2] * c[2]).toBeGreaterThan(0);
  });

  it('is conformal: corner angles of ever smaller triangles change ever less (first order in size)', () => {
    const coarse = worstAngleChange(6),
      fine = worstAngleChange(24);
    expect(fine).toBeLessThan(coarse / 2.5);
    expect(fine).toBeLessThan(0.05);
  });
});
