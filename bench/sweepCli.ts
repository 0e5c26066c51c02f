/**
 * The published tube sweep with the lab protocol (examples/published-tube-sweep-lab.json:
 * Voronoi 1–10 × 12 ratios × R realizations, exact engine) through `tissue-sheet sweep`, against
 * the fair NumPy/SciPy program computing the same table (bench/exactSweep.py: one
 * scipy.spatial.Delaunay per tessellation, no Python loop over cells), timed in the same run:
 *
 *   1. NumPy/SciPy baseline (`--python`, default python3; needs numpy and scipy): wall time of
 *      the process, start included;
 *   2. `tissue-sheet sweep --workers N` (default the machine's cores), start included, alternated
 *      with the baseline `--repeats` times; the ratio CLI / NumPy of each pair and their median;
 *   3. `--workers 1` once, and whether its files equal the N-thread sweep's byte for byte;
 *   4. optionally (`--shards S`, S > 0) S shards side by side and `merge`, compared with the
 *      whole sweep's files;
 *   5. for reference, bench/exactSweep.ts (the same grid in process, one thread, no files);
 *   6. optionally (`--against "node OTHER/bin/tissue-sheet.mjs"`: another build, e.g. a copy of
 *      another commit's bin/, dist/ and package.json beside a node_modules) that CLI right after
 *      this one in every pair, the ratio this / that of each pair and their median, and whether
 *      their files are the same: a change of a few per cent is seen only this way on a machine
 *      whose speed drifts from one minute to the next.
 *
 *   xvfb-run -a npx tsx bench/sweepCli.ts [--realizations 20] [--workers N] [--repeats 3]
 *       [--shards 0] [--python python3] [--cli "node bin/tissue-sheet.mjs"] [--against "..."]
 *
 * The CLI defaults to the compiled one (bin/tissue-sheet.mjs, `npm run build:lib` first) when
 * dist/esm/cli.js exists, else the sources through tsx (slower to start). Peak memory of the
 * children from /usr/bin/time when present. Every figure is wall-clock on a machine other jobs
 * may share: compare ratios of the same run.
 */
import { spawn } from 'node:child_process';
import { existsSync, mkdtempSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { availableParallelism, loadavg, tmpdir } from 'node:os';
import { dirname, join } from 'node:path';
import { fileURLToPath } from 'node:url';

const args = process.argv.slice(2);
const option = (name: string, fallback: string) => {
  const at = args.indexOf(`--${name}`);
  return at >= 0 ? args[at + 1] : fallback;
};
const root = join(dirname(fileURLToPath(import.meta.url)), '..');
const realizations = Number(option('realizations', '20'));
const workers = Number(option('workers', String(availableParallelism())));
const repeats = Number(option('repeats', '3'));
const shards = Number(option('shards', '0'));
const python = option('python', 'python3');
const compiled = existsSync(join(root, 'dist/esm/cli.js'));
const cliCommand = option('cli', compiled ? `${process.execPath} bin/tissue-sheet.mjs` : `${process.execPath} tests/cli/fromSource.mjs`).split(' ');
const against = args.includes('--against') ? option('against', '').split(' ') : null;
const work = mkdtempSync(join(tmpdir(), 'tissue-sheet-bench-sweep-'));
const hasTime = existsSync('/usr/bin/time');

const published = JSON.parse(readFileSync(join(root, 'examples/published-tube-sweep-lab.json'), 'utf8'));
const specPath = join(work, 'spec.json');
writeFileSync(specPath, JSON.stringify({ ...published, realizations }));
const runs = realizations * 10 * 12;
const FILES = ['runs.csv', 'aggregate.csv', 'aggregate.json', 'flintstones.csv'];

interface Timed {
  ms: number;
  peakMiB: number | null;
  /** User + system CPU seconds of the child (all its threads), with /usr/bin/time. */
  cpuS: number | null;
  stdout: string;
  stderr: string;
  status: number | null;
}

/** Runs a command; wall time and (with /usr/bin/time) peak RSS in MiB. */
function timed(command: string[]): Promise<Timed> {
  const full = hasTime ? ['/usr/bin/time', '-f', 'PEAK_KB %M CPU %U %S', ...command] : command;
  const t = performance.now();
  return new Promise((done) => {
    const child = spawn(full[0], full.slice(1), { cwd: root, stdio: ['ignore', 'pipe', 'pipe'] });
    let stdout = '';
    let stderr = '';
    child.stdout.on('data', (d) => (stdout += d));
    child.stderr.on('data', (d) => (stderr += d));
    child.on('close', (status) => {
      const peak = /PEAK_KB (\d+) CPU ([\d.]+) ([\d.]+)/.exec(stderr);
      done({
        ms: performance.now() - t,
        peakMiB: peak ? Number(peak[1]) / 1024 : null,
        cpuS: peak ? Number(peak[2]) + Number(peak[3]) : null,
        stdout,
        stderr,
        status,
      });
    });
  });
}
const s = (ms: number) => `${(ms / 1000).toFixed(2)} s`;
const mib = (x: number | null) => (x === null ? '' : `, peak RSS ${x.toFixed(0)} MiB`);
const cpu = (r: Timed) => (r.cpuS === null ? '' : `, CPU ${r.cpuS.toFixed(2)} s`);
const load = () => loadavg()[0].toFixed(1);
const median = (xs: number[]) => [...xs].sort((a, b) => a - b)[Math.floor((xs.length - 1) / 2)];

async function numpy(): Promise<Timed> {
  const r = await timed([python, 'bench/exactSweep.py', '--realizations', String(realizations)]);
  if (r.status !== 0) throw new Error(`NumPy baseline failed (needs numpy and scipy: pip install numpy scipy): ${r.stderr.slice(-500)}`);
  return r;
}

async function sweep(out: string, n: number, extra: string[] = [], cli = cliCommand): Promise<Timed> {
  const r = await timed([...cli, 'sweep', specPath, '--out', out, '--workers', String(n), ...extra]);
  if (r.status !== 0) throw new Error(`CLI sweep failed: ${r.stderr.slice(-500)}`);
  return r;
}

const same = (a: string, b: string) => FILES.every((f) => readFileSync(join(a, f), 'utf8') === readFileSync(join(b, f), 'utf8'));

async function main() {
  console.log(`published tube sweep, lab protocol, exact engine: ${runs} runs (Voronoi 1-10 x 12 ratios x ${realizations} realizations)`);
  console.log(`CLI: ${cliCommand.join(' ')}; ${availableParallelism()} cores; load ${load()} at start`);
  const ratios: number[] = [];
  const cpuRatios: number[] = [];
  const versus: number[] = [];
  let last = '';
  for (let k = 0; k < repeats; k++) {
    const base = await numpy();
    const out = join(work, `workers${workers}-${k}`);
    const cli = await sweep(out, workers);
    last = out;
    ratios.push(cli.ms / base.ms);
    if (cli.cpuS !== null && base.cpuS !== null) cpuRatios.push(cli.cpuS / base.cpuS);
    const inner = /in ([\d.]+) s/.exec(base.stdout)?.[1];
    console.log(
      `  pair ${k + 1}: NumPy/SciPy ${s(base.ms)} (computing ${inner} s${cpu(base)}${mib(base.peakMiB)}); tissue-sheet sweep --workers ${workers} ${s(cli.ms)}${cpu(cli)}${mib(cli.peakMiB)}; wall ratio ${(cli.ms / base.ms).toFixed(3)}x (load ${load()})`,
    );
    if (against) {
      const otherOut = join(work, `against-${k}`);
      const other = await sweep(otherOut, workers, [], against);
      versus.push(cli.ms / other.ms);
      console.log(
        `          --against: ${s(other.ms)}${cpu(other)}; this / that ${(cli.ms / other.ms).toFixed(3)}x; files ${same(out, otherOut) ? 'identical' : 'DIFFER'}`,
      );
    }
  }
  if (against) console.log(`this CLI / --against (${against.join(' ')}), wall: median ${median(versus).toFixed(3)}x over ${repeats} pairs`);
  console.log(
    `CLI / NumPy, wall: median ${median(ratios).toFixed(3)}x over ${repeats} pairs (target <= 0.2x)${cpuRatios.length ? `; CPU time: median ${median(cpuRatios).toFixed(2)}x` : ''}`,
  );

  const one = join(work, 'workers1');
  const single = await sweep(one, 1);
  console.log(
    `tissue-sheet sweep --workers 1: ${s(single.ms)}${cpu(single)}${mib(single.peakMiB)}; files ${same(one, last) ? 'identical to' : 'DIFFER from'} --workers ${workers}'s`,
  );

  if (shards > 0) {
    const t = performance.now();
    const parts = await Promise.all(Array.from({ length: shards }, (_, i) => sweep(join(work, `shard${i + 1}`), 1, ['--shard', `${i + 1}/${shards}`])));
    console.log(
      `${shards} shards side by side (--workers 1 each): ${s(performance.now() - t)}${mib(Math.max(...parts.map((p) => p.peakMiB ?? 0)) || null)} per shard`,
    );
    const merged = join(work, 'merged');
    const merge = await timed([...cliCommand, 'merge', ...parts.map((_, i) => join(work, `shard${i + 1}`)), '--out', merged]);
    console.log(`merge: ${s(merge.ms)} (process included); merged files ${same(one, merged) ? 'identical to' : 'DIFFER from'} the whole sweep's`);
  }

  const inProcess = await timed([process.execPath, '--import', 'tsx', 'bench/exactSweep.ts', '--realizations', String(realizations)]);
  console.log(
    `for reference, bench/exactSweep.ts (same grid in process, one thread, no files): ${inProcess.stdout.split('\n')[0].replace(/^exact engine, lab protocol: /, '')}`,
  );
  const flintstones = readFileSync(join(one, 'flintstones.csv'), 'utf8').trim().split(/\r?\n/);
  console.log(`flintstones.csv (${flintstones.length - 1} fits):`);
  for (const line of flintstones.slice(0, 4)) console.log(`   ${line.split(',').slice(0, 12).join(',')}`);
  rmSync(work, { recursive: true, force: true });
}

main().catch((error) => {
  console.error(error);
  process.exitCode = 1;
});
