import { describe, expect, it } from 'vitest';
import {
  CUBE_EDGES,
  CUBE_FACES,
  directionToTexel,
  texelDirection,
  texelEdgeTable,
  texelFromIndex,
  texelIndex,
  texelSolidAngle,
  wrapTexel,
  type Vec3,
} from '../../src/core/cubemap/cubemap';

const angle = (a: Vec3, b: Vec3) => Math.acos(Math.min(1, Math.max(-1, a[0] * b[0] + a[1] * b[1] + a[2] * b[2])));
const cross = (a: Vec3, b: Vec3): Vec3 => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];

describe('cube-map frames (OpenGL convention)', () => {
  it('each face frame is orthonormal and the six normals are the ±axes', () => {
    const normals = new Set<string>();
    for (const F of CUBE_FACES) {
      for (const [u, v] of [
        [F.normal, F.s],
        [F.normal, F.t],
        [F.s, F.t],
      ] as const)
        expect(u[0] * v[0] + u[1] * v[1] + u[2] * v[2]).toBe(0);
      // s × t points inward for every face (GL cube maps are "seen from inside"): consistent handedness.
      const c = cross(F.s, F.t);
      expect(c[0] * F.normal[0] + c[1] * F.normal[1] + c[2] * F.normal[2]).toBe(-1);
      normals.add(F.normal.join(','));
    }
    expect(normals.size).toBe(6);
  });

  it('matches the GL table on known directions', () => {
    // +X face: s = -z, t = -y. Direction (1, -0.5, -0.5) is at u = 0.5, v = 0.5.
    const n = 8;
    expect(directionToTexel([1, -0.5, -0.5], n)).toMatchObject({ face: 0, u: 0.5, v: 0.5, i: 6, j: 6 });
    expect(directionToTexel([0, 0, -1], n).face).toBe(5);
    expect(directionToTexel([0.2, 1, 0.9], n)).toMatchObject({ face: 2, i: 4, j: 7 });
  });

  it('texel -> direction -> texel and index round trips', () => {
    const n = 16;
    for (let f = 0; f < 6; f++) {
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const t = directionToTexel(texelDirection(f, i, j, n), n);
          expect([t.face, t.i, t.j]).toEqual([f, i, j]);
          expect(texelFromIndex(texelIndex(f, i, j, n), n)).toEqual({ face: f, i, j });
        }
      }
    }
  });

  it('exact texel solid angles sum to 4π and are symmetric; the corner/centre ratio tends to 1/(3√3)', () => {
    for (const n of [1, 7, 64]) {
      let s = 0;
      for (let j = 0; j < n; j++) for (let i = 0; i < n; i++) s += texelSolidAngle(i, j, n);
      expect(6 * s).toBeCloseTo(4 * Math.PI, 12);
    }
    expect(texelSolidAngle(0, 3, 16)).toBeCloseTo(texelSolidAngle(15, 12, 16), 14);
    const n = 512;
    expect(texelSolidAngle(0, 0, n) / texelSolidAngle(n / 2, n / 2, n)).toBeCloseTo(1 / (3 * Math.sqrt(3)), 2);
    // A single texel is close to its projected-area estimate dA cos / r², (2/n)² / (1+u²+v²)^{3/2}.
    const u = (2 * (10 + 0.5)) / 64 - 1,
      v = (2 * (40 + 0.5)) / 64 - 1;
    expect(texelSolidAngle(10, 40, 64) / ((2 / 64) ** 2 / (1 + u * u + v * v) ** 1.5)).toBeCloseTo(1, 3);
  });
});

describe('crossing face edges', () => {
  it('the neighbour across each edge is the face whose normal is that edge direction, and tables are mutually inverse', () => {
    for (let f = 0; f < 6; f++) {
      const seen = new Set<number>();
      for (let e = 0; e < 4; e++) {
        const T = CUBE_EDGES[f][e];
        expect(T.face).not.toBe(f);
        expect(Math.abs(CUBE_FACES[T.face].normal.reduce((s, x, k) => s + x * CUBE_FACES[f].normal[k], 0))).toBe(0);
        seen.add(T.face);
        // Rotation by a multiple of 90°: orthogonal integer 2x2 with det +1 (no mirror).
        expect(T.a * T.e - T.b * T.d).toBe(1);
      }
      expect(seen.size).toBe(4);
    }
  });

  it('texels just off an edge land on the adjacent texel of the neighbour face (direction check)', () => {
    const n = 32;
    for (let f = 0; f < 6; f++) {
      for (let k = 0; k < n; k++) {
        for (const [i, j] of [
          [-1, k],
          [n, k],
          [k, -1],
          [k, n],
        ]) {
          const w = wrapTexel(f, i, j, n);
          // The texel it lands on contains the direction of the extended face-plane point.
          const d = texelDirection(f, i, j, n);
          const t = directionToTexel(d, n);
          expect([w.face, w.i, w.j]).toEqual([t.face, t.i, t.j]);
        }
      }
    }
  });

  it('stepping off an edge and back returns to the same texel (any step length up to n)', () => {
    const n = 16;
    for (let f = 0; f < 6; f++) {
      for (let k = 0; k < n; k++) {
        for (let step = 1; step <= n; step++) {
          // Start on an edge row/column and step outward by `step` in each of the 4 directions.
          for (const [i0, j0, di, dj] of [
            [n - 1, k, 1, 0],
            [0, k, -1, 0],
            [k, n - 1, 0, 1],
            [k, 0, 0, -1],
          ]) {
            const out = wrapTexel(f, i0 + di * step, j0 + dj * step, n);
            expect(out.face).not.toBe(f);
            // The step direction in the neighbour's frame: rotate (di, dj) by the edge transform.
            const e = di > 0 ? 1 : di < 0 ? 0 : dj > 0 ? 3 : 2;
            const T = CUBE_EDGES[f][e];
            const bi = -(T.a * di + T.b * dj),
              bj = -(T.d * di + T.e * dj);
            const back = wrapTexel(out.face, out.i + bi * step, out.j + bj * step, n);
            expect(back).toEqual({ face: f, i: i0, j: j0 });
          }
        }
      }
    }
  });

  it("every texel's 8 neighbours are distinct from it and at a similar angular distance", () => {
    const n = 24;
    let worst = 0;
    let best = Infinity;
    for (let f = 0; f < 6; f++) {
      for (let j = 0; j < n; j++) {
        for (let i = 0; i < n; i++) {
          const d = texelDirection(f, i, j, n);
          const size = Math.sqrt(texelSolidAngle(i, j, n));
          for (let dj = -1; dj <= 1; dj++) {
            for (let di = -1; di <= 1; di++) {
              if (di === 0 && dj === 0) continue;
              const w = wrapTexel(f, i + di, j + dj, n);
              expect(w.i >= 0 && w.i < n && w.j >= 0 && w.j < n).toBe(true);
              const r = angle(d, texelDirection(w.face, w.i, w.j, n)) / size;
              worst = Math.max(worst, r);
              best = Math.min(best, r);
            }
          }
        }
      }
    }
    // Straight neighbours are ~1 texel away, diagonal ones ~√2; at a cube corner the missing
    // fourth face makes the diagonal fall on a texel next to the corner.
    expect(best).toBeGreaterThan(0.6);
    expect(worst).toBeLessThan(2);
  });

  it('texelEdgeTable is the integer form of CUBE_EDGES', () => {
    const n = 10;
    const table = texelEdgeTable(n);
    for (let f = 0; f < 6; f++) {
      for (let e = 0; e < 4; e++) {
        const T = CUBE_EDGES[f][e];
        const o = (f * 4 + e) * 7;
        const [i, j] = e === 0 ? [-1, 3] : e === 1 ? [n, 3] : e === 2 ? [3, -1] : [3, n];
        const u = ((i + 0.5) * 2) / n - 1,
          v = ((j + 0.5) * 2) / n - 1;
        const u2 = T.a * u + T.b * v + T.c,
          v2 = T.d * u + T.e * v + T.f;
        expect(table[o]).toBe(T.face);
        expect(table[o + 1] * i + table[o + 2] * j + table[o + 3]).toBeCloseTo(((u2 + 1) / 2) * n - 0.5, 10);
        expect(table[o + 4] * i + table[o + 5] * j + table[o + 6]).toBeCloseTo(((v2 + 1) / 2) * n - 0.5, 10);
      }
    }
  });
});
