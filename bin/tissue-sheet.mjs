#!/usr/bin/env node
// Launcher for the tissue-sheet CLI: runs the compiled dist/esm/cli.js (built by
// `npm run build:lib`, shipped in the npm package; no TypeScript loader at run time).
// headless-gl needs an X display: without one, re-run this command under `xvfb-run -a`.
import { spawnSync } from 'node:child_process';
import { existsSync } from 'node:fs';
import { fileURLToPath } from 'node:url';

const compiled = new URL('../dist/esm/cli.js', import.meta.url);
if (!existsSync(compiled)) {
  console.error('tissue-sheet: dist/esm/cli.js is missing; in a checkout, build it first: npm run build:lib');
  process.exit(1);
}

if (!process.env.DISPLAY && !process.env.TISSUE_SHEET_UNDER_XVFB) {
  const child = spawnSync('xvfb-run', ['-a', process.execPath, fileURLToPath(import.meta.url), ...process.argv.slice(2)], {
    stdio: 'inherit',
    env: { ...process.env, TISSUE_SHEET_UNDER_XVFB: '1' },
  });
  if (child.error) {
    console.error('tissue-sheet: no X display and xvfb-run is missing; install it (apt-get install xvfb xauth) or set DISPLAY');
    process.exit(3);
  }
  process.exit(child.status ?? 1);
}

const { main } = await import(compiled.href);
process.exitCode = await main(process.argv.slice(2));
