import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test } from '@playwright/test';
import { runCli, tempDir } from './cli';
import { openElementExample } from './elementHelpers';

/** The parts of a result JSON (README, "Result JSON") these tests read. */
interface ResultJson {
  config: Record<string, unknown>;
  gpu: { centroidPath: string };
  analyses: { method: string; summary: { percentScutoids: number }; cells: { sides: number[] }[] }[];
  cells: { neighbours: { id: number }[] }[];
  surfaces: { cells: { neighbours: { id: number }[] }[] }[];
  lloyd: { finalEnergy: number };
}

/**
 * `<tissue-sheet>` on Debian's Chromium. Screenshot tolerance: maxDiffPixelRatio 0.02.
 * The CLI comparison runs `tissue-sheet run` from source (e2e/cli.ts: headless-gl under xvfb-run on Mesa's
 * software rasterizer, where "auto" reads the ids back and sums on the CPU) on the element's own
 * config; the browser is told to run the additive blend path ("auto" would pick readback on
 * SwiftShader too). Both are Lloyd on the same grid from the same seeded sites, so the neighbour
 * sets and % scutoids are compared for equality, energies within a relative 1e-4.
 */

test('example page with two instances (screenshot)', async ({ page }) => {
  await openElementExample(page);
  await expect(page.locator('#bare').locator('.percent')).toHaveText(/\d+\.\d %/);
  await expect(page.locator('#wide').locator('.percent')).toHaveText(/\d+\.\d %/);
  expect(await page.locator('#bare').evaluate((e) => e.shadowRoot !== null)).toBe(true);
  await page.evaluate(() => new Promise(requestAnimationFrame));
  await expect(page).toHaveScreenshot('element-example.png', { maxDiffPixelRatio: 0.02 });
});

test('attributes, properties, methods and events', async ({ page }) => {
  await openElementExample(page);
  const outcome = await page.evaluate(async () => {
    const element = document.createElement('tissue-sheet');
    element.setAttribute('manual', '');
    element.setAttribute('cells', '80');
    element.setAttribute('iterations', '3');
    element.setAttribute('surface-ratio', '2');
    document.body.append(element);
    const progress: number[] = [];
    let fired: unknown = null;
    element.addEventListener('progress', (e) => progress.push(e.detail.iteration));
    let method = '';
    element.addEventListener('result', (e) => {
      fired = e.detail.percentScutoids;
      method = e.detail.method;
    });
    const result = await element.run();
    const exported = element.exportResult();
    const blob = await element.toBlob();
    const errors: unknown[] = [];
    element.addEventListener('error', (e) => errors.push(e.detail));
    element.setAttribute('cells', '-5');
    const failed = await element.run().then(
      () => 'resolved',
      (e: Error) => e.name,
    );
    return {
      progress,
      fired,
      // The event reports the exact method wherever the result has one (a tube has).
      method,
      percent: result.analyses.find((a) => a.method === 'exact')!.summary.percentScutoids,
      exportedCells: exported.cells.length,
      ratio: exported.config.sheet.surfaceRatio,
      blobType: blob.type,
      blobSize: blob.size,
      failed,
      errors,
      stillShown: element.result?.cells.length,
    };
  });
  expect(outcome.progress).toEqual([1, 2, 3]);
  expect(outcome.method).toBe('exact');
  expect(outcome.fired).toBe(outcome.percent);
  expect(outcome.exportedCells).toBe(80);
  expect(outcome.ratio).toBe(2);
  expect(outcome.blobType).toBe('image/png');
  expect(outcome.blobSize).toBeGreaterThan(2000);
  expect(outcome.failed).toBe('ConfigError');
  expect(outcome.errors).toEqual([{ name: 'ConfigError', field: 'cells', message: 'cells: must be an integer >= 1 (got -5)' }]);
  expect(outcome.stillShown).toBe(80);
});

test('the element fires result with the same numbers as the CLI for the same config', async ({ page }) => {
  await openElementExample(page);
  const browser = await page.evaluate(async () => {
    const element = document.createElement('tissue-sheet');
    element.setAttribute('manual', '');
    element.setAttribute('cells', '120');
    element.setAttribute('seed', '3');
    element.setAttribute('surface-ratio', '2');
    element.setAttribute('iterations', '4');
    // The GPU engine on both sides (auto takes the exact CPU engine on software renderers):
    // Chromium's blend path against headless-gl's readback.
    element.config = { centroidPath: 'blend', engine: 'gpu' };
    document.body.append(element);
    const detail = new Promise<unknown>((resolve) => element.addEventListener('result', (e) => resolve(e.detail), { once: true }));
    await element.run();
    return { config: element.config, detail: (await detail) as { result: ResultJson; percentScutoids: number } };
  });
  const dir = tempDir('element');
  writeFileSync(join(dir, 'cfg.json'), JSON.stringify({ ...browser.config, centroidPath: 'auto' }));
  runCli(['run', join(dir, 'cfg.json'), '--out', join(dir, 'out.json')]);
  const cli = JSON.parse(readFileSync(join(dir, 'out.json'), 'utf8')) as ResultJson;
  const web = browser.detail.result;

  expect(web.gpu.centroidPath).toBe('blend');
  expect(cli.gpu.centroidPath).toBe('readback');
  expect({ ...cli.config, centroidPath: 'blend' }).toEqual(web.config);
  for (const method of ['labels', 'exact']) {
    const a = web.analyses.find((x) => x.method === method)!;
    const b = cli.analyses.find((x) => x.method === method)!;
    expect(a.summary.percentScutoids, `${method} % scutoids`).toBe(b.summary.percentScutoids);
    expect(a.cells.map((c) => c.sides)).toEqual(b.cells.map((c) => c.sides));
  }
  expect(browser.detail.percentScutoids).toBe(cli.analyses.find((a) => a.method === 'exact')!.summary.percentScutoids);
  const neighbourSets = (r: Pick<ResultJson, 'cells'>) => r.cells.map((c) => c.neighbours.map((n) => n.id).sort((x, y) => x - y));
  expect(neighbourSets(web)).toEqual(neighbourSets(cli));
  expect(neighbourSets({ cells: web.surfaces.at(-1)!.cells })).toEqual(neighbourSets({ cells: cli.surfaces.at(-1)!.cells }));
  const relative = Math.abs(web.lloyd.finalEnergy - cli.lloyd.finalEnergy) / cli.lloyd.finalEnergy;
  expect(relative).toBeLessThan(1e-4);
});
