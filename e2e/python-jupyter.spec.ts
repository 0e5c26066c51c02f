import { spawn, type ChildProcess } from 'node:child_process';
import { existsSync, mkdirSync, mkdtempSync, readdirSync, readFileSync, rmSync, writeFileSync } from 'node:fs';
import { tmpdir } from 'node:os';
import { join, resolve } from 'node:path';
import { expect, test, type Page } from '@playwright/test';

/**
 * Issue 29: tissue_sheet.Sheet in a real JupyterLab (installed from PyPI into the venv that
 * scripts/test-python.sh makes, with the wheel it built), driven in Debian's Chromium: a notebook
 * shows the widget, the sheet runs in the browser (in the element's inlined worker), Python reads
 * the result, sets a new config and reads the new result, sees a change made in the widget, runs
 * a sweep in the browser in one cell (`runs = sheet.sweep(spec)` waits for the browser and
 * returns the DataFrame) that equals the CLI's runs.csv, saves the view as PNG, and a re-run cell
 * (the element registered again) is harmless, a refused config reaches Python as `sheet.error`; all of it under a Content-Security-Policy with no
 * other origin, and nothing requested from one.
 *
 * Run by `npm run test:python` (TISSUE_SHEET_JUPYTER_E2E=1, TISSUE_SHEET_VENV); skipped by a plain
 * `npm run test:e2e`, which has no venv.
 */

const venv = resolve(process.env.TISSUE_SHEET_VENV ?? 'python/.venv');
const jupyter = join(venv, 'bin', 'jupyter');
const port = Number(process.env.E2E_PORT ?? 5174) + 3000;
const base = `http://127.0.0.1:${port}`;
/**
 * The host's Content-Security-Policy: the app's (index.html), plus what any notebook widget needs
 * (anywidget imports the module from a blob: URL; JupyterLab itself evaluates code, and talks to
 * its kernel over a WebSocket). Nothing from another origin; workers only from 'self' or blob:.
 */
const csp = [
  "default-src 'self'",
  "script-src 'self' 'unsafe-eval' blob:",
  "style-src 'self' 'unsafe-inline'",
  "img-src 'self' data: blob:",
  `connect-src 'self' data: blob: ws://127.0.0.1:${port}`,
  "worker-src 'self' blob:",
  "font-src 'self' data:",
  "frame-src 'self'",
  "object-src 'none'",
  "base-uri 'self'",
].join('; ');

const config = {
  surface: { kind: 'tube', radius: 128 / (2 * Math.PI), length: 256 },
  resolution: 128,
  cells: 30,
  seed: 3,
  lloyd: { maxIterations: 3 },
  sheet: { surfaceRatio: 2 },
};
const spec = {
  base: { ...config, lloyd: { maxIterations: 2 } },
  vary: { 'sheet.surfaceRatio': [1.5, 2.5] },
  realizations: 2,
  seed: 7,
};

const cells = [
  // 0: the widget
  `import json, pandas as pd, tissue_sheet\nCONFIG = json.loads(${JSON.stringify(JSON.stringify(config))})\nsheet = tissue_sheet.Sheet(config=CONFIG, realizations=1, height="320px")\nsheet`,
  // 1: the result in Python
  `print("RESULT", sheet.result["config"]["cells"], len(sheet.cells), sheet.compute_site.get("where"), round(sheet.summary["percentScutoids"].iloc[0], 6) == round(sheet.result["headline"]["percentScutoids"], 6))`,
  // 2: a new config from Python
  `sheet.config = {**CONFIG, "cells": 24}`,
  // 3: the new result in Python
  `print("CHANGED", sheet.result["config"]["cells"], len(sheet.cells), sheet.config["cells"])`,
  // 4: after a change made in the widget
  `print("FROM WIDGET", sheet.config["cells"], sheet.result["config"]["cells"])`,
  // 5: the sweep by the CLI (headless)
  `SPEC = json.loads(${JSON.stringify(JSON.stringify(spec))})\ncli = tissue_sheet.sweep(SPEC, out="cli-sweep", workers=1)\nprint("CLI", len(cli))`,
  // 6: the same sweep in the browser, in one cell: it waits for the browser and returns runs.csv as a DataFrame
  `runs = sheet.sweep(SPEC, timeout=240)\npd.testing.assert_frame_equal(runs, cli)\nprint("SWEEP EQUAL", type(runs).__name__, len(runs), list(runs.columns) == list(cli.columns), sheet.last_sweep.done)`,
  // 7: a figure
  `figure = sheet.save_figure("view.png")`,
  // 8: the figure on disk
  `print("FIGURE", figure.done, open("view.png", "rb").read()[:4] == b"\\x89PNG", figure.bytes > 1000)`,
  // 9: the widget cell again (the element is registered a second time)
  `again = tissue_sheet.Sheet(config={**CONFIG, "cells": 20}, realizations=1, height="320px")\nagain`,
  // 10: a config the element refuses
  `sheet.config = {**CONFIG, "cells": -5}`,
  // 11: the refusal in Python; the last result stays
  `print("REFUSED", sheet.result["config"]["cells"], sheet.error)`,
];

function notebook(): string {
  return JSON.stringify({
    cells: cells.map((source) => ({ cell_type: 'code', execution_count: null, metadata: {}, outputs: [], source })),
    metadata: { kernelspec: { name: 'python3', display_name: 'Python 3', language: 'python' } },
    nbformat: 4,
    nbformat_minor: 5,
  });
}

async function runCell(page: Page, index: number, timeout = 120_000): Promise<void> {
  const cell = page.locator('.jp-Notebook .jp-Cell').nth(index);
  await cell.locator('.jp-InputArea-editor').click();
  await page.keyboard.press('Shift+Enter');
  // Done when the prompt shows an execution count ("[n]:"), not "[*]:".
  await expect(cell.locator('.jp-InputPrompt')).toHaveText(/\[\d+\]/, { timeout });
}

const output = (page: Page, index: number) => page.locator('.jp-Notebook .jp-Cell').nth(index).locator('.jp-OutputArea');

async function waitForResult(page: Page, nth: number, cellsWanted: number): Promise<void> {
  await page.waitForFunction(
    ([nth, n]) => {
      const el = document.querySelectorAll('tissue-sheet')[nth];
      return el?.result?.config.cells === n;
    },
    [nth, cellsWanted] as const,
    { timeout: 120_000 },
  );
}

test.describe('tissue_sheet.Sheet in JupyterLab', () => {
  test.skip(process.env.TISSUE_SHEET_JUPYTER_E2E !== '1', 'run by npm run test:python (scripts/test-python.sh), which makes the venv');

  let server: ChildProcess | undefined;
  let dir = '';
  let log = '';

  test.beforeAll(async () => {
    if (!existsSync(jupyter)) throw new Error(`${jupyter} is missing: run scripts/test-python.sh, which installs JupyterLab and the wheel`);
    dir = mkdtempSync(join(tmpdir(), 'tissue-sheet-jupyter-'));
    writeFileSync(join(dir, 'sheet.ipynb'), notebook());
    // No news or update checks (a closed network), and no notification in front of the cells.
    const settings = join(dir, '.settings', '@jupyterlab', 'apputils-extension');
    mkdirSync(settings, { recursive: true });
    writeFileSync(join(settings, 'notification.jupyterlab-settings'), JSON.stringify({ fetchNews: 'false', checkForUpdates: false }));
    server = spawn(
      jupyter,
      [
        'lab',
        '--no-browser',
        '--allow-root',
        '--ip=127.0.0.1',
        `--port=${port}`,
        '--ServerApp.token=',
        '--ServerApp.password=',
        `--ServerApp.root_dir=${dir}`,
        '--LabApp.news_url=',
        `--ServerApp.tornado_settings=${JSON.stringify({ headers: { 'Content-Security-Policy': csp } })}`,
      ],
      {
        cwd: dir,
        env: {
          ...process.env,
          JUPYTERLAB_SETTINGS_DIR: join(dir, '.settings'),
          JUPYTER_CONFIG_DIR: join(dir, '.jupyter'),
          TISSUE_SHEET_CLI: resolve('bin/tissue-sheet.mjs'),
        },
        stdio: ['ignore', 'pipe', 'pipe'],
      },
    );
    server.stdout?.on('data', (d) => (log += String(d)));
    server.stderr?.on('data', (d) => (log += String(d)));
    const start = Date.now();
    for (;;) {
      try {
        if ((await fetch(`${base}/api/status`)).ok) break;
      } catch {
        /* not listening yet */
      }
      if (Date.now() - start > 90_000 || server.exitCode !== null) throw new Error(`JupyterLab did not start:\n${log}`);
      await new Promise((r) => setTimeout(r, 500));
    }
  });

  test.afterAll(async () => {
    if (server && server.exitCode === null) {
      server.kill('SIGTERM');
      await new Promise((r) => server!.once('exit', r));
    }
    if (dir) rmSync(dir, { recursive: true, force: true });
  });

  test('a notebook shows the sheet; Python sets its config and reads its results, sweeps and figures', async ({ page }) => {
    test.setTimeout(480_000);
    const errors: string[] = [];
    page.on('pageerror', (e) => errors.push(e.message));
    // Nothing is fetched from elsewhere: every request goes to the notebook server (or is a blob:/data: URL).
    const elsewhere: string[] = [];
    page.on('request', (r) => {
      if (!/^(blob:|data:)/.test(r.url()) && !r.url().startsWith(base)) elsewhere.push(r.url());
    });
    const violations: string[] = [];
    page.on('console', (m) => {
      if (/Content Security Policy/i.test(m.text())) violations.push(m.text());
    });
    await page.goto(`${base}/lab/tree/sheet.ipynb`);
    await expect(page.locator('.jp-Notebook .jp-Cell')).toHaveCount(cells.length, { timeout: 90_000 });
    await expect(page.locator('.jp-Notebook-ExecutionIndicator[data-status="idle"]').first()).toBeAttached({ timeout: 90_000 });

    // JupyterLab's own page breaks this policy once (an inline script of its index page); what
    // the widget does afterwards must break it never.
    const hostViolations = violations.splice(0);
    await runCell(page, 0);
    await waitForResult(page, 0, 30);
    const site = await page.evaluate(() => document.querySelector('tissue-sheet')!.computeSite);
    expect(site.where, 'the inlined worker runs the sheet').toBe('worker');

    await runCell(page, 1);
    await expect(output(page, 1)).toContainText('RESULT 30 60 worker True');

    await runCell(page, 2);
    await waitForResult(page, 0, 24);
    await runCell(page, 3);
    await expect(output(page, 3)).toContainText('CHANGED 24 48 24');

    // A change made in the widget (the element's own config property) reaches Python.
    await page.evaluate(() => {
      const el = document.querySelector('tissue-sheet')!;
      el.config = { ...el.config, cells: 18 };
    });
    await waitForResult(page, 0, 18);
    await runCell(page, 4);
    await expect(output(page, 4)).toContainText('FROM WIDGET 18 18');

    await runCell(page, 5, 180_000);
    await expect(output(page, 5)).toContainText('CLI 4');
    // One cell: sheet.sweep(spec) blocks while the browser runs the sweep (the kernel handles
    // the widget's messages meanwhile) and returns the DataFrame, equal to the CLI's runs.csv.
    const sweepCell = page.locator('.jp-Notebook .jp-Cell').nth(6);
    await sweepCell.locator('.jp-InputArea-editor').click();
    await page.keyboard.press('Shift+Enter');
    // While the cell runs, the element shows the progress and the cell's output a progress line.
    await expect(sweepCell.locator('.jp-InputPrompt')).toHaveText(/\[\*\]/, { timeout: 30_000 });
    await expect(page.locator('.tissue-sheet-widget-progress').first()).toContainText('sweep:', { timeout: 60_000 });
    await expect(sweepCell.locator('.jp-InputPrompt')).toHaveText(/\[\d+\]/, { timeout: 240_000 });
    await expect(output(page, 6)).toContainText('SWEEP EQUAL DataFrame 4 True True');
    await expect(output(page, 6)).toContainText(/sweep: 4 runs done in [\d.]+ s/);
    await expect(page.locator('.tissue-sheet-widget-progress').first()).toContainText('sweep: 4 runs done');
    await expect(page.locator('.tissue-sheet-widget-progress progress').first()).toHaveAttribute('value', '4');

    await runCell(page, 7);
    await expect.poll(() => existsSync(join(dir, 'view.png')), { timeout: 60_000 }).toBe(true);
    await runCell(page, 8);
    await expect(output(page, 8)).toContainText('FIGURE True True True');
    expect(readFileSync(join(dir, 'view.png')).subarray(1, 4).toString()).toBe('PNG');

    await runCell(page, 9);
    await waitForResult(page, 1, 20);

    // The widget module evaluated twice more on the same page (two more definitions of the
    // element's class): no error, and the element already registered keeps working.
    const installed = readdirSync(join(venv, 'lib')).map((v) => join(venv, 'lib', v, 'site-packages', 'tissue_sheet', 'static', 'widget.js'));
    const moduleText = readFileSync(
      installed.find((p) => existsSync(p))!,
      'utf8',
    );
    const twice = await page.evaluate(async (text) => {
      const load = async () => {
        const url = URL.createObjectURL(new Blob([text], { type: 'text/javascript' }));
        try {
          return (await import(/* @vite-ignore */ url)) as { default: { render: unknown } };
        } finally {
          URL.revokeObjectURL(url);
        }
      };
      const [a, b] = [await load(), await load()];
      return [typeof a.default.render, typeof b.default.render, customElements.get('tissue-sheet') === document.querySelector('tissue-sheet')!.constructor];
    }, moduleText);
    expect(twice).toEqual(['function', 'function', true]);

    await page.evaluate(() => {
      const w = window as unknown as { refused?: string };
      document.querySelector('tissue-sheet')!.addEventListener('error', (e) => (w.refused = (e as CustomEvent<{ message: string }>).detail.message));
    });
    await runCell(page, 10);
    const refused = await page.waitForFunction(() => (window as unknown as { refused?: string }).refused, undefined, { timeout: 60_000 });
    const message = String(await refused.jsonValue());
    expect(message).toContain('cells');
    await runCell(page, 11);
    await expect(output(page, 11)).toContainText(`REFUSED 18 ${message}`);
    await expect(page.locator('.jp-OutputArea-output[data-mime-type="application/vnd.jupyter.stderr"]')).toHaveCount(0);
    expect(errors, `page errors:\n${errors.join('\n')}`).toEqual([]);
    expect(elsewhere, 'requests to other origins').toEqual([]);
    expect(violations, `CSP violations after the page loaded (the page's own: ${hostViolations.length})`).toEqual([]);
    const header = (await page.request.get(`${base}/lab/tree/sheet.ipynb`)).headers()['content-security-policy'];
    expect(header, 'the server sent the CSP under test').toBe(csp);
  });
});
