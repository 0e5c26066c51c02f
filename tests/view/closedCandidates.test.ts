import { describe, expect, it } from 'vitest';
import { texelDirection, texelFromIndex } from '../../src/core/cubemap/cubemap';
import { validateConfig } from '../../src/core/config';
import type { LabelImage } from '../../src/run';
import { runSheet } from '../../src/run/runSheet';
import { atlasTopology, closedSurfaceMesh } from '../../src/view/cubeAtlasMesh';
import { CANDIDATES, nearestCandidate, sitePositions, vertexCandidates } from '../../src/view/closedCandidates';
import { viewStack } from '../../src/view/stack';
import { createRandom } from '../../src/core/random';
import { useHeadlessContext } from '../gpu/context';

const context = useHeadlessContext();

/** The site nearest to (x, y, z) by brute force: the restricted Voronoi cell there. */
function nearestSite(sites: Float32Array, x: number, y: number, z: number): number {
  let best = -1;
  let bestDistance = Infinity;
  for (let i = 0; i < sites.length / 3; i++) {
    const d = (x - sites[3 * i]) ** 2 + (y - sites[3 * i + 1]) ** 2 + (z - sites[3 * i + 2]) ** 2;
    if (d < bestDistance) {
      bestDistance = d;
      best = i;
    }
  }
  return best;
}

/** Random sites on a sphere and the atlas labelled by brute force (what the flood computes). */
function sphereAtlas(n: number, count: number, radius: number, seed: number): { image: LabelImage; sites: Float32Array } {
  const rng = createRandom(seed);
  const random = () => rng.next();
  const sites = new Float32Array(3 * count);
  for (let i = 0; i < count; i++) {
    const z = 2 * random() - 1,
      phi = 2 * Math.PI * random(),
      r = Math.sqrt(1 - z * z);
    sites.set([radius * r * Math.cos(phi), radius * r * Math.sin(phi), radius * z], 3 * i);
  }
  const labels = new Int32Array(6 * n * n);
  const positions = new Float32Array(3 * labels.length);
  for (let t = 0; t < labels.length; t++) {
    const { face, i, j } = texelFromIndex(t, n);
    const d = texelDirection(face, i, j, n);
    const l = Math.hypot(d[0], d[1], d[2]);
    positions.set([(radius * d[0]) / l, (radius * d[1]) / l, (radius * d[2]) / l], 3 * t);
    labels[t] = nearestSite(sites, positions[3 * t], positions[3 * t + 1], positions[3 * t + 2]);
  }
  const grid = { width: n, height: 6 * n, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
  return { image: { name: 'sphere', grid, labels, positions }, sites };
}

/**
 * Samples `samples` random points on random triangles of the surface and returns the fraction
 * where the per-fragment rule (nearest candidate of the triangle's last vertex) differs from the
 * brute-force nearest site, and checks that every label of a triangle is among the candidates
 * of its provoking vertex.
 */
function disagreement(image: LabelImage, sites: Float32Array, samples: number, seed: number): number {
  const mesh = closedSurfaceMesh(image);
  const candidates = vertexCandidates(mesh.positions, mesh.cells, atlasTopology(image.grid.width).neighbours, sites);
  const { indices, positions, cells } = mesh;
  let missingTriangleLabels = 0;
  for (let f = 0; f < indices.length; f += 3) {
    const last = indices[f + 2];
    const own = Array.from(candidates.subarray(CANDIDATES * last, CANDIDATES * last + CANDIDATES));
    for (let k = 0; k < 3; k++) if (!own.includes(cells[indices[f + k]])) missingTriangleLabels++;
  }
  // More than four cells within one texel of a vertex is the only way to miss one.
  expect(missingTriangleLabels / indices.length).toBeLessThan(1e-3);
  const rng = createRandom(seed);
  const random = () => rng.next();
  let wrong = 0;
  for (let s = 0; s < samples; s++) {
    const f = 3 * Math.floor(random() * (indices.length / 3));
    let u = random(),
      v = random();
    if (u + v > 1) [u, v] = [1 - u, 1 - v];
    const [a, b, c] = [indices[f], indices[f + 1], indices[f + 2]].map((k) => 3 * k);
    const point = [0, 1, 2].map((k) => positions[a + k] + u * (positions[b + k] - positions[a + k]) + v * (positions[c + k] - positions[a + k]));
    const drawn = nearestCandidate(candidates, indices[f + 2], sites, point[0], point[1], point[2]);
    if (drawn !== nearestSite(sites, point[0], point[1], point[2])) wrong++;
  }
  return wrong / samples;
}

describe('per-fragment cells on closed surfaces', () => {
  it('candidates: the vertex own label first, distinct, -1 padding', () => {
    const { image, sites } = sphereAtlas(24, 60, 50, 3);
    const mesh = closedSurfaceMesh(image);
    const candidates = vertexCandidates(mesh.positions, mesh.cells, atlasTopology(24).neighbours, sites);
    for (let v = 0; v < mesh.cells.length; v++) {
      const own = Array.from(candidates.subarray(CANDIDATES * v, CANDIDATES * v + CANDIDATES));
      // The texel's label is the nearest site to the vertex, so it comes first.
      expect(own[0]).toBe(mesh.cells[v]);
      const present = own.filter((id) => id >= 0);
      expect(new Set(present).size).toBe(present.length);
      expect(own.slice(present.length).every((id) => id === -1)).toBe(true);
    }
  });

  for (const [n, count] of [
    [32, 40],
    [48, 300],
  ] as const) {
    it(`a sphere (${count} cells on 6 x ${n}² texels): fragments get the exact nearest site`, () => {
      const { image, sites } = sphereAtlas(n, count, 80, n + count);
      // Per-vertex colouring was wrong on about half of each triangle along every border; the
      // per-fragment rule only where a fifth cell comes within a texel of a vertex.
      expect(disagreement(image, sites, 20_000, 7)).toBeLessThan(2e-3);
    });
  }

  it('labels without a site (or no cell) never become candidates', () => {
    const { image, sites } = sphereAtlas(8, 10, 5, 1);
    image.labels[0] = 99;
    image.labels[1] = -1;
    const mesh = closedSurfaceMesh(image);
    const candidates = vertexCandidates(mesh.positions, mesh.cells, atlasTopology(8).neighbours, sites);
    for (const id of candidates) expect(id === -1 || (id >= 0 && id < 10)).toBe(true);
  });

  it('every surface of a real ellipsoid stack (GPU labels, projected sites) draws its exact cells', async () => {
    const config = validateConfig({
      surface: { kind: 'ellipsoid', a: 60, b: 45, c: 40 },
      cells: 150,
      lloyd: { maxIterations: 5 },
      sheet: { thickness: 15, layers: 1 },
    });
    const stack = viewStack(await runSheet(config, context));
    expect(stack.surfaces.length).toBe(3);
    for (const surface of stack.surfaces) {
      const sites = sitePositions(surface.cells);
      expect(sites.length).toBe(3 * 150);
      expect(disagreement(surface.image, sites, 5_000, 11)).toBeLessThan(5e-3);
    }
  });
});
