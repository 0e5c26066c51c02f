/**
 * Synthetic label volumes built by the model's own construction, and their exact neighbours.
 *
 * - Tube (open, along z): sites (θ_i, z_i) on the inner cylinder of radius R1; a voxel at radius
 *   r in [R1, R2] takes the label of the nearest site in the unrolled metric at its own radius,
 *   (r Δθ)² + Δz² (the sites projected radially to its depth, as the model's tube layers are).
 *   On the cylinder of radius r this is exactly the periodic planar Voronoi diagram of
 *   (r θ_i, z_i): exactVoronoi gives its neighbours and true edge lengths.
 * - Ellipsoid shell (closed): sites on the inner ellipsoid (a, b, c); the voxel's depth t solves
 *   x²/(a+t)² + y²/(b+t)² + z²/(c+t)² = 1, and it takes the label of the nearest site scaled
 *   onto that ellipsoid (each axis by (a+t)/a, ...). On the ellipsoid of depth t this is exactly
 *   the restricted Voronoi diagram of the scaled sites: restrictedVoronoi gives it.
 * Voxels inside the inner surface are lumen (0, or a lumen label), beyond the outer one outside.
 */
import { exactVoronoi } from '../../src/core/exact';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import { createRandom } from '../../src/core/random';

export interface SyntheticVolume {
  width: number;
  height: number;
  depth: number;
  voxel: { x: number; y: number; z: number };
  /** Site index per voxel, -1 lumen, -2 outside. */
  site: Int32Array;
  sites: number;
  /** Exact contact lengths (µm) per surface at two depths bracketing the voxel surface: pair key i * sites + j (i < j). */
  exact: { inner: Map<number, number>[]; outer: Map<number, number>[] };
  /** Exact cell areas (µm²) on the inner and outer surfaces (closed shells only). */
  exactAreas?: { inner: Float64Array; outer: Float64Array };
}

export interface TubeSpec {
  width: number;
  height: number;
  depth: number;
  voxel: { x: number; y: number; z: number };
  inner: number;
  outer: number;
  sites: number;
  seed: number;
  /** The tube's axis (default z, through the pages). */
  axis?: 'x' | 'y' | 'z';
}

/** Random sites with a minimum distance (dart throwing), in a w x h box periodic in x. */
function dartThrow(count: number, w: number, h: number, minDistance: number, seed: number, periodicX: boolean): number[] {
  const random = createRandom(seed);
  const out: number[] = [];
  for (let tries = 0; out.length < 2 * count; tries++) {
    if (tries > 200000) throw new Error('dartThrow: cannot place the sites; lower the minimum distance');
    const x = random.next() * w;
    const y = random.next() * h;
    let ok = true;
    for (let k = 0; k < out.length && ok; k += 2) {
      let dx = Math.abs(x - out[k]);
      if (periodicX) dx = Math.min(dx, w - dx);
      if (dx * dx + (y - out[k + 1]) ** 2 < minDistance * minDistance) ok = false;
    }
    if (ok) out.push(x, y);
  }
  return out;
}

const pairKey = (i: number, j: number, n: number) => (i < j ? i * n + j : j * n + i);

export function tubeVolume(spec: TubeSpec): SyntheticVolume {
  const { width: W, height: H, depth: D, voxel, inner, outer, sites: n } = spec;
  const axis = spec.axis ?? 'z';
  // Voxel coordinates (µm) -> (across 1, across 2, along) for the tube's axis.
  const size = [W * voxel.x, H * voxel.y, D * voxel.z];
  const along = axis === 'x' ? 0 : axis === 'y' ? 1 : 2;
  const [a1, a2] = [0, 1, 2].filter((k) => k !== along);
  const length = size[along];
  const c1 = size[a1] / 2;
  const c2 = size[a2] / 2;
  // Sites in (arc length at the inner radius, along), spaced by 0.6 x the mean cell diameter.
  const circumference = 2 * Math.PI * inner;
  const xy = dartThrow(n, circumference, length, 0.6 * Math.sqrt((circumference * length) / n), spec.seed, true);
  const theta = Float64Array.from({ length: n }, (_, i) => xy[2 * i] / inner);
  const zs = Float64Array.from({ length: n }, (_, i) => xy[2 * i + 1]);
  const site = new Int32Array(W * H * D);
  const p = [0, 0, 0];
  for (let z = 0; z < D; z++) {
    p[2] = (z + 0.5) * voxel.z;
    for (let y = 0; y < H; y++) {
      p[1] = (y + 0.5) * voxel.y;
      for (let x = 0; x < W; x++) {
        p[0] = (x + 0.5) * voxel.x;
        const px = p[a1] - c1;
        const py = p[a2] - c2;
        const pz = p[along];
        const r = Math.hypot(px, py);
        const i = (z * H + y) * W + x;
        if (r < inner) site[i] = -1;
        else if (r > outer) site[i] = -2;
        else {
          const t = Math.atan2(py, px);
          let best = Infinity;
          let bestId = -1;
          for (let k = 0; k < n; k++) {
            let d = Math.abs(t - theta[k]);
            if (d > Math.PI) d = 2 * Math.PI - d;
            const du = r * d;
            const dz = pz - zs[k];
            const dd = du * du + dz * dz;
            if (dd < best) {
              best = dd;
              bestId = k;
            }
          }
          site[i] = bestId;
        }
      }
    }
  }
  const diagonal = Math.hypot([voxel.x, voxel.y, voxel.z][a1], [voxel.x, voxel.y, voxel.z][a2]);
  const lengthsAt = (r: number) => {
    const grid = { width: 1000, height: 1000, texelX: (2 * Math.PI * r) / 1000, texelY: length / 1000, periodicX: true, periodicY: false };
    const sitesTexel = new Float64Array(2 * n);
    for (let k = 0; k < n; k++) {
      sitesTexel[2 * k] = ((((theta[k] % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI)) / (2 * Math.PI)) * 1000;
      sitesTexel[2 * k + 1] = (zs[k] / length) * 1000;
    }
    const v = exactVoronoi(grid, sitesTexel);
    const out = new Map<number, number>();
    for (const cell of v.cells) cell.neighbours.forEach((j, k) => out.set(pairKey(cell.id, j, n), cell.lengths[k]));
    return out;
  };
  return {
    width: W,
    height: H,
    depth: D,
    voxel,
    site,
    sites: n,
    exact: { inner: [lengthsAt(inner), lengthsAt(inner + diagonal)], outer: [lengthsAt(outer - diagonal), lengthsAt(outer)] },
  };
}

export interface ShellSpec {
  voxel: { x: number; y: number; z: number };
  /** Inner semi-axes (µm) and thickness h (outer = inner + h on each axis). */
  a: number;
  b: number;
  c: number;
  h: number;
  sites: number;
  seed: number;
  /** Empty voxels around the shell on each side. */
  margin: number;
}

/** Depth t of point p: x²/(a+t)² + y²/(b+t)² + z²/(c+t)² = 1 (monotone in t; bisection). */
function depthOf(x: number, y: number, z: number, a: number, b: number, c: number): number {
  const f = (t: number) => (x / (a + t)) ** 2 + (y / (b + t)) ** 2 + (z / (c + t)) ** 2 - 1;
  let lo = -Math.min(a, b, c) + 1e-9;
  let hi = Math.hypot(x, y, z) + 1;
  if (f(lo) < 0) return lo;
  for (let k = 0; k < 60; k++) {
    const mid = 0.5 * (lo + hi);
    if (f(mid) > 0) lo = mid;
    else hi = mid;
  }
  return 0.5 * (lo + hi);
}

export function shellVolume(spec: ShellSpec): SyntheticVolume {
  const { voxel, a, b, c, h, sites: n, margin } = spec;
  const W = Math.ceil((2 * (a + h)) / voxel.x) + 2 * margin;
  const H = Math.ceil((2 * (b + h)) / voxel.y) + 2 * margin;
  const D = Math.ceil((2 * (c + h)) / voxel.z) + 2 * margin;
  const cx = (W * voxel.x) / 2;
  const cy = (H * voxel.y) / 2;
  const cz = (D * voxel.z) / 2;
  // Sites: random directions with a minimum angle, mapped onto the inner ellipsoid.
  const random = createRandom(spec.seed);
  const dirs: number[] = [];
  const minDot = Math.cos(0.6 * Math.sqrt((4 * Math.PI) / n));
  for (let tries = 0; dirs.length < 3 * n; tries++) {
    if (tries > 200000) throw new Error('shellVolume: cannot place the sites');
    const u = 2 * random.next() - 1;
    const phi = 2 * Math.PI * random.next();
    const s = Math.sqrt(1 - u * u);
    const d = [s * Math.cos(phi), s * Math.sin(phi), u];
    let ok = true;
    for (let k = 0; k < dirs.length && ok; k += 3) if (d[0] * dirs[k] + d[1] * dirs[k + 1] + d[2] * dirs[k + 2] > minDot) ok = false;
    if (ok) dirs.push(...d);
  }
  const sites = new Float64Array(3 * n);
  for (let k = 0; k < n; k++) {
    const [dx, dy, dz] = [dirs[3 * k], dirs[3 * k + 1], dirs[3 * k + 2]];
    const s = 1 / Math.hypot(dx / a, dy / b, dz / c);
    sites[3 * k] = dx * s;
    sites[3 * k + 1] = dy * s;
    sites[3 * k + 2] = dz * s;
  }
  const site = new Int32Array(W * H * D);
  for (let z = 0; z < D; z++) {
    const pz = (z + 0.5) * voxel.z - cz;
    for (let y = 0; y < H; y++) {
      const py = (y + 0.5) * voxel.y - cy;
      for (let x = 0; x < W; x++) {
        const px = (x + 0.5) * voxel.x - cx;
        const i = (z * H + y) * W + x;
        const t = depthOf(px, py, pz, a, b, c);
        if (t < 0) site[i] = -1;
        else if (t > h) site[i] = -2;
        else {
          const fx = (a + t) / a,
            fy = (b + t) / b,
            fz = (c + t) / c;
          let best = Infinity;
          let bestId = -1;
          for (let k = 0; k < n; k++) {
            const dd = (px - sites[3 * k] * fx) ** 2 + (py - sites[3 * k + 1] * fy) ** 2 + (pz - sites[3 * k + 2] * fz) ** 2;
            if (dd < best) {
              best = dd;
              bestId = k;
            }
          }
          site[i] = bestId;
        }
      }
    }
  }
  const areasAt: Float64Array[] = [];
  const lengthsAt = (t: number) => {
    const scaled = new Float64Array(3 * n);
    for (let k = 0; k < n; k++) {
      scaled[3 * k] = (sites[3 * k] * (a + t)) / a;
      scaled[3 * k + 1] = (sites[3 * k + 1] * (b + t)) / b;
      scaled[3 * k + 2] = (sites[3 * k + 2] * (c + t)) / c;
    }
    const rvd = restrictedVoronoi({ kind: 'ellipsoid', a: a + t, b: b + t, c: c + t }, scaled, n);
    if (t === 0 || t === h) areasAt[t === 0 ? 0 : 1] = rvd.adjacency.areas;
    const out = new Map<number, number>();
    const adj = rvd.adjacency;
    for (let i = 0; i < n; i++) {
      for (let k = adj.offsets[i]; k < adj.offsets[i + 1]; k++) out.set(pairKey(i, adj.neighbours[k], n), adj.lengths![k]);
    }
    return out;
  };
  const diagonal = Math.hypot(voxel.x, voxel.y, voxel.z);
  return {
    width: W,
    height: H,
    depth: D,
    voxel,
    site,
    sites: n,
    exact: { inner: [lengthsAt(0), lengthsAt(diagonal)], outer: [lengthsAt(h - diagonal), lengthsAt(h)] },
    exactAreas: { inner: areasAt[0], outer: areasAt[1] },
  };
}

/** The volume's labels: site k gets labels[k]; lumen gets `lumenLabel` (default 0), outside 0. */
export function labelData(volume: SyntheticVolume, labels: number[], bits: 8 | 16 | 32, lumenLabel = 0): Uint8Array | Uint16Array | Uint32Array {
  const n = volume.site.length;
  const out = bits === 8 ? new Uint8Array(n) : bits === 16 ? new Uint16Array(n) : new Uint32Array(n);
  for (let i = 0; i < n; i++) {
    const s = volume.site[i];
    out[i] = s >= 0 ? labels[s] : s === -1 ? lumenLabel : 0;
  }
  return out;
}

/** Pages of a volume for writeTiff (one page per z-slice). */
export function volumePages(
  volume: { width: number; height: number; depth: number },
  data: ArrayLike<number> & { subarray(a: number, b: number): ArrayLike<number> },
  bits: 8 | 16 | 32,
  first: Record<string, unknown> = {},
) {
  const plane = volume.width * volume.height;
  return Array.from({ length: volume.depth }, (_, z) => ({
    width: volume.width,
    height: volume.height,
    bitsPerSample: bits,
    data: data.subarray(z * plane, (z + 1) * plane),
    ...(z === 0 ? first : {}),
  }));
}

/** A random permutation of distinct labels from `from` upwards, spaced by `step`. */
export function permutedLabels(count: number, from: number, step: number, seed: number): number[] {
  const labels = Array.from({ length: count }, (_, k) => from + k * step);
  const random = createRandom(seed);
  for (let k = count - 1; k > 0; k--) {
    const j = random.nextInt(k + 1);
    [labels[k], labels[j]] = [labels[j], labels[k]];
  }
  return labels;
}

/** A BigTIFF (64-bit offsets, as OME-TIFF writers often produce) of 16-bit pages, one strip each, uncompressed. */
export function writeBigTiff(width: number, height: number, pages: ArrayLike<number>[], description?: string): Uint8Array {
  const le = true;
  const text = description === undefined ? null : new TextEncoder().encode(description + '\0');
  const entryCount = text ? 9 : 8;
  const ifdSize = 8 + 20 * entryCount + 8;
  const pageBytes = 2 * width * height;
  const textAt = 16;
  const dataAt = textAt + (text ? text.length + (text.length % 2) : 0);
  const ifdAt = (k: number) => dataAt + pages.length * pageBytes + k * ifdSize;
  const out = new Uint8Array(ifdAt(pages.length));
  const v = new DataView(out.buffer);
  out.set([0x49, 0x49]);
  v.setUint16(2, 43, le);
  v.setUint16(4, 8, le);
  v.setBigUint64(8, BigInt(ifdAt(0)), le);
  if (text) out.set(text, textAt);
  pages.forEach((page, k) => {
    for (let i = 0; i < width * height; i++) v.setUint16(dataAt + k * pageBytes + 2 * i, page[i], le);
    const at = ifdAt(k);
    const entries: [number, number, number | bigint][] = [
      [256, 4, width],
      [257, 4, height],
      [258, 3, 16],
      [259, 3, 1],
      [262, 3, 1],
      ...(text && k === 0 ? [[270, 2, BigInt(textAt)] as [number, number, bigint]] : []),
      [273, 16, BigInt(dataAt + k * pageBytes)],
      [277, 3, 1],
      [279, 16, BigInt(pageBytes)],
    ];
    v.setBigUint64(at, BigInt(entries.length), le);
    entries.forEach(([tag, type, value], e) => {
      const o = at + 8 + 20 * e;
      v.setUint16(o, tag, le);
      v.setUint16(o + 2, type, le);
      v.setBigUint64(o + 4, BigInt(tag === 270 ? text!.length : 1), le);
      if (type === 3) v.setUint16(o + 12, Number(value), le);
      else if (type === 4) v.setUint32(o + 12, Number(value), le);
      else v.setBigUint64(o + 12, BigInt(value), le);
    });
    v.setBigUint64(at + 8 + 20 * entries.length, BigInt(k + 1 < pages.length ? ifdAt(k + 1) : 0), le);
  });
  return out;
}
