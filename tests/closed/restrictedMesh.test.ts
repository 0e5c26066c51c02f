import { describe, expect, it } from 'vitest';
import { isSymmetric } from '../oracles/adjacency';
import { offsetClosedSurface } from '../../src/core/closed/closedOffset';
import { randomSequentialSites } from './randomSequentialSites';
import { restrictedVoronoi } from '../../src/core/closed/restrictedVoronoi';
import type { MeshGeometry } from '../../src/core/closed/restrictedSurface';
import { loadShipped, surfaceArea } from '../mesh/helpers';
import { compareNeighbourSets, meshContactsReference, neighbourLists } from './restrictedReference';

/** A shipped mesh scaled to µm. */
function shipped(file: string, scale: number): MeshGeometry {
  const mesh = loadShipped(file);
  return { kind: 'mesh', positions: Float64Array.from(mesh.positions, (v) => v * scale), indices: mesh.indices };
}

function check(name: string, surface: MeshGeometry, sites: Float64Array, count: number) {
  const rvd = restrictedVoronoi(surface, sites, count);
  const ref = meshContactsReference(surface.positions, surface.indices, sites, count);
  const cmp = compareNeighbourSets(rvd.adjacency, neighbourLists(ref, 1e-6));
  let maxLength = 0,
    pairs = 0;
  for (let i = 0; i < count; i++) {
    for (let k = rvd.adjacency.offsets[i]; k < rvd.adjacency.offsets[i + 1]; k++) {
      const j = rvd.adjacency.neighbours[k];
      const other = ref.lengths.get(Math.min(i, j) * count + Math.max(i, j));
      if (other === undefined) continue;
      pairs++;
      maxLength = Math.max(maxLength, Math.abs(other - rvd.adjacency.lengths[k]));
    }
  }
  const area = surfaceArea({ positions: Float32Array.from(surface.positions), indices: Uint32Array.from(surface.indices) });
  const sum = rvd.adjacency.areas.reduce((s, v) => s + v, 0);
  console.log(
    `${name}: ${surface.indices.length / 3} triangles, ${count} cells: ${cmp.same}/${count} neighbour sets equal the dense per-triangle reference (${(100 * cmp.fraction).toFixed(2)} %), differ ${JSON.stringify(cmp.differ)}; max |Δlength| ${maxLength.toExponential(2)} µm over ${pairs / 2} contacts; Σ areas / area - 1 = ${(sum / rvd.surfaceArea - 1).toExponential(2)}; ${rvd.stats.ms.toFixed(0)} ms ${JSON.stringify(rvd.stats)}`,
  );
  expect(cmp.fraction).toBeGreaterThanOrEqual(0.995);
  expect(maxLength).toBeLessThan(1e-3);
  expect(Math.abs(sum / area - 1)).toBeLessThan(1e-6); // float32 mesh area vs float64
  expect(Math.abs(sum / rvd.surfaceArea - 1)).toBeLessThan(1e-9);
  expect(isSymmetric(rvd.adjacency, 1e-9)).toBe(true);
  return rvd;
}

describe('restricted Voronoi on a triangle mesh', () => {
  it('organoid.ply (bumpy, concave parts), 200 RSA cells on the mesh, against a dense per-triangle reference', () => {
    const surface = shipped('organoid.ply', 50);
    const seeded = randomSequentialSites(surface, 200, 4, 5);
    check('organoid.ply ×50', surface, seeded.positions, 200);
  }, 60000);

  it('egg-chamber.ply, 200 cells, and its parallel surface 10 µm outward with the sites moved along their normals (off the mesh)', () => {
    const surface = shipped('egg-chamber.ply', 40);
    const seeded = randomSequentialSites(surface, 200, 5, 9);
    check('egg-chamber.ply ×40', surface, seeded.positions, 200);
    const outer = offsetClosedSurface(surface, seeded.positions, seeded.normals, 200, 10, 'normal');
    const plain = check('egg-chamber.ply ×40, +10 µm', outer.surface as MeshGeometry, outer.sites, 200);
    // Start triangles from the basal diagram (same topology) give the same diagram.
    const basal = restrictedVoronoi(surface, seeded.positions, 200);
    const hinted = restrictedVoronoi(outer.surface, outer.sites, 200, { startTriangles: basal.startTriangles });
    expect(Array.from(hinted.adjacency.neighbours)).toEqual(Array.from(plain.adjacency.neighbours));
    for (let k = 0; k < plain.adjacency.lengths.length; k++) expect(Math.abs(hinted.adjacency.lengths[k] - plain.adjacency.lengths[k])).toBeLessThan(1e-9);
  }, 60000);

  it('a cell in two pieces (top and bottom caps) is found whole by the coverage repair', () => {
    // Site 0 at the centre of the organoid (radius ~50 µm), 8 sites on a ring of radius 60 µm
    // in its equatorial plane: the ring takes the equator band, site 0 keeps both caps, which
    // do not touch on the surface. One traversal sees one cap; the repair finds the other.
    const surface = shipped('organoid.ply', 50);
    const count = 9;
    const sites = new Float64Array(3 * count);
    for (let k = 0; k < 8; k++) {
      sites[3 * (k + 1)] = 60 * Math.cos((k * Math.PI) / 4);
      sites[3 * (k + 1) + 1] = 60 * Math.sin((k * Math.PI) / 4);
    }
    const rvd = check('organoid.ply ×50, a cell in two caps', surface, sites, count);
    expect(rvd.stats.method === 'mesh' && rvd.stats.mesh.repairTraversals).toBeGreaterThanOrEqual(1);
  }, 60000);
});
