/**
 * Procedural closed meshes: the sample meshes shipped in public/meshes (see
 * scripts/make-meshes.ts) and the fixtures of the tests. Generating them keeps the
 * repository free of third-party mesh files and their licences, and lets tests pick sizes.
 */
import { weldVertices } from './parse';
import { signedVolume, type TriangleMesh, type Vec3 } from './types';

/** Small seeded PRNG (mulberry32): the generated meshes must be reproducible byte for byte. */
export function mulberry32(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

const PHI = (1 + Math.sqrt(5)) / 2;
const ICO_V = [-1, PHI, 0, 1, PHI, 0, -1, -PHI, 0, 1, -PHI, 0, 0, -1, PHI, 0, 1, PHI, 0, -1, -PHI, 0, 1, -PHI, PHI, 0, -1, PHI, 0, 1, -PHI, 0, -1, -PHI, 0, 1];
const ICO_F = [
  0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4,
  11, 6, 2, 10, 8, 6, 7, 9, 8, 1,
];

/**
 * Unit geodesic sphere: each icosahedron face split into `frequency`² triangles, projected to
 * the sphere. 10 f² + 2 vertices, 20 f² faces (f = 30 gives 9002 vertices, close to the
 * 8896-vertex mesh of the seed document). Outward (counter-clockwise) orientation.
 */
export function icosphere(frequency: number): TriangleMesh {
  const n = Math.max(1, Math.floor(frequency));
  const pos: number[] = [];
  const idx: number[] = [];
  for (let f = 0; f < 20; f++) {
    const [A, B, C] = [0, 1, 2].map((k) => ICO_V.slice(3 * ICO_F[3 * f + k], 3 * ICO_F[3 * f + k] + 3));
    const base = pos.length / 3;
    const id = (i: number, j: number) => base + (j * (2 * n + 3 - j)) / 2 + i; // row j has n + 1 - j points
    for (let j = 0; j <= n; j++) {
      for (let i = 0; i <= n - j; i++) {
        const p = [0, 1, 2].map((c) => A[c] + ((B[c] - A[c]) * i) / n + ((C[c] - A[c]) * j) / n);
        const l = Math.hypot(p[0], p[1], p[2]);
        pos.push(p[0] / l, p[1] / l, p[2] / l);
      }
    }
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n - j; i++) {
        idx.push(id(i, j), id(i + 1, j), id(i, j + 1));
        if (i + j < n - 1) idx.push(id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
      }
    }
  }
  const mesh = weldVertices({ positions: new Float32Array(pos), indices: new Uint32Array(idx) }, 1e-7);
  return signedVolume(mesh) < 0 ? flipOrientation(mesh) : mesh;
}

export function flipOrientation(mesh: TriangleMesh): TriangleMesh {
  const t = mesh.indices.slice();
  for (let f = 0; f < t.length; f += 3) [t[f + 1], t[f + 2]] = [t[f + 2], t[f + 1]];
  return { positions: mesh.positions, indices: t };
}

/** Applies `f` to every vertex (a new mesh; topology shared). */
export function mapVertices(mesh: TriangleMesh, f: (p: Vec3) => Vec3): TriangleMesh {
  const out = new Float32Array(mesh.positions.length);
  for (let i = 0; i < out.length; i += 3) {
    const q = f([mesh.positions[i], mesh.positions[i + 1], mesh.positions[i + 2]]);
    out.set(q, i);
  }
  return { positions: out, indices: mesh.indices };
}

/** Ellipsoid with semi-axes a, b, c (an icosphere stretched along the axes). */
export function ellipsoidMesh(a: number, b: number, c: number, frequency: number): TriangleMesh {
  return mapVertices(icosphere(frequency), ([x, y, z]) => [a * x, b * y, c * z]);
}

/**
 * Organoid-like blob: a sphere with smooth random low-frequency radial bumps,
 * r(d) = radius (1 + Σ a_k cos(ω_k · d + φ_k)), |ω_k| ≤ 3 so bumps are a few per hemisphere.
 */
export function bumpySphere(frequency: number, seed: number, amplitude = 0.08, radius = 1): TriangleMesh {
  const rnd = mulberry32(seed);
  const waves = Array.from({ length: 6 }, () => {
    const w = [rnd() - 0.5, rnd() - 0.5, rnd() - 0.5];
    const l = Math.hypot(w[0], w[1], w[2]) || 1;
    const k = 1.5 + 1.5 * rnd();
    return { w: w.map((x) => (x / l) * k), phase: 2 * Math.PI * rnd(), amp: (amplitude * (0.5 + rnd())) / 2 };
  });
  return mapVertices(icosphere(frequency), (d) => {
    let r = 1;
    for (const { w, phase, amp } of waves) r += amp * Math.cos(w[0] * d[0] + w[1] * d[1] + w[2] * d[2] + phase);
    return [radius * r * d[0], radius * r * d[1], radius * r * d[2]];
  });
}

/**
 * Level-set blob: the iso-surface F(x) = Σ_i exp(-|x - c_i|² / s_i²) = iso of a few Gaussian
 * "metaballs" near the origin (like pygalmesh's custom level-set example in the seed), meshed
 * by shooting each icosphere vertex direction from the origin to the outermost crossing.
 */
export function levelSetBlob(frequency: number, seed: number): TriangleMesh {
  const rnd = mulberry32(seed);
  const balls = Array.from({ length: 5 }, (_, i) => ({
    c: i === 0 ? [0, 0, 0] : [0.5 * (rnd() - 0.5), 0.5 * (rnd() - 0.5), 0.5 * (rnd() - 0.5)],
    s: 0.55 + 0.2 * rnd(),
  }));
  const iso = 0.5;
  const F = (x: number, y: number, z: number) => {
    let v = 0;
    for (const { c, s } of balls) v += Math.exp(-((x - c[0]) ** 2 + (y - c[1]) ** 2 + (z - c[2]) ** 2) / (s * s));
    return v - iso;
  };
  return mapVertices(icosphere(frequency), ([dx, dy, dz]) => {
    let lo = 0,
      hi = 3;
    // Outermost crossing: march inward from far away, then bisect.
    for (let r = 3; r > 0; r -= 0.02) {
      if (F(r * dx, r * dy, r * dz) > 0) {
        lo = r;
        hi = r + 0.02;
        break;
      }
    }
    for (let k = 0; k < 40; k++) {
      const m = (lo + hi) / 2;
      if (F(m * dx, m * dy, m * dz) > 0) lo = m;
      else hi = m;
    }
    const r = (lo + hi) / 2;
    return [r * dx, r * dy, r * dz];
  });
}

/** Torus (genus 1) around the z axis: major radius R, minor radius r. */
export function torusMesh(R: number, r: number, nu: number, nv: number): TriangleMesh {
  const pos = new Float32Array(nu * nv * 3);
  const idx: number[] = [];
  for (let i = 0; i < nu; i++) {
    const u = (2 * Math.PI * i) / nu;
    for (let j = 0; j < nv; j++) {
      const v = (2 * Math.PI * j) / nv;
      pos.set([(R + r * Math.cos(v)) * Math.cos(u), (R + r * Math.cos(v)) * Math.sin(u), r * Math.sin(v)], 3 * (i * nv + j));
      const a = i * nv + j,
        b = ((i + 1) % nu) * nv + j,
        c = ((i + 1) % nu) * nv + ((j + 1) % nv),
        d = i * nv + ((j + 1) % nv);
      idx.push(a, b, c, a, c, d);
    }
  }
  const mesh = { positions: pos, indices: new Uint32Array(idx) };
  return signedVolume(mesh) < 0 ? flipOrientation(mesh) : mesh;
}

/** Keeps the faces for which `keep(faceIndex)` holds and drops vertices no longer used. */
export function selectFaces(mesh: TriangleMesh, keep: (f: number) => boolean): TriangleMesh {
  const t = mesh.indices;
  const remap = new Int32Array(mesh.positions.length / 3).fill(-1);
  const pos: number[] = [];
  const idx: number[] = [];
  for (let f = 0; f < t.length / 3; f++) {
    if (!keep(f)) continue;
    for (let k = 0; k < 3; k++) {
      const v = t[3 * f + k];
      if (remap[v] < 0) {
        remap[v] = pos.length / 3;
        pos.push(mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]);
      }
      idx.push(remap[v]);
    }
  }
  return { positions: new Float32Array(pos), indices: new Uint32Array(idx) };
}

/** A sphere with a hole: the icosphere without the faces around the north pole (z > cos θ). */
export function openSphere(frequency: number, holeAngle = 0.5): TriangleMesh {
  const s = icosphere(frequency);
  const p = s.positions,
    t = s.indices;
  return selectFaces(s, (f) => {
    const z = (p[3 * t[3 * f] + 2] + p[3 * t[3 * f + 1] + 2] + p[3 * t[3 * f + 2] + 2]) / 3;
    return z < Math.cos(holeAngle);
  });
}
