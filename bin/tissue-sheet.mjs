#!/usr/bin/env node
// Launcher for the tissue-sheet CLI, runnable from a checkout with `npx tissue-sheet`.
// headless-gl needs an X display: without one, re-run this command under `xvfb-run -a`.
import { spawnSync } from 'node:child_process';
import { fileURLToPath } from 'node:url';

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

const { register } = await import('tsx/esm/api');
register();
const { main } = await import('../src/cli/main.ts');
process.exitCode = await main(process.argv.slice(2));
