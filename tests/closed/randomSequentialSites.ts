/**
 * Sites for the restricted Voronoi tests and bench/restrictedVoronoi.ts, seeded as the lab seeds
 * closed surfaces (the product's placement is placeClosedSites in src/core/closed/geometry.ts, on
 * the cube-map geometry image): random sites uniform in surface area with a minimum
 * distance, by random sequential addition (RSA): draw a uniform point, keep it when it is at
 * least `minSpacing` µm (3D Euclidean distance) from every site kept so far, otherwise draw
 * again. Reproducible from `seed`. Pure: no Lloyd, no GPU.
 *
 * - ellipsoid / sphere: a uniform direction x on the unit sphere is accepted with probability
 *   w(x) / max w, w(x) = |M⁻¹ x| (M = diag(a, b, c)), the ellipsoid's area element pulled back
 *   to the sphere over abc; the point is M x, its normal M⁻¹ x normalised.
 * - mesh: a triangle with probability proportional to its area, a uniform point in it
 *   (√r barycentrics); the normal is the barycentric mix of the area-weighted vertex normals
 *   (as the mesh projector interpolates), normalised.
 *
 * RSA jams: on a surface of area A, discs of diameter d stop fitting near a covered fraction
 * of 0.547 (the 2D jamming limit), N π d² / 4 ≈ 0.547 A. The work is bounded: after
 * `maxFailures` draws in a row that were too close, it stops with a ConfigError on
 * `minSpacing` (the config's fault: exit 2) and the largest spacing that is likely to fit. Neighbour checks use a hash
 * grid of cells `minSpacing` wide (typed arrays, collisions checked by distance).
 */
import { ConfigError } from '../../src/core/config/configError';
import { createRandom, searchCdf } from '../../src/core/random';
import { RSA_JAMMING_COVERAGE } from '../../src/core/sites';
import { areaWeightedVertexNormals, triangleArea } from '../../src/core/mesh/types';
import { ellipsoidArea } from '../../src/core/closed/conicArc';
import type { RestrictedSurface } from '../../src/core/closed/restrictedSurface';

export interface RandomSequentialOptions {
  /** Consecutive rejected draws before giving up (default 20,000). */
  maxFailures?: number;
}

export interface SeededSites {
  readonly count: number;
  /** x, y, z per site, µm, on the surface. */
  readonly positions: Float64Array;
  /** Unit outward normal per site. */
  readonly normals: Float64Array;
  /** Draws made in all (accepted + rejected). */
  readonly draws: number;
}

export function randomSequentialSites(
  surface: RestrictedSurface,
  count: number,
  minSpacing: number,
  seed: number,
  options: RandomSequentialOptions = {},
): SeededSites {
  if (!(Number.isInteger(count) && count >= 1)) throw new Error(`cells: ${count} is not a positive whole number of sites`);
  if (!(Number.isFinite(minSpacing) && minSpacing >= 0)) throw new Error(`minSpacing: ${minSpacing} is not a distance ≥ 0 in µm`);
  const maxFailures = options.maxFailures ?? 20000;
  const random = createRandom(seed);
  const positions = new Float64Array(3 * count),
    normals = new Float64Array(3 * count);
  const draw =
    surface.kind === 'ellipsoid' ? ellipsoidSampler(surface.a, surface.b, surface.c, random) : meshSampler(surface.positions, surface.indices, random);
  const area = surface.kind === 'ellipsoid' ? ellipsoidArea(surface.a, surface.b, surface.c) : draw.area;
  // Hash grid: bucket heads per hashed cell, one link per site.
  const tableSize = 1 << Math.max(4, Math.ceil(Math.log2(2 * count)));
  const head = new Int32Array(tableSize).fill(-1);
  const next = new Int32Array(count);
  const cell = minSpacing > 0 ? minSpacing : 1;
  const hash = (ix: number, iy: number, iz: number) => ((Math.imul(ix, 73856093) ^ Math.imul(iy, 19349663) ^ Math.imul(iz, 83492791)) >>> 0) & (tableSize - 1);
  const point = new Float64Array(6);
  let placed = 0,
    failures = 0,
    draws = 0;
  while (placed < count) {
    if (failures >= maxFailures) {
      const fit = Math.sqrt((4 * RSA_JAMMING_COVERAGE * area) / (Math.PI * count));
      throw new ConfigError(
        'minSpacing',
        `minSpacing: placed only ${placed} of ${count} sites at least ${minSpacing} µm apart (${maxFailures} draws in a row fell closer); random sequential addition jams near ${RSA_JAMMING_COVERAGE * 100} % coverage, so ${count} sites on ${area.toPrecision(4)} µm² fit up to about ${fit.toPrecision(3)} µm apart; lower minSpacing or the number of cells`,
      );
    }
    draws++;
    draw.sample(point);
    const x = point[0],
      y = point[1],
      z = point[2];
    const ix = Math.floor(x / cell),
      iy = Math.floor(y / cell),
      iz = Math.floor(z / cell);
    let close = false;
    if (minSpacing > 0) {
      const d2 = minSpacing * minSpacing;
      for (let a = -1; a <= 1 && !close; a++) {
        for (let b = -1; b <= 1 && !close; b++) {
          for (let c = -1; c <= 1 && !close; c++) {
            for (let s = head[hash(ix + a, iy + b, iz + c)]; s >= 0; s = next[s]) {
              const dx = positions[3 * s] - x,
                dy = positions[3 * s + 1] - y,
                dz = positions[3 * s + 2] - z;
              if (dx * dx + dy * dy + dz * dz < d2) {
                close = true;
                break;
              }
            }
          }
        }
      }
    }
    if (close) {
      failures++;
      continue;
    }
    failures = 0;
    for (let k = 0; k < 3; k++) {
      positions[3 * placed + k] = point[k];
      normals[3 * placed + k] = point[3 + k];
    }
    const h = hash(ix, iy, iz);
    next[placed] = head[h];
    head[h] = placed++;
  }
  return { count, positions, normals, draws };
}

interface Sampler {
  /** Writes a uniform surface point and its unit normal into out[0..5]. */
  sample(out: Float64Array): void;
  area: number;
}

function ellipsoidSampler(a: number, b: number, c: number, random: { next(): number }): Sampler {
  const wMax = 1 / Math.min(a, b, c);
  return {
    area: 0,
    sample(out) {
      for (;;) {
        // Uniform direction: z uniform in [-1, 1], longitude uniform (Archimedes).
        const z = 2 * random.next() - 1,
          l = 2 * Math.PI * random.next();
        const r = Math.sqrt(Math.max(0, 1 - z * z));
        const x = r * Math.cos(l),
          y = r * Math.sin(l);
        const nx = x / a,
          ny = y / b,
          nz = z / c;
        const w = Math.hypot(nx, ny, nz);
        if (random.next() * wMax > w) continue;
        out[0] = a * x;
        out[1] = b * y;
        out[2] = c * z;
        out[3] = nx / w;
        out[4] = ny / w;
        out[5] = nz / w;
        return;
      }
    },
  };
}

function meshSampler(P: ArrayLike<number>, T: ArrayLike<number>, random: { next(): number }): Sampler {
  const nf = T.length / 3;
  const cdf = new Float64Array(nf);
  let total = 0;
  for (let f = 0; f < nf; f++) {
    total += triangleArea(P, T, f);
    cdf[f] = total;
  }
  const N = areaWeightedVertexNormals(P, T);
  return {
    area: total,
    sample(out) {
      const triangle = searchCdf(cdf, nf, random.next() * total);
      const s = Math.sqrt(random.next()),
        u = random.next();
      const wa = 1 - s,
        wb = s * (1 - u),
        wc = s * u;
      const a = 3 * T[3 * triangle],
        b = 3 * T[3 * triangle + 1],
        c = 3 * T[3 * triangle + 2];
      let nx = 0,
        ny = 0,
        nz = 0;
      for (let k = 0; k < 3; k++) out[k] = wa * P[a + k] + wb * P[b + k] + wc * P[c + k];
      nx = wa * N[a] + wb * N[b] + wc * N[c];
      ny = wa * N[a + 1] + wb * N[b + 1] + wc * N[c + 1];
      nz = wa * N[a + 2] + wb * N[b + 2] + wc * N[c + 2];
      const l = Math.hypot(nx, ny, nz) || 1;
      out[3] = nx / l;
      out[4] = ny / l;
      out[5] = nz / l;
    },
  };
}
