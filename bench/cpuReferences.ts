// `npx tsx bench/cpuReferences.ts`: times the CPU references the tests use, which only check
// correctness. Prints figures; asserts nothing (speed depends on the machine).
// - bruteForceLabels (tests/oracles/labels.ts): 512 x 512 texels, 2000 random sites, periodic x.
// - the heat-method geodesic Voronoi (src/core/mesh/heat.ts): 14 sites on the shipped
//   level-set blob (~9,000 vertices): factorization, then the Voronoi per site.
// Options: --repeats N (default 3; the median is printed).
import { readFileSync } from 'node:fs';
import type { Grid } from '../src/core/grid';
import { geodesicVoronoi, HeatGeodesics } from '../src/core/mesh/heat';
import { parseMesh } from '../src/core/mesh/parse';
import { Random } from '../src/core/random';
import { bruteForceLabels } from '../tests/oracles/labels';

const index = process.argv.indexOf('--repeats');
const repeats = index >= 0 ? Number(process.argv[index + 1]) : 3;

function median(values: number[]): number {
  const sorted = [...values].sort((a, b) => a - b);
  return sorted[Math.floor(sorted.length / 2)];
}

function timeIt(run: () => void): number {
  const times: number[] = [];
  for (let r = 0; r < repeats; r++) {
    const start = performance.now();
    run();
    times.push(performance.now() - start);
  }
  return median(times);
}

const grid: Grid = { width: 512, height: 512, texelX: 1, texelY: 1, periodicX: true, periodicY: false };
const random = new Random(3);
const sites = new Float32Array(2 * 2000);
for (let k = 0; k < sites.length; k += 2) {
  sites[k] = random.next() * grid.width;
  sites[k + 1] = random.next() * grid.height;
}
const labelsMs = timeIt(() => bruteForceLabels(grid, sites));
console.log(`bruteForceLabels 512 x 512, 2000 sites: ${labelsMs.toFixed(0)} ms (median of ${repeats})`);

const file = new URL('../public/meshes/level-set-blob.ply', import.meta.url);
const bytes = readFileSync(file);
const mesh = parseMesh(bytes.buffer.slice(bytes.byteOffset, bytes.byteOffset + bytes.byteLength) as ArrayBuffer, { fileName: 'level-set-blob.ply' });
const nv = mesh.positions.length / 3;
const seeds = Array.from({ length: 14 }, (_, k) => Math.floor(((k + 0.5) * nv) / 14));
let solver: HeatGeodesics | null = null;
const factorMs = timeIt(() => {
  solver = new HeatGeodesics(mesh);
});
const voronoiMs = timeIt(() => geodesicVoronoi(mesh, seeds, solver!));
console.log(
  `heat method, ${nv} vertices: factorization ${factorMs.toFixed(0)} ms (factor nonzeros ${solver!.factorNonzeros}), ` +
    `14-site Voronoi ${voronoiMs.toFixed(0)} ms (${(voronoiMs / 14).toFixed(1)} ms per site), total ${((factorMs + voronoiMs) / 14).toFixed(1)} ms per site`,
);
