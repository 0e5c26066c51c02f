/**
 * Restricted Voronoi diagram timings (issue 20: exact neighbours of 1,000 cells on a
 * 100k-triangle surface in ≤ 1 s on the 2-core machine).
 *
 *   npx tsx bench/restrictedVoronoi.ts [--cells 1000] [--frequency 71] [--rounds 3]
 *
 * Cases: a 90:45:45 µm ellipsoid triangulated (icosphere of frequency f stretched: 20 f²
 * triangles, 100,820 at f = 71) and the same ellipsoid analytic, RSA sites; a 5-layer stack of
 * the mesh case (parallel surfaces, sites moved along their normals). Prints the first (cold)
 * and the median of the following rounds, and cells/s.
 */
import { offsetClosedSurface } from '../src/core/closed/closedOffset';
import { randomSequentialSites } from '../tests/closed/randomSequentialSites';
import { restrictedVoronoi } from '../src/core/closed/restrictedVoronoi';
import { triangleNeighbours, type MeshGeometry, type RestrictedSurface } from '../src/core/closed/restrictedSurface';
import { icosphere } from '../src/core/mesh/generate';

function option(name: string, fallback: number): number {
  const k = process.argv.indexOf(`--${name}`);
  return k >= 0 ? Number(process.argv[k + 1]) : fallback;
}

const cells = option('cells', 1000),
  frequency = option('frequency', 71),
  rounds = Math.max(2, option('rounds', 3));
const a = 90,
  b = 45,
  c = 45;
const ico = icosphere(frequency);
const positions = new Float64Array(ico.positions.length);
for (let v = 0; v < positions.length; v += 3) {
  const l = Math.hypot(ico.positions[v], ico.positions[v + 1], ico.positions[v + 2]);
  positions[v] = (a * ico.positions[v]) / l;
  positions[v + 1] = (b * ico.positions[v + 1]) / l;
  positions[v + 2] = (c * ico.positions[v + 2]) / l;
}
const mesh: MeshGeometry = { kind: 'mesh', positions, indices: ico.indices };
const analytic: RestrictedSurface = { kind: 'ellipsoid', a, b, c };
const spacing = 0.7 * Math.sqrt(43000 / cells);
const sitesMesh = randomSequentialSites(mesh, cells, spacing, 1);
const sitesAnalytic = randomSequentialSites(analytic, cells, spacing, 1);

function time(label: string, run: () => void): void {
  const ms: number[] = [];
  for (let r = 0; r < rounds; r++) {
    const t = performance.now();
    run();
    ms.push(performance.now() - t);
  }
  const warm = ms.slice(1).sort((x, y) => x - y)[Math.floor((ms.length - 1) / 2)];
  console.log(`${label}: cold ${ms[0].toFixed(0)} ms, warm median ${warm.toFixed(0)} ms (${((cells / warm) * 1000).toFixed(0)} cells/s)`);
}

console.log(`${cells} RSA cells (min spacing ${spacing.toFixed(2)} µm); mesh: ${ico.indices.length / 3} triangles`);
time(`mesh RVD, ${ico.indices.length / 3} triangles (triangle neighbours built inside)`, () => restrictedVoronoi(mesh, sitesMesh.positions, cells));
const prepared: MeshGeometry = { ...mesh, triangleNeighbours: triangleNeighbours(mesh.indices, positions.length / 3) };
time('mesh RVD, triangle neighbours given', () => restrictedVoronoi(prepared, sitesMesh.positions, cells));
time('analytic ellipsoid RVD', () => restrictedVoronoi(analytic, sitesAnalytic.positions, cells));
const layers = [0, 2, 4, 6, 8, 10].map((t) => offsetClosedSurface(prepared, sitesMesh.positions, sitesMesh.normals, cells, t, 'normal'));
time('stack of 6 mesh surfaces (basal + 5 offsets), sequential, start triangles from the basal', () => {
  const basal = restrictedVoronoi(layers[0].surface, layers[0].sites, cells);
  for (const layer of layers.slice(1)) restrictedVoronoi(layer.surface, layer.sites, cells, { startTriangles: basal.startTriangles });
});
const r = restrictedVoronoi(mesh, sitesMesh.positions, cells);
console.log(`mesh stats ${JSON.stringify(r.stats)}; mean neighbours ${(r.adjacency.neighbours.length / cells).toFixed(3)}`);
