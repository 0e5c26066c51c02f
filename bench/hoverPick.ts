/**
 * Hover picking on a closed surface (issue 14): what one raycast into the 3D view's closed mesh
 * costs, brute force (three.js Mesh.raycast over every triangle) against three-mesh-bvh's
 * accelerated raycast, and what building the hierarchy costs once per result.
 *
 *   npx tsx bench/hoverPick.ts [--n 204] [--rays 200]
 *
 * The mesh is cubeAtlasMesh.ts's closed surface of a sphere's geometry image with n texels per
 * cube-face edge (12 n² triangles: 499,392 at n = 204). Rays are shot from a camera at 3 R
 * through random points of the sphere's disc, as the pointer would; every ray needs all hits
 * (the view skips hits removed by the cut). Prints the median and the 95th percentile per ray.
 */
import * as THREE from 'three';
import { acceleratedRaycast, MeshBVH } from 'three-mesh-bvh';
import { sampleSurface } from '../src/core/cubemap/sample';
import { closedSurfaceMesh } from '../src/view/cubeAtlasMesh';

function option(name: string, fallback: number): number {
  const k = process.argv.indexOf(`--${name}`);
  return k >= 0 ? Number(process.argv[k + 1]) : fallback;
}

const n = option('n', 204);
const count = option('rays', 200);
const radius = 50;
const image = sampleSurface({ kind: 'sphere', radius }, n);
const built = closedSurfaceMesh({
  name: 'bench',
  grid: { width: n, height: 6 * n, texelX: 1, texelY: 1, periodicX: false, periodicY: false },
  labels: new Int32Array(6 * n * n),
  positions: image.position,
});
const geometry = new THREE.BufferGeometry();
geometry.setAttribute('position', new THREE.BufferAttribute(built.positions, 3));
geometry.setIndex(new THREE.BufferAttribute(built.indices, 1));
const mesh = new THREE.Mesh(geometry, new THREE.MeshBasicMaterial({ side: THREE.DoubleSide }));
const triangles = built.indices.length / 3;

let seed = 7;
const random = () => (seed = (seed * 16807) % 2147483647) / 2147483647;
const rays: THREE.Ray[] = [];
for (let i = 0; i < count; i++) {
  const origin = new THREE.Vector3(0, 0, 3 * radius);
  const r = radius * Math.sqrt(random()),
    a = 2 * Math.PI * random();
  rays.push(new THREE.Ray(origin, new THREE.Vector3(r * Math.cos(a), r * Math.sin(a), 0).sub(origin).normalize()));
}

function time(label: string): { median: number; p95: number; hits: number } {
  const raycaster = new THREE.Raycaster();
  const times: number[] = [];
  let hits = 0;
  for (const ray of rays) {
    raycaster.ray.copy(ray);
    const start = performance.now();
    hits += raycaster.intersectObject(mesh, false).length;
    times.push(performance.now() - start);
  }
  times.sort((x, y) => x - y);
  const result = { median: times[Math.floor(times.length / 2)], p95: times[Math.floor(times.length * 0.95)], hits };
  console.log(`${label}: median ${result.median.toFixed(3)} ms, p95 ${result.p95.toFixed(3)} ms per ray (${hits} hits over ${count} rays)`);
  return result;
}

console.log(`closed sphere mesh: n = ${n}, ${triangles} triangles`);
const brute = time('brute force (Mesh.raycast)');
const start = performance.now();
geometry.boundsTree = new MeshBVH(geometry, { indirect: true });
const build = performance.now() - start;
console.log(`MeshBVH build (indirect): ${build.toFixed(1)} ms`);
mesh.raycast = acceleratedRaycast;
const fast = time('three-mesh-bvh acceleratedRaycast');
if (fast.hits !== brute.hits) console.log(`hit counts differ: ${brute.hits} vs ${fast.hits}`);
