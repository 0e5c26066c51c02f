import { describe, expect, it } from 'vitest';
import { texelDirection, texelFromIndex } from '../../src/core/cubemap/cubemap';
import type { LabelImage } from '../../src/run';
import { atlasTopology, closedSurfaceMesh } from '../../src/view/cubeAtlasMesh';

/** A closed surface's label image: texel directions mapped by `place`, labelled by `label`. */
function atlasImage(n: number, place: (d: number[]) => number[], label: (d: number[]) => number): LabelImage {
  const labels = new Int32Array(6 * n * n);
  const positions = new Float32Array(3 * labels.length);
  for (let t = 0; t < labels.length; t++) {
    const { face, i, j } = texelFromIndex(t, n);
    const d = texelDirection(face, i, j, n);
    positions.set(place(d), 3 * t);
    labels[t] = label(d);
  }
  const grid = { width: n, height: 6 * n, texelX: 1, texelY: 1, periodicX: false, periodicY: false };
  return { name: 'test', grid, labels, positions };
}

/** Counts of each directed edge of a triangle list. */
function directedEdges(indices: Uint32Array): Map<string, number> {
  const edges = new Map<string, number>();
  for (let f = 0; f < indices.length; f += 3) {
    for (let k = 0; k < 3; k++) {
      const key = `${indices[f + k]}>${indices[f + ((k + 1) % 3)]}`;
      edges.set(key, (edges.get(key) ?? 0) + 1);
    }
  }
  return edges;
}

describe('the cube-map atlas as a triangle mesh', () => {
  for (const n of [1, 2, 5, 16]) {
    it(`n = ${n}: a closed, consistently wound surface of genus 0 over every texel`, () => {
      const { indices } = atlasTopology(n);
      const vertices = 6 * n * n;
      const used = new Set(indices);
      expect(used.size).toBe(vertices);
      for (const v of indices) expect(v).toBeLessThan(vertices);
      // Every directed edge once, and its reverse once: no hole, no fold, one orientation.
      const edges = directedEdges(indices);
      for (const [key, count] of edges) {
        expect(count).toBe(1);
        const [a, b] = key.split('>');
        expect(edges.get(`${b}>${a}`)).toBe(1);
      }
      const faces = indices.length / 3;
      expect(vertices - edges.size / 2 + faces).toBe(2); // Euler characteristic of a sphere
    });
  }

  it('on a sphere: outward triangles and normals, vertices at the texel positions, labels as given', () => {
    const R = 7;
    const image = atlasImage(
      12,
      (d) => d.map((x) => R * x),
      (d) => (d[2] > 0 ? 1 : 0) + (d[0] > 0 ? 2 : 0),
    );
    const mesh = closedSurfaceMesh(image);
    expect(mesh.positions).toBe(image.positions);
    expect(mesh.cells).toBe(image.labels);
    let volume = 0;
    const p = mesh.positions;
    for (let f = 0; f < mesh.indices.length; f += 3) {
      const [a, b, c] = [0, 1, 2].map((k) => 3 * mesh.indices[f + k]);
      volume +=
        (p[a] * (p[b + 1] * p[c + 2] - p[b + 2] * p[c + 1]) - p[a + 1] * (p[b] * p[c + 2] - p[b + 2] * p[c]) + p[a + 2] * (p[b] * p[c + 1] - p[b + 1] * p[c])) /
        6;
    }
    // An inscribed polyhedron: a little less than the ball's volume.
    expect(volume).toBeGreaterThan(0.95 * (4 / 3) * Math.PI * R ** 3);
    expect(volume).toBeLessThan((4 / 3) * Math.PI * R ** 3);
    for (let v = 0; v < p.length / 3; v++) {
      const dot = (mesh.normals[3 * v] * p[3 * v] + mesh.normals[3 * v + 1] * p[3 * v + 1] + mesh.normals[3 * v + 2] * p[3 * v + 2]) / R;
      expect(dot).toBeGreaterThan(0.99);
    }
    // Boundary vertices: exactly those with a triangle neighbour of a higher cell id.
    const lower = new Uint8Array(mesh.cells.length);
    for (let f = 0; f < mesh.indices.length; f += 3) {
      for (let k = 0; k < 3; k++) {
        for (let l = 0; l < 3; l++) {
          const i = mesh.indices[f + k],
            j = mesh.indices[f + l];
          if (mesh.cells[j] > mesh.cells[i]) lower[i] = 1;
        }
      }
    }
    expect(Array.from(mesh.boundary)).toEqual(Array.from(lower));
    expect(mesh.boundary.some((b) => b === 1)).toBe(true);
    expect(mesh.boundary.some((b) => b === 0)).toBe(true);
  });

  it('a surface mapped mirror-wise still faces outward', () => {
    const image = atlasImage(
      6,
      (d) => [-3 * d[0], 2 * d[1], d[2]],
      () => 0,
    );
    const mesh = closedSurfaceMesh(image);
    const p = mesh.positions;
    for (let v = 0; v < p.length / 3; v++) {
      const radial = mesh.normals[3 * v] * p[3 * v] + mesh.normals[3 * v + 1] * p[3 * v + 1] + mesh.normals[3 * v + 2] * p[3 * v + 2];
      expect(radial).toBeGreaterThan(0);
    }
    expect(mesh.edgeLength).toBeGreaterThan(0);
  });

  it('names the label image that has no geometry image', () => {
    const { name, grid, labels } = atlasImage(
      4,
      (d) => d,
      () => 0,
    );
    expect(() => closedSurfaceMesh({ name: 'apical', grid, labels })).toThrow(/"apical".*positions/);
    expect(() => closedSurfaceMesh({ name: 'flat', grid: { ...grid, height: 5 }, labels })).toThrow(/"flat".*n x 6n/);
    expect(name).toBe('test');
  });
});
