/**
 * References (test oracles) for the cube-map passes, from their definitions: the nearest site
 * of every texel by 3D distance (what the cube-map jump flood approximates), and a direction's
 * texel by the cube map's own face rule (what the fast directionTexel computes).
 */
import { directionToTexel, texelIndex } from '../../src/core/cubemap/cubemap';

/**
 * Exact nearest-site labels of every texel by 3D distance (ties: smaller id), the reference
 * for the jump flood. Sites are bucketed in a 3D grid; O(texels · sites in nearby buckets).
 */
export function cubeBruteForceLabels(position: ArrayLike<number>, sites: ArrayLike<number>, count: number): Int32Array {
  const texels = position.length / 3;
  const out = new Int32Array(texels);
  let lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < count; i++)
    for (let c = 0; c < 3; c++) {
      lo[c] = Math.min(lo[c], sites[3 * i + c]);
      hi[c] = Math.max(hi[c], sites[3 * i + c]);
    }
  lo = lo.map((v) => v - 1e-9);
  const extent = Math.max(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-9);
  const side = Math.max(1, Math.round(Math.cbrt(count / 2) * 2));
  const size = (extent / side) * 1.0000001;
  const bucket = (v: number, c: number) => Math.max(0, Math.min(side - 1, Math.floor((v - lo[c]) / size)));
  const lists: number[][] = Array.from({ length: side ** 3 }, () => []);
  for (let i = 0; i < count; i++) lists[(bucket(sites[3 * i], 0) * side + bucket(sites[3 * i + 1], 1)) * side + bucket(sites[3 * i + 2], 2)].push(i);
  for (let k = 0; k < texels; k++) {
    const x = position[3 * k],
      y = position[3 * k + 1],
      z = position[3 * k + 2];
    const bx = bucket(x, 0),
      by = bucket(y, 1),
      bz = bucket(z, 2);
    let best = -1,
      bestD = Infinity;
    for (let ring = 0; ring <= side; ring++) {
      // A site in ring r+1 or beyond is at least (r + distance to the bucket wall) away; stop
      // once the best distance is below r · size (conservative).
      if (best >= 0 && Math.sqrt(bestD) < (ring - 1) * size) break;
      for (let a = bx - ring; a <= bx + ring; a++) {
        for (let b = by - ring; b <= by + ring; b++) {
          for (let c = bz - ring; c <= bz + ring; c++) {
            if (Math.max(Math.abs(a - bx), Math.abs(b - by), Math.abs(c - bz)) !== ring) continue;
            if (a < 0 || b < 0 || c < 0 || a >= side || b >= side || c >= side) continue;
            for (const i of lists[(a * side + b) * side + c]) {
              const dx = sites[3 * i] - x,
                dy = sites[3 * i + 1] - y,
                dz = sites[3 * i + 2] - z;
              const d = dx * dx + dy * dy + dz * dz;
              if (d < bestD || (d === bestD && i < best)) {
                bestD = d;
                best = i;
              }
            }
          }
        }
      }
    }
    out[k] = best;
  }
  return out;
}

/** directionToTexel's atlas index (the reference for directionTexel). */
export function directionTexelReference(dx: number, dy: number, dz: number, n: number): number {
  const t = directionToTexel([dx, dy, dz], n);
  return texelIndex(t.face, t.i, t.j, n);
}
