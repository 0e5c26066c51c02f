/**
 * Pure geometry of closed sheets on cube-map geometry images (no GL): initial sites, offset
 * (apical) surfaces, label adjacency across face edges, and the curvature bound for offsets of a mesh.
 */
import { ConfigError } from '../config/configError';
import type { SurfaceAdjacency } from '../analysis/adjacency';
import { ContactRows, type ContactLength } from '../labels';
import { texelFromIndex, texelIndex, wrapTexel } from '../cubemap/cubemap';
import type { CubeGeometryImage } from '../cubemap/sample';
import type { TriangleMesh } from '../mesh/types';
import { crossOfDifferences, vertexNormals } from '../mesh/types';
import { createRandom, searchCdf } from '../random';
import { directionTexel, PROJECTION_STRIDE, type ClosedProjector } from './projector';

/** Sites on a closed surface: xyz, unit normal, atlas texel per site. */
export interface ClosedSites {
  readonly count: number;
  /** x, y, z per site, µm. */
  readonly positions: Float64Array;
  /** Unit outward normal per site. */
  readonly normals: Float64Array;
  /** Parameter direction per site (unit). */
  readonly directions: Float64Array;
  /** Atlas index of the cube-map texel each site lies in. */
  readonly texels: Int32Array;
}

export function allocateSites(count: number): ClosedSites {
  return {
    count,
    positions: new Float64Array(3 * count),
    normals: new Float64Array(3 * count),
    directions: new Float64Array(3 * count),
    texels: new Int32Array(count),
  };
}

/** Copies one projector output (the first PROJECTION_STRIDE values of `buffer`) for site i into `sites`, with its texel on an n-texel map. */
export function storeProjection(sites: ClosedSites, i: number, buffer: Float64Array, n: number): void {
  for (let c = 0; c < 3; c++) {
    sites.positions[3 * i + c] = buffer[c];
    sites.normals[3 * i + c] = buffer[3 + c];
    sites.directions[3 * i + c] = buffer[6 + c];
  }
  sites.texels[i] = directionTexel(buffer[6], buffer[7], buffer[8], n);
}

/**
 * Random sites, uniform in surface area: a texel is drawn with probability proportional to
 * its area element, a point uniform in its face-plane square is taken and projected onto the
 * surface (the texel's point plus the jitter). With minSpacing > 0, dart throwing in 3D
 * (Euclidean distance; a hash grid of cells minSpacing wide). Reproducible from `seed`.
 */
export function placeClosedSites(image: CubeGeometryImage, projector: ClosedProjector, count: number, seed: number, minSpacing: number): ClosedSites {
  const { n, area, position } = image;
  const texels = 6 * n * n;
  const cdf = new Float64Array(texels);
  let total = 0;
  for (let k = 0; k < texels; k++) cdf[k] = total += area[k];
  const random = createRandom(seed);
  const sites = allocateSites(count);
  const buffer = new Float64Array(PROJECTION_STRIDE);
  const cell = minSpacing > 0 ? minSpacing : 1;
  const hash = new Map<string, number[]>();
  const key = (x: number, y: number, z: number) => `${Math.floor(x / cell)},${Math.floor(y / cell)},${Math.floor(z / cell)}`;
  let placed = 0;
  let failures = 0;
  const taken = new Set<number>();
  while (placed < count) {
    if (failures > 20000) {
      // A config the surface cannot hold (exit 2 naming the field; a sweep records the point).
      throw new ConfigError(
        'minSpacing',
        `minSpacing: could place only ${placed} of ${count} sites at least ${minSpacing} µm apart; lower minSpacing or cells`,
      );
    }
    const texel = searchCdf(cdf, texels, random.next() * total);
    // Jitter within the texel: up to half the spacing towards the neighbours along i and j
    // (wrapped across face edges), then onto the surface.
    const { face, i, j } = texelFromIndex(texel, n);
    const ju = random.next() - 0.5,
      jv = random.next() - 0.5;
    const ni = wrapTexel(face, i + (ju >= 0 ? 1 : -1), j, n);
    const nj = wrapTexel(face, i, j + (jv >= 0 ? 1 : -1), n);
    const ki = texelIndex(ni.face, ni.i, ni.j, n),
      kj = texelIndex(nj.face, nj.i, nj.j, n);
    const fu = Math.abs(ju),
      fv = Math.abs(jv);
    const x = position[3 * texel] + fu * (position[3 * ki] - position[3 * texel]) + fv * (position[3 * kj] - position[3 * texel]);
    const y = position[3 * texel + 1] + fu * (position[3 * ki + 1] - position[3 * texel + 1]) + fv * (position[3 * kj + 1] - position[3 * texel + 1]);
    const z = position[3 * texel + 2] + fu * (position[3 * ki + 2] - position[3 * texel + 2]) + fv * (position[3 * kj + 2] - position[3 * texel + 2]);
    projector.project(x, y, z, buffer, 0);
    const px = buffer[0],
      py = buffer[1],
      pz = buffer[2];
    if (minSpacing > 0) {
      let close = false;
      const cx = Math.floor(px / cell),
        cy = Math.floor(py / cell),
        cz = Math.floor(pz / cell);
      for (let a = -1; a <= 1 && !close; a++) {
        for (let b = -1; b <= 1 && !close; b++) {
          for (let c = -1; c <= 1 && !close; c++) {
            for (const id of hash.get(`${cx + a},${cy + b},${cz + c}`) ?? []) {
              const d = Math.hypot(sites.positions[3 * id] - px, sites.positions[3 * id + 1] - py, sites.positions[3 * id + 2] - pz);
              if (d < minSpacing) {
                close = true;
                break;
              }
            }
          }
        }
      }
      if (close) {
        failures++;
        continue;
      }
    }
    storeProjection(sites, placed, buffer, n);
    // Two sites in one texel would splat over each other: draw again.
    if (taken.has(sites.texels[placed])) {
      failures++;
      continue;
    }
    taken.add(sites.texels[placed]);
    if (minSpacing > 0) {
      const k = key(px, py, pz);
      const list = hash.get(k);
      if (list) list.push(placed);
      else hash.set(k, [placed]);
    }
    failures = 0;
    placed++;
  }
  return sites;
}

/** The four wrapped neighbours (i±1, j±1) of every texel, atlas indices (4 per texel: -i, +i, -j, +j). */
export function texelNeighbours(n: number): Int32Array {
  const out = new Int32Array(4 * 6 * n * n);
  for (let f = 0; f < 6; f++) {
    for (let j = 0; j < n; j++) {
      for (let i = 0; i < n; i++) {
        const k = texelIndex(f, i, j, n);
        const steps: [number, number][] = [
          [i - 1, j],
          [i + 1, j],
          [i, j - 1],
          [i, j + 1],
        ];
        steps.forEach(([a, b], s) => {
          const w = wrapTexel(f, a, b, n);
          out[4 * k + s] = texelIndex(w.face, w.i, w.j, n);
        });
      }
    }
  }
  return out;
}

/** A surface of the stack: per-texel points and area elements. */
export interface CubeSurfaceSample {
  readonly n: number;
  readonly position: Float32Array;
  readonly area: Float32Array;
  readonly totalArea: number;
}

/**
 * The parallel surface at signed distance t along the normal: point + t·normal per texel, and
 * the area element scaled by the ratio of the tangent-plane areas after and before the offset,
 * from central differences over the (wrapped) texel neighbours (exactly ((R + t)/R)² up to
 * rounding on a sphere). t = 0 returns the image itself.
 */
export function offsetSurface(image: CubeGeometryImage, t: number, neighbours = texelNeighbours(image.n)): CubeSurfaceSample {
  const { n, position: P, normal: N, area: A } = image;
  if (t === 0) return { n, position: P, area: A, totalArea: image.totalArea };
  const count = 6 * n * n;
  const position = new Float32Array(3 * count);
  for (let k = 0; k < 3 * count; k++) position[k] = P[k] + t * N[k];
  const area = new Float32Array(count);
  let total = 0;
  const cross = new Float64Array(3);
  const crossNorm = (X: ArrayLike<number>, k: number) => {
    const n = crossOfDifferences(X, neighbours[4 * k], neighbours[4 * k + 1], neighbours[4 * k + 2], neighbours[4 * k + 3], cross);
    return Math.hypot(n[0], n[1], n[2]);
  };
  for (let k = 0; k < count; k++) {
    const before = crossNorm(P, k);
    const ratio = before > 0 ? crossNorm(position, k) / before : 1;
    area[k] = A[k] * ratio;
    total += area[k];
  }
  return { n, position, area, totalArea: total };
}

/**
 * Cell adjacency of a cube-map label image, as the adjacency record (src/core/analysis/adjacency.ts):
 * areas as sums of the texels' area elements, `border` all 0 (a closed surface has no open edge).
 * Every pair of edge-adjacent texels (4-neighbourhood, across face edges through the edge
 * table) with different labels adds their shared texel edge to both cells' boundary.
 *
 * The 'staircase' length sums the edges, each estimated as (A_k + A_l) / (2 |p_k - p_l|) (the
 * texels' extent across the line joining their centres): a staircase, 1 to 1.41 times the
 * true length of a contact.
 *
 * The 'true' length (the default) removes that bias. Each shared texel edge is taken as a 3D vector: it runs along
 * the parameter line between the two texels (the other axis than the step between them), from
 * the central difference of the texel's wrapped neighbours, and is oriented so that the cell
 * with the smaller id lies on its left (the cube faces' (s, t) frames all have the same
 * handedness about the outward normal, so this holds across face edges too). Oriented edges of
 * a staircase add up to the vector between its ends (the back-and-forth steps cancel), so per
 * pair and per cube face the length of the summed vector is the chord of that piece of the
 * contact, and the pair's length is the sum of those chords over the faces. A contact is a
 * plane section of the surface (a bisector plane): on a sphere a great-circle arc, which the
 * gnomonic cube map draws as a straight line on each face, so the per-face chord is its length
 * up to about one texel edge; on an ellipsoid or a mesh the arcs are nearly straight over one
 * cell (chord/arc - 1 is about θ²/24 for an arc turning by θ). Chosen over summing the two
 * axes' edges separately and taking sqrt(Lu² + Lv²) (the planar labels' rule) because the
 * face frames here are not orthogonal (60° to 120° between the axes near cube corners), which
 * that rule cannot see, and over a sub-texel polyline because it needs only the labels.
 * Splitting by face keeps a contact that goes all round the surface (two cells) from summing to
 * 0. Measured against the restricted Voronoi diagram: tests/closed/labelLengths.test.ts.
 */
export function cubeLabelAdjacency(
  surface: CubeSurfaceSample,
  labels: ArrayLike<number>,
  count: number,
  neighbours = texelNeighbours(surface.n),
  length: ContactLength = 'true',
  label?: string,
): SurfaceAdjacency {
  const { position: P, area: A } = surface;
  const texelCount = labels.length;
  const perFace = surface.n * surface.n;
  const area = new Float64Array(count);
  const pairs = new Map<number, number>();
  // Per (pair, face): slot of its summed oriented edge vector in `chords` (x, y, z per slot).
  const slots = new Map<number, number>();
  let chords = new Float64Array(3 * 1024);
  for (let k = 0; k < texelCount; k++) {
    const a = labels[k];
    if (a < 0) continue;
    area[a] += A[k];
    // All 4 neighbours, each undirected texel pair counted once from its smaller index (across
    // a face edge the neighbour's axes are rotated, so "+i and +j only" would miss pairs).
    for (let s = 0; s < 4; s++) {
      const l = neighbours[4 * k + s];
      if (l <= k) continue;
      const b = labels[l];
      if (b < 0 || b === a) continue;
      const d = Math.hypot(P[3 * k] - P[3 * l], P[3 * k + 1] - P[3 * l + 1], P[3 * k + 2] - P[3 * l + 2]);
      const length = d > 0 ? (A[k] + A[l]) / (2 * d) : 0;
      const key = Math.min(a, b) * count + Math.max(a, b);
      pairs.set(key, (pairs.get(key) ?? 0) + length);

      // The shared edge: along j for a step in i (s = 0, 1), along i for a step in j (s = 2, 3);
      // steps +i, -j give +axis and -i, +j give -axis (the step turned by +90° in the face
      // frame), with the smaller id on k's side; flipped otherwise.
      const along = s < 2 ? 2 : 0;
      const from = neighbours[4 * k + along],
        to = neighbours[4 * k + along + 1];
      const sign = (s === 1 || s === 2 ? 0.5 : -0.5) * (a < b ? 1 : -1);
      const slotKey = key * 6 + Math.floor(k / perFace);
      let slot = slots.get(slotKey);
      if (slot === undefined) {
        slot = slots.size;
        slots.set(slotKey, slot);
        if (3 * slot + 3 > chords.length) {
          const grown = new Float64Array(2 * chords.length);
          grown.set(chords);
          chords = grown;
        }
      }
      chords[3 * slot] += sign * (P[3 * to] - P[3 * from]);
      chords[3 * slot + 1] += sign * (P[3 * to + 1] - P[3 * from + 1]);
      chords[3 * slot + 2] += sign * (P[3 * to + 2] - P[3 * from + 2]);
    }
  }
  const unbiased = new Map<number, number>();
  for (const [slotKey, slot] of slots) {
    const key = Math.floor(slotKey / 6);
    const chord = Math.hypot(chords[3 * slot], chords[3 * slot + 1], chords[3 * slot + 2]);
    unbiased.set(key, (unbiased.get(key) ?? 0) + chord);
  }
  const degree = new Int32Array(count + 1);
  for (const key of pairs.keys()) {
    degree[Math.floor(key / count) + 1]++;
    degree[(key % count) + 1]++;
  }
  for (let c = 0; c < count; c++) degree[c + 1] += degree[c];
  const offsets = degree;
  const rows = new ContactRows(offsets, count);
  const sorted = [...pairs.entries()].sort((x, y) => x[0] - y[0]);
  for (const [key, staircase] of sorted) {
    const a = Math.floor(key / count),
      b = key % count;
    rows.add(a, b, unbiased.get(key)!, staircase);
  }
  const lengths = length === 'true' ? rows.lengths : rows.staircaseLengths;
  return { count, offsets, neighbours: rows.neighbours, lengths, areas: area, border: new Uint8Array(count), label };
}

/**
 * Smallest radii of curvature of a mesh, estimated per edge from the vertex normals:
 * κ_ij = (n_i - n_j)·(p_i - p_j) / |p_i - p_j|² (the normal curvature along the edge).
 * `convex`: 1 / max κ over edges with κ > 0 (an inward offset this far folds);
 * `concave`: 1 / max(-κ) over edges with κ < 0 (an outward offset this far folds);
 * Infinity when no edge bends that way. Edge estimates are noisy on coarse meshes: a bound,
 * not an exact value.
 */
export function meshCurvatureRadii(mesh: TriangleMesh): { convex: number; concave: number } {
  const p = mesh.positions,
    t = mesh.indices;
  const nrm = vertexNormals(mesh);
  let kPlus = 0,
    kMinus = 0;
  for (let f = 0; f < t.length; f += 3) {
    for (let e = 0; e < 3; e++) {
      const i = t[f + e],
        j = t[f + ((e + 1) % 3)];
      if (i > j) continue;
      const dx = p[3 * i] - p[3 * j],
        dy = p[3 * i + 1] - p[3 * j + 1],
        dz = p[3 * i + 2] - p[3 * j + 2];
      const l2 = dx * dx + dy * dy + dz * dz;
      if (!(l2 > 0)) continue;
      const k = ((nrm[3 * i] - nrm[3 * j]) * dx + (nrm[3 * i + 1] - nrm[3 * j + 1]) * dy + (nrm[3 * i + 2] - nrm[3 * j + 2]) * dz) / l2;
      if (k > kPlus) kPlus = k;
      if (-k > kMinus) kMinus = -k;
    }
  }
  return { convex: kPlus > 0 ? 1 / kPlus : Infinity, concave: kMinus > 0 ? 1 / kMinus : Infinity };
}
