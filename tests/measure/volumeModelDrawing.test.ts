/**
 * The model of the same tissue, drawn (src/core/measure/volume/modelDrawing.ts), on a closed shell
 * and an open tube built by the model's construction (volumes.ts):
 * - it is the comparison's first realization: its % scutoids and transitions are the record's;
 * - each drawn triangle belongs to the site nearest it, checked by brute force over every site
 *   (3D distance on a shell's restricted diagram; the unrolled tube metric on a tube);
 * - the neighbours it reports are the cells its drawn triangles share edges with (edges matched
 *   by their ends within 2e-5 µm, a few float32 steps: pieces have edges under a nanometre; the
 *   shared lengths are the diagram's), and its scutoid flags follow from them;
 * - a saved comparison (JSON) draws the same model again; the triangle budget holds.
 */
import { beforeAll, describe, expect, it } from 'vitest';
import { KdTree3 } from '../../src/core/closed/kdTree';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import {
  compareVolume,
  measureVolume,
  prepareMesh,
  volumeModelDrawing,
  type ShellMeshes,
  type VolumeComparison,
  type VolumeMeasuredResult,
  type VolumeModelDrawing,
} from '../../src/core/measure';
import { writeTiff } from './tiffWriter';
import { labelData, shellVolume, tubeVolume, volumePages, type SyntheticVolume } from './volumes';

const tiffOf = (volume: SyntheticVolume) =>
  writeTiff(
    volumePages(
      volume,
      labelData(
        volume,
        Array.from({ length: volume.sites }, (_, k) => k + 1),
        16,
      ),
      16,
    ) as never,
  );

interface Case {
  result: VolumeMeasuredResult;
  comparison: VolumeComparison;
  meshes?: ShellMeshes;
  drawing: VolumeModelDrawing;
}

function modelled(volume: SyntheticVolume): Case {
  let meshes: ShellMeshes | undefined;
  const bytes = tiffOf(volume);
  const result = measureVolume({ name: 'v.tif', read: () => bytes }, { voxelSize: volume.voxel, version: 'test', onSurfaceMeshes: (m) => (meshes = m) });
  const { comparison } = compareVolume(result, { realizations: 3, seed: 4 }, meshes);
  const { drawing, note } = volumeModelDrawing(result, comparison!, meshes);
  expect(note).toBe('');
  return { result, comparison: comparison!, meshes, drawing: drawing! };
}

let shell: Case;
let tube: Case;

beforeAll(() => {
  shell = modelled(shellVolume({ voxel: { x: 0.5, y: 0.5, z: 0.75 }, a: 12, b: 10, c: 9, h: 4, sites: 36, seed: 2, margin: 2 }));
  tube = modelled(tubeVolume({ width: 80, height: 80, depth: 60, voxel: { x: 0.5, y: 0.5, z: 1 }, inner: 10, outer: 18, sites: 40, seed: 3 }));
}, 120_000);

const triangleCentre = (p: Float32Array, t: number) => [0, 1, 2].map((a) => (p[9 * t + a] + p[9 * t + 3 + a] + p[9 * t + 6 + a]) / 3);

/**
 * Each triangle's cell is the site nearest its centre (`distanceFrom(t)(i)`: to site i), by brute
 * force over the `n` sites; where another is nearer, only by rounding (1 nm), and rarely.
 */
function checkNearest(cells: Int32Array, n: number, distanceFrom: (t: number) => (i: number) => number): void {
  let ties = 0;
  for (let t = 0; t < cells.length; t++) {
    const dist = distanceFrom(t);
    let best = 0;
    for (let i = 1; i < n; i++) if (dist(i) < dist(best)) best = i;
    if (best !== cells[t]) {
      ties++;
      expect(dist(cells[t]) - dist(best)).toBeLessThan(1e-3);
    }
  }
  expect(ties).toBeLessThan(0.001 * cells.length + 2);
}

/** Pairs of cells whose drawn triangles share an edge (matched by its ends within `eps` µm), with the shared length, key i * n + j (i < j). */
function drawnContacts(positions: Float32Array, cells: Int32Array, n: number, eps: number): Map<number, number> {
  const edges = cells.length * 3;
  const mid = new Float64Array(3 * edges);
  const end = (e: number, which: 0 | 1, a: number) => positions[9 * Math.floor(e / 3) + 3 * ((e % 3) + which === 3 ? 0 : (e % 3) + which) + a];
  for (let e = 0; e < edges; e++) for (let a = 0; a < 3; a++) mid[3 * e + a] = (end(e, 0, a) + end(e, 1, a)) / 2;
  const tree = new KdTree3(mid, edges);
  const ids = new Int32Array(12);
  const d2 = new Float64Array(12);
  const out = new Map<number, number>();
  const close = (e: number, ea: 0 | 1, f: number, fb: 0 | 1) => Math.hypot(...[0, 1, 2].map((a) => end(e, ea, a) - end(f, fb, a))) < eps;
  for (let e = 0; e < edges; e++) {
    const found = tree.knn(mid[3 * e], mid[3 * e + 1], mid[3 * e + 2], 12, ids, d2);
    for (let q = 0; q < found; q++) {
      const f = ids[q];
      if (d2[q] > eps * eps) break;
      const i = cells[Math.floor(e / 3)];
      const j = cells[Math.floor(f / 3)];
      if (i >= j) continue;
      if (!((close(e, 0, f, 1) && close(e, 1, f, 0)) || (close(e, 0, f, 0) && close(e, 1, f, 1)))) continue;
      const length = Math.hypot(...[0, 1, 2].map((a) => end(e, 1, a) - end(e, 0, a)));
      out.set(i * n + j, (out.get(i * n + j) ?? 0) + length);
    }
  }
  return out;
}

function listed(drawing: VolumeModelDrawing, k: number, i: number): number[] {
  const s = drawing.surfaces[k];
  return Array.from(s.neighbours.subarray(s.offsets[i], s.offsets[i + 1]));
}

/** Neighbours drawn = neighbours reported; scutoid = valid and the two surfaces' sets differ. */
function checkNeighbours(c: Case, shortest: number): void {
  const d = c.drawing;
  const n = d.cells;
  for (let k = 0; k < 2; k++) {
    const contacts = drawnContacts(d.surfaces[k].positions, d.surfaces[k].cells, n, 2e-5);
    let matched = 0;
    for (let i = 0; i < n; i++) {
      const reported = listed(d, k, i);
      for (let j = 0; j < n; j++) {
        if (j === i) continue;
        const drawn = contacts.get(Math.min(i, j) * n + Math.max(i, j)) ?? 0;
        // A drawn contact is reported; a reported one is drawn unless shorter than float32 rounding allows.
        if (drawn > shortest) expect(reported, `surface ${k} cells ${i} and ${j} touch in the drawing (${drawn} µm)`).toContain(j);
        if (reported.includes(j) && drawn > 0) matched++;
      }
      expect(d.surfaces[k].sides[i]).toBe(reported.length);
    }
    const pairs = d.surfaces[k].neighbours.length;
    expect(matched).toBeGreaterThan(0.97 * pairs);
  }
  for (let i = 0; i < n; i++) {
    const same = listed(d, 0, i).join() === listed(d, 1, i).join();
    expect(d.scutoid[i]).toBe(d.valid[i] && !same ? 1 : 0);
  }
}

describe('the model of a closed shell, drawn', () => {
  it("is the comparison's first realization, every cell drawn on both surfaces", () => {
    const { drawing: d, comparison: c } = shell;
    expect(d.kind).toBe('mesh');
    expect(d.matches).toBe(true);
    expect(d.percentScutoids).toBe(c.percentScutoids[0]);
    expect([d.seed, d.k, d.cells]).toEqual([c.seed, c.bestK, c.cells]);
    expect(d.surfaces.map((s) => s.name)).toEqual(['basal', 'apical']);
    expect(d.surfaces.map((s) => s.faces)).toEqual(['outside', 'lumen']);
    for (const s of d.surfaces) {
      expect(new Set(s.cells).size).toBe(c.cells);
      expect(s.positions.length).toBe(9 * s.cells.length);
    }
  });

  it('draws each triangle in the cell of the site nearest it (brute force over the sites)', () => {
    for (const s of shell.drawing.surfaces) {
      checkNearest(s.cells, shell.drawing.cells, (t) => {
        const [x, y, z] = triangleCentre(s.positions, t);
        return (i) => Math.hypot(s.sites[3 * i] - x, s.sites[3 * i + 1] - y, s.sites[3 * i + 2] - z);
      });
    }
  });

  it('reports as neighbours the cells its drawn triangles touch, with the diagram’s contact lengths', () => {
    checkNeighbours(shell, 0.01);
    // Lengths: every contact of the restricted diagram is drawn along its whole length, once.
    const d = shell.drawing;
    const seededMesh = prepareMesh(shell.meshes!.lumen);
    const k = d.surfaces.findIndex((s) => s.faces === 'lumen');
    const rvd = restrictedVoronoi({ kind: 'mesh', positions: seededMesh.positions, indices: seededMesh.indices }, d.surfaces[k].sites, d.cells).adjacency;
    const contacts = drawnContacts(d.surfaces[k].positions, d.surfaces[k].cells, d.cells, 2e-5);
    for (let i = 0; i < d.cells; i++) {
      for (let e = rvd.offsets[i]; e < rvd.offsets[i + 1]; e++) {
        const j = rvd.neighbours[e];
        if (j < i || rvd.lengths[e] < 0.05) continue;
        const drawn = contacts.get(i * d.cells + j) ?? 0;
        expect(Math.abs(drawn / rvd.lengths[e] - 1), `cells ${i} and ${j}: drawn ${drawn} µm, diagram ${rvd.lengths[e]} µm`).toBeLessThan(1e-4);
      }
    }
  });

  it('draws a saved (JSON) comparison the same again, and keeps to the triangle budget', () => {
    const saved = JSON.parse(JSON.stringify(shell.comparison)) as VolumeComparison;
    const again = volumeModelDrawing(shell.result, saved, shell.meshes).drawing!;
    expect(again.matches).toBe(true);
    expect(again.surfaces[0].positions).toEqual(shell.drawing.surfaces[0].positions);
    expect(again.surfaces[1].cells).toEqual(shell.drawing.surfaces[1].cells);
    const small = volumeModelDrawing(shell.result, shell.comparison, shell.meshes, 200);
    expect(small.drawing).toBeNull();
    expect(small.note).toMatch(/^model not drawn: the model's surfaces need more than 200 triangles/);
    expect(volumeModelDrawing(shell.result, shell.comparison).note).toMatch(/own surface meshes/);
  });
});

describe('the model of an open tube, drawn', () => {
  it("is the comparison's first realization on the fitted tube, in the volume's coordinates", () => {
    const { drawing: d, comparison: c } = tube;
    const g = c.geometry;
    if (g.kind !== 'tube') throw new Error('expected a tube');
    expect(d.kind).toBe('tube');
    expect(d.matches).toBe(true);
    expect(d.percentScutoids).toBe(c.percentScutoids[0]);
    expect(Array.from(d.valid).filter((v) => v === 1).length).toBe(c.summary.validCells);
    // Every vertex on its cylinder (chords of at most ~0.1 rad: within 0.2 %), within the model's length.
    d.surfaces.forEach((s) => {
      const radius = s.faces === 'lumen' ? g.innerRadius : g.outerRadius;
      for (let v = 0; v < s.positions.length; v += 3) {
        const r = [0, 1, 2].map((a) => s.positions[v + a] - g.centre[a]);
        const along = r[0] * g.axis[0] + r[1] * g.axis[1] + r[2] * g.axis[2];
        expect(Math.abs(Math.hypot(...r.map((x, a) => x - along * g.axis[a])) / radius - 1)).toBeLessThan(2e-3);
        expect(Math.abs(along)).toBeLessThan(g.length / 2 + 1);
      }
    });
  });

  it('draws each triangle in the cell of the site nearest it in the unrolled tube metric (brute force)', () => {
    const g = tube.comparison.geometry;
    if (g.kind !== 'tube') throw new Error('expected a tube');
    const seedAxis = Math.abs(g.axis[0]) < 0.9 ? [1, 0, 0] : [0, 1, 0];
    const cross = (a: number[], b: number[]) => [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    const u0 = cross(g.axis, seedAxis);
    const u = u0.map((x) => x / Math.hypot(...u0));
    const v = cross(g.axis, u);
    const unrolled = (p: number[]) => {
      const r = p.map((x, a) => x - g.centre[a]);
      const along = r[0] * g.axis[0] + r[1] * g.axis[1] + r[2] * g.axis[2];
      return { theta: Math.atan2(r[0] * v[0] + r[1] * v[1] + r[2] * v[2], r[0] * u[0] + r[1] * u[1] + r[2] * u[2]), along };
    };
    for (const s of tube.drawing.surfaces) {
      const radius = s.faces === 'lumen' ? g.innerRadius : g.outerRadius;
      const sites = Array.from({ length: tube.drawing.cells }, (_, i) => unrolled([s.sites[3 * i], s.sites[3 * i + 1], s.sites[3 * i + 2]]));
      checkNearest(s.cells, sites.length, (t) => {
        const p = unrolled(triangleCentre(s.positions, t));
        return (i) => {
          let dt = Math.abs(p.theta - sites[i].theta);
          dt = Math.min(dt, 2 * Math.PI - dt);
          return Math.hypot(radius * dt, p.along - sites[i].along);
        };
      });
    }
  });

  it('reports as neighbours the cells its drawn triangles touch', () => {
    checkNeighbours(tube, 0.01);
  });
});
