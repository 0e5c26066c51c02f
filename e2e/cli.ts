import { execFileSync } from 'node:child_process';
import { mkdtempSync, readFileSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join } from 'node:path';

/**
 * The CLI as the e2e tests call it: from its TypeScript sources (tests/cli/fromSource.mjs, the
 * same entry as bin/tissue-sheet.mjs, so a test checks the code as it is without a build), under
 * `xvfb-run -a` (headless-gl needs an X display, and Playwright's runner has none).
 */
export function runCli(args: readonly string[], options: { timeout?: number } = {}): string {
  return execFileSync('xvfb-run', ['-a', process.execPath, 'tests/cli/fromSource.mjs', ...args], {
    stdio: 'pipe',
    encoding: 'utf8',
    timeout: options.timeout ?? 150_000,
  });
}

/** A fresh folder for a test's files (a test's own output folder is emptied when it restarts). */
export function tempDir(prefix: string): string {
  return mkdtempSync(join(tmpdir(), `tissue-sheet-${prefix}-`));
}

/**
 * `tissue-sheet run` on `config` (written to config.json in a fresh folder) with `args` after
 * `--out`: the result JSON it wrote, and the paths of both files.
 */
export function cliRun<T = unknown>(
  config: unknown,
  args: readonly string[] = [],
  options: { timeout?: number } = {},
): { result: T; configPath: string; resultPath: string } {
  const dir = tempDir('cli');
  const configPath = join(dir, 'config.json');
  const resultPath = join(dir, 'result.json');
  writeFileSync(configPath, JSON.stringify(config));
  runCli(['run', configPath, '--out', resultPath, ...args], options);
  return { result: JSON.parse(readFileSync(resultPath, 'utf8')) as T, configPath, resultPath };
}
