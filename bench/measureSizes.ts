/**
 * Time and peak memory of `tissue-sheet measure` on synthetic 16-bit label images of a given
 * size (docs/measure.md, "Size, memory and time"): writes the brick tiling of
 * tests/measure/bench8k.ts (two layers as 16-bit PNG, uncompressed TIFF, and one two-page
 * Deflate TIFF), then measures each form in a fresh process under /usr/bin/time -v and prints
 * peak RSS and wall time.
 *
 *   node --import tsx bench/measureSizes.ts [SIZE=2048] [DIR=/tmp/measure-bench]
 *
 * 8192 takes about a minute per form on a 2-core machine: run it alone.
 */
import { execFileSync, spawnSync } from 'node:child_process';
import { mkdirSync, statSync } from 'node:fs';
import { join } from 'node:path';

const size = Number(process.argv[2] ?? 2048);
const dir = process.argv[3] ?? `/tmp/measure-bench-${size}`;
mkdirSync(dir, { recursive: true });
execFileSync(process.execPath, ['--import', 'tsx', 'tests/measure/bench8k.ts', dir, String(size)], { stdio: 'inherit' });

const forms: [string, string[]][] = [
  ['two 16-bit PNG', ['basal.png', 'apical.png']],
  ['two uncompressed TIFF', ['basal-raw.tif', 'apical-raw.tif']],
  ['one two-page Deflate TIFF', ['stack.tif']],
];
const mb = (bytes: number) => (bytes / 2 ** 20).toFixed(1);
console.log(`| input (${size} x ${size}, 16-bit) | file size | peak RSS | wall time | cells | % scutoids |`);
console.log('| --- | --- | --- | --- | --- | --- |');
for (const [name, files] of forms) {
  const out = join(dir, 'r.json');
  const run = spawnSync(
    '/usr/bin/time',
    [
      '-v',
      process.execPath,
      '--import',
      'tsx',
      'tests/measure/runMeasure.ts',
      'measure',
      ...files.map((f) => join(dir, f)),
      '--out',
      out,
      '--pixel-size',
      '0.5',
      '--force',
    ],
    { encoding: 'utf8' },
  );
  if (run.status !== 0) throw new Error(`${name}: exit ${run.status}\n${run.stderr}`);
  const rss = Number(/Maximum resident set size \(kbytes\): (\d+)/.exec(run.stderr)![1]) * 1024;
  const wall = /Elapsed \(wall clock\) time \(h:mm:ss or m:ss\): ([\d:.]+)/.exec(run.stderr)![1];
  const seconds = wall.split(':').reduce((a, part) => 60 * a + Number(part), 0);
  const done = /done: (\d+) cells, \d+ valid, ([\d.]+) % scutoids/.exec(run.stderr)!;
  const bytes = files.reduce((a, f) => a + statSync(join(dir, f)).size, 0);
  console.log(`| ${name} | ${mb(bytes)} MB | ${mb(rss)} MB | ${seconds.toFixed(2)} s | ${done[1]} | ${done[2]} |`);
}
