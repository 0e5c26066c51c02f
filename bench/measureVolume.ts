/**
 * Time and peak memory of `tissue-sheet measure --volume` on a synthetic 16-bit label volume
 * (docs/measure.md, "Measuring a volume": size, memory and time), beside a baseline on the
 * same file in the same way: reading and decoding it alone (bench/decodeVolume.ts).
 *
 *   node --import tsx bench/measureVolume.ts [WIDTH=512] [HEIGHT=512] [DEPTH=200] [CELLS=300] [DIR=/tmp/measure-volume-bench]
 *
 * The volume: a spheroidal shell (a cyst) filling the box, voxels 0.2 x 0.2 x 0.5 µm, CELLS
 * sites with a minimum spacing on the unit sphere; a voxel at relative depth d in the shell
 * takes the label of the nearest site direction after the sites are sheared by
 * diag(1 + 0.3 d, 1, 1 - 0.2 d) (so neighbours change with depth: scutoids). Written once as an
 * uncompressed and a Deflate TIFF, then each run is a fresh process under /usr/bin/time -v; the
 * last row adds the model of the same shell (--compare).
 */
import { spawnSync } from 'node:child_process';
import { existsSync, mkdirSync, statSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { createRandom } from '../src/core/random';
import { writeTiff } from '../tests/measure/tiffWriter';

const [W, H, D, CELLS] = [512, 512, 200, 300].map((d, k) => Number(process.argv[2 + k] ?? d));
const dir = process.argv[6] ?? '/tmp/measure-volume-bench';
const voxel = { x: 0.2, y: 0.2, z: 0.5 };
mkdirSync(dir, { recursive: true });
const raw = join(dir, `volume-${W}x${H}x${D}-${CELLS}.tif`);
const deflate = join(dir, `volume-${W}x${H}x${D}-${CELLS}-deflate.tif`);

function sites(count: number, seed: number): Float64Array {
  const random = createRandom(seed);
  const out = new Float64Array(3 * count);
  const minDot = Math.cos(0.6 * Math.sqrt((4 * Math.PI) / count));
  let n = 0;
  for (let tries = 0; n < count; tries++) {
    if (tries > 1e6) throw new Error('cannot place the sites');
    const u = 2 * random.next() - 1;
    const phi = 2 * Math.PI * random.next();
    const s = Math.sqrt(1 - u * u);
    const p = [s * Math.cos(phi), s * Math.sin(phi), u];
    let ok = true;
    for (let k = 0; k < n && ok; k++) if (p[0] * out[3 * k] + p[1] * out[3 * k + 1] + p[2] * out[3 * k + 2] > minDot) ok = false;
    if (ok) out.set(p, 3 * n++);
  }
  return out;
}

/** Nearest site direction by buckets of a 3D grid over [-1, 1]^3 (one grid per depth level). */
function makeVolume(): Uint16Array {
  const s = sites(CELLS, 7);
  const levels = 16;
  const B = 24;
  const bucket = (v: number) => Math.min(B - 1, Math.max(0, Math.floor(((v + 1) / 2) * B)));
  const grids = Array.from({ length: levels }, (_, level) => {
    const d = (level + 0.5) / levels;
    const warped = new Float64Array(3 * CELLS);
    const cells: number[][] = Array.from({ length: B * B * B }, () => []);
    for (let k = 0; k < CELLS; k++) {
      const x = s[3 * k] * (1 + 0.3 * d),
        y = s[3 * k + 1],
        z = s[3 * k + 2] * (1 - 0.2 * d);
      const r = Math.hypot(x, y, z);
      warped.set([x / r, y / r, z / r], 3 * k);
      cells[(bucket(z / r) * B + bucket(y / r)) * B + bucket(x / r)].push(k);
    }
    return { warped, cells };
  });
  const data = new Uint16Array(W * H * D);
  const cx = (W * voxel.x) / 2,
    cy = (H * voxel.y) / 2,
    cz = (D * voxel.z) / 2;
  const outer = 0.96 * Math.min(cx, cy, cz);
  const inner = 0.78 * outer;
  const reach = 3; // buckets searched either side (1/4 of the unit cube: far beyond a cell's radius)
  for (let z = 0; z < D; z++) {
    const pz = (z + 0.5) * voxel.z - cz;
    for (let y = 0; y < H; y++) {
      const py = (y + 0.5) * voxel.y - cy;
      for (let x = 0; x < W; x++) {
        const px = (x + 0.5) * voxel.x - cx;
        const r = Math.hypot(px, py, pz);
        if (r < inner || r > outer) continue;
        const { warped, cells } = grids[Math.min(levels - 1, Math.floor(((r - inner) / (outer - inner)) * levels))];
        const ux = px / r,
          uy = py / r,
          uz = pz / r;
        const bx = bucket(ux),
          by = bucket(uy),
          bz = bucket(uz);
        let best = -2;
        let bestK = 0;
        for (let k2 = Math.max(0, bz - reach); k2 <= Math.min(B - 1, bz + reach); k2++) {
          for (let j = Math.max(0, by - reach); j <= Math.min(B - 1, by + reach); j++) {
            for (let i = Math.max(0, bx - reach); i <= Math.min(B - 1, bx + reach); i++) {
              for (const k of cells[(k2 * B + j) * B + i]) {
                const dot = ux * warped[3 * k] + uy * warped[3 * k + 1] + uz * warped[3 * k + 2];
                if (dot > best) {
                  best = dot;
                  bestK = k;
                }
              }
            }
          }
        }
        data[(z * H + y) * W + x] = 1 + bestK;
      }
    }
  }
  return data;
}

if (!existsSync(raw) || !existsSync(deflate)) {
  const t0 = performance.now();
  const data = makeVolume();
  const plane = W * H;
  const pages = (compression: 1 | 8) =>
    Array.from({ length: D }, (_, z) => ({
      width: W,
      height: H,
      bitsPerSample: 16 as const,
      compression,
      rowsPerStrip: 64,
      data: data.subarray(z * plane, (z + 1) * plane),
    }));
  writeFileSync(raw, writeTiff(pages(1)));
  writeFileSync(deflate, writeTiff(pages(8)));
  console.log(`wrote ${raw} and ${deflate} in ${((performance.now() - t0) / 1000).toFixed(1)} s`);
}

const mb = (bytes: number) => (bytes / 2 ** 20).toFixed(0);
function timed(name: string, file: string, args: string[]): void {
  const run = spawnSync('/usr/bin/time', ['-v', process.execPath, '--import', 'tsx', ...args], { encoding: 'utf8', maxBuffer: 1 << 26 });
  if (run.status !== 0) throw new Error(`${name}: exit ${run.status}\n${run.stderr.slice(-2000)}`);
  const rss = Number(/Maximum resident set size \(kbytes\): (\d+)/.exec(run.stderr)![1]) * 1024;
  const wall = /Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([\d:.]+)/.exec(run.stderr)![1];
  const seconds = wall.split(':').reduce((a, part) => 60 * a + Number(part), 0);
  const done = /done: (\d+) cells, (\d+) valid, ([\d.]+) % scutoids/.exec(run.stderr);
  console.log(
    `| ${name} | ${mb(statSync(file).size)} MB | ${mb(rss)} MB | ${seconds.toFixed(1)} s | ${done ? `${done[1]} cells, ${done[2]} valid, ${done[3]} % scutoids` : ''} |`,
  );
}

const out = join(dir, 'r.json');
const size = `${voxel.x},${voxel.y},${voxel.z}`;
console.log(`| ${W} x ${H} x ${D}, 16-bit, ${CELLS} cells | file | peak RSS | wall time | result |`);
console.log('| --- | --- | --- | --- | --- |');
timed('baseline: decode the uncompressed TIFF only', raw, ['bench/decodeVolume.ts', raw]);
timed('--volume, uncompressed TIFF', raw, ['tests/measure/runMeasure.ts', 'measure', '--volume', raw, '--out', out, '--voxel-size', size, '--force']);
timed('--volume, Deflate TIFF', deflate, ['tests/measure/runMeasure.ts', 'measure', '--volume', deflate, '--out', out, '--voxel-size', size, '--force']);
timed('--volume --compare (10 realizations), Deflate TIFF', deflate, [
  'tests/measure/runMeasure.ts',
  'measure',
  '--volume',
  deflate,
  '--out',
  out,
  '--voxel-size',
  size,
  '--compare',
  '--force',
]);
