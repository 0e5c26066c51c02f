/**
 * References (test oracles) for the cube-map passes, from their definitions: the nearest site
 * of every texel by 3D distance (what the cube-map jump flood approximates), and a direction's
 * texel by the OpenGL cube-map face rule (what directionTexel and directionToTexel compute).
 */

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

/**
 * The atlas index of a direction's texel, from the OpenGL cube-map table (OpenGL 4.6, table
 * 8.19): the face is the axis of largest |component| (ties: x before y before z, + before -),
 * its face coordinates are sc / |ma|, tc / |ma| as the table gives them, texel (i, j) of an
 * n x n face covers [2i/n - 1, 2(i+1)/n - 1] along sc (the last texel holds 1), and texel
 * (face, i, j) is stored at (face · n + j) · n + i (src/core/cubemap/cubemap.ts's layout).
 */
export function directionTexelReference(x: number, y: number, z: number, n: number): number {
  const ax = Math.abs(x),
    ay = Math.abs(y),
    az = Math.abs(z);
  let face: number, sc: number, tc: number, ma: number;
  if (ax >= ay && ax >= az) [face, sc, tc, ma] = x >= 0 ? [0, -z, -y, ax] : [1, z, -y, ax];
  else if (ay >= az) [face, sc, tc, ma] = y >= 0 ? [2, x, z, ay] : [3, x, -z, ay];
  else [face, sc, tc, ma] = z >= 0 ? [4, x, -y, az] : [5, -x, -y, az];
  const cell = (c: number) => Math.min(n - 1, Math.max(0, Math.floor(((c / ma + 1) / 2) * n)));
  return (face * n + cell(tc)) * n + cell(sc);
}

/**
 * Per site, 5 sums over the texels labelled with it, from the definition of a cube-map cell's
 * centroid (the atlas's points and area elements, 3D offsets from the site): [Σ w·dx, Σ w·dy,
 * Σ w·dz, Σ w, Σ w·|d|²] with d = point − site (µm) and w the texel's area (µm²) — the
 * quantities the GPU centroid paths sum (SUMS_STRIDE order). Float64, texel by texel; texels
 * labelled -1 are skipped.
 */
export function cubeReduceCentroids(
  position: ArrayLike<number>,
  area: ArrayLike<number>,
  labels: ArrayLike<number>,
  sites: ArrayLike<number>,
  count: number,
): Float64Array {
  const sums = new Float64Array(5 * count);
  for (let k = 0; k < labels.length; k++) {
    const id = labels[k];
    if (id < 0) continue;
    if (id >= count) throw new Error(`cubeReduceCentroids: label ${id} at texel ${k} but only ${count} sites`);
    const w = area[k];
    const dx = position[3 * k] - sites[3 * id],
      dy = position[3 * k + 1] - sites[3 * id + 1],
      dz = position[3 * k + 2] - sites[3 * id + 2];
    sums[5 * id] += w * dx;
    sums[5 * id + 1] += w * dy;
    sums[5 * id + 2] += w * dz;
    sums[5 * id + 3] += w;
    sums[5 * id + 4] += w * (dx * dx + dy * dy + dz * dz);
  }
  return sums;
}
