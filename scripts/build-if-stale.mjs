// Rebuilds the package modules (dist/esm, what bin/tissue-sheet.mjs runs) when any source is
// newer than them, so tests that spawn the CLI never run stale compiled code: `npm run test:e2e`
// runs it first (e2e/element.spec.ts compares the element with `node bin/tissue-sheet.mjs`);
// `npm ci` runs it as `prepare`, so a fresh clone has a working CLI; `node
// scripts/build-if-stale.mjs` runs it by hand. The build goes to a temporary folder that then
// replaces dist/esm, so a CLI started by a concurrent test run never sees a half-written folder.
import { spawnSync } from 'node:child_process';
import { existsSync, readdirSync, renameSync, rmSync, statSync } from 'node:fs';
import { join, resolve } from 'node:path';
import { fileURLToPath } from 'node:url';

const root = resolve(fileURLToPath(new URL('..', import.meta.url)));
const built = join(root, 'dist/esm/cli.js');
const inputs = ['src', 'package.json', 'vite.lib.config.ts'].map((p) => join(root, p));

function newestMtime(path) {
  const stat = statSync(path);
  if (!stat.isDirectory()) return stat.mtimeMs;
  let newest = stat.mtimeMs; // a deleted or renamed file changes its folder's mtime
  for (const name of readdirSync(path)) newest = Math.max(newest, newestMtime(join(path, name)));
  return newest;
}

export function isStale() {
  if (!existsSync(built)) return true;
  const builtAt = statSync(built).mtimeMs;
  return inputs.some((input) => existsSync(input) && newestMtime(input) > builtAt);
}

/** Returns true when dist/esm is current afterwards; prints one line when the build fails. */
export function buildIfStale() {
  if (!isStale()) return true;
  const tmp = join(root, `dist/esm.tmp-${process.pid}`);
  const vite = join(root, 'node_modules/vite/bin/vite.js');
  const run = spawnSync(process.execPath, [vite, 'build', '-c', 'vite.lib.config.ts', '--outDir', tmp, '--logLevel', 'warn'], {
    cwd: root,
    encoding: 'utf8',
  });
  if (run.status !== 0) {
    rmSync(tmp, { recursive: true, force: true });
    const lines = run.stderr
      .replace(/\x1b\[[0-9;]*m/g, '')
      .split('\n')
      .map((line) => line.trim());
    const why = lines.find((line) => /^\[[A-Z_]+\]/.test(line)) ?? lines.find((line) => /error/i.test(line));
    console.error(`build-if-stale: the package build failed, so dist/esm (the CLI) is stale: ${why ?? 'run npm run build:esm to see why'}`);
    return false;
  }
  // Swap the new build in; another process (a concurrent test run) may be swapping its own.
  const esm = join(root, 'dist/esm');
  const old = join(root, `dist/esm.old-${process.pid}`);
  try {
    if (existsSync(esm)) renameSync(esm, old);
    renameSync(tmp, esm);
  } catch {
    // The other process's build is in place and just as new: keep it.
  }
  rmSync(tmp, { recursive: true, force: true });
  rmSync(old, { recursive: true, force: true });
  return true;
}

// By hand, or as the `prepare` script (which runs on `npm ci` / `npm install` in a checkout)
// with --never-fail: a broken build in a shared working tree must not make installing fail.
if (process.argv[1] && resolve(process.argv[1]) === fileURLToPath(import.meta.url)) {
  process.exit(buildIfStale() || process.argv.includes('--never-fail') ? 0 : 1);
}
