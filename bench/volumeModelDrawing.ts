/**
 * What drawing the model of the same tissue adds to the page's volume worker
 * (docs/measure.md, "The model drawn"): on the benchmark shell of bench/measureVolume.ts (512 x
 * 512 x 200, 300 cells; run that first, it writes the file), in one process, the CPU time of
 * measuring it (measureVolume with the meshes), of the comparison (compareVolume, 10
 * realizations: the baseline) and of drawing its first realization (volumeModelDrawing), as
 * ratios to the comparison's; and the drawing's size (triangles, bytes transferred to the page).
 *
 *   node --import tsx bench/volumeModelDrawing.ts [FILE=/tmp/measure-volume-bench/volume-512x512x200-300-deflate.tif]
 */
import { readFileSync } from 'node:fs';
import { compareVolume, measureVolume, volumeModelDrawing, type ShellMeshes } from '../src/core/measure';

const file = process.argv[2] ?? '/tmp/measure-volume-bench/volume-512x512x200-300-deflate.tif';
const bytes = new Uint8Array(readFileSync(file));

/** CPU milliseconds (user + system) and wall milliseconds of `f`. */
function timed<T>(f: () => T): { value: T; cpu: number; wall: number } {
  const c0 = process.cpuUsage();
  const w0 = performance.now();
  const value = f();
  const c = process.cpuUsage(c0);
  return { value, cpu: (c.user + c.system) / 1000, wall: performance.now() - w0 };
}

let meshes: ShellMeshes | undefined;
const measured = timed(() =>
  measureVolume({ name: file, read: () => bytes }, { voxelSize: { x: 0.2, y: 0.2, z: 0.5 }, version: 'bench', onSurfaceMeshes: (m) => (meshes = m) }),
);
const compared = timed(() => compareVolume(measured.value, { realizations: 10, seed: 1 }, meshes));
const comparison = compared.value.comparison;
if (!comparison) throw new Error(`no model: ${compared.value.note}`);
const drawn = timed(() => volumeModelDrawing(measured.value, comparison, meshes));
const drawing = drawn.value.drawing;
if (!drawing) throw new Error(drawn.value.note);

const transferred =
  drawing.valid.byteLength +
  drawing.scutoid.byteLength +
  drawing.surfaces.reduce((a, s) => a + [s.positions, s.cells, s.sites, s.sides, s.offsets, s.neighbours].reduce((b, x) => b + x.byteLength, 0), 0);
const row = (name: string, t: { cpu: number; wall: number }) =>
  console.log(`| ${name} | ${(t.cpu / 1000).toFixed(2)} s | ${(t.wall / 1000).toFixed(2)} s | ${(t.cpu / compared.cpu).toFixed(3)} |`);
console.log(`| ${file.split('/').pop()}, ${drawing.cells} cells | CPU | wall | CPU / comparison's |`);
console.log('| --- | --- | --- | --- |');
row('measureVolume (with the meshes)', measured);
row('baseline: compareVolume, 10 realizations', compared);
row('volumeModelDrawing (first realization)', drawn);
console.log(
  `drawing: ${drawing.surfaces.map((s) => `${s.name} ${s.cells.length} triangles`).join(', ')}; ${(transferred / 2 ** 20).toFixed(1)} MB transferred; ` +
    `matches the comparison's first realization: ${drawing.matches}; Voronoi ${drawing.k}, ${drawing.percentScutoids.toFixed(1)} % scutoids`,
);
