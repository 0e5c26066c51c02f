import { mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { download, expectNoLongTasks, linkTo } from './appHelpers';
import { runCli, tempDir } from './cli';
import { installLongTaskObserver, takeLongTasks } from './pages/longTasks';
import type { MeasuredResult } from '../src/core/measure';
import { png16, randomSites, rasterizeVoronoi } from '../tests/measure/images';

/**
 * Issue 16, the app: label images dropped on the page are measured in a worker and shown with
 * the numbers `tissue-sheet measure --compare` gives for the same files (% scutoids, valid cells,
 * the best Voronoi k and the model's % scutoids), the cells can be picked, a bad file shows an
 * alert naming it and leaves the tissue shown, and no main-thread task exceeds 50 ms while
 * measuring. The images are a known Voronoi tiling: 70 random sites on a 256 x 192 basal layer,
 * the same sites on a 512 x 192 apical layer (x doubled: an unrolled tube at s = 2), periodic in x.
 */

const small = { surface: { kind: 'tube', radius: 128 / (2 * Math.PI), length: 256 }, resolution: 128, cells: 60, seed: 3, lloyd: { maxIterations: 2 } };

interface Inputs {
  dir: string;
  basal: Buffer;
  apical: Buffer;
  cli: MeasuredResult;
}

function makeInputs(dir: string): Inputs {
  mkdirSync(dir, { recursive: true });
  const width = 256;
  const height = 192;
  const sites = randomSites(70, width, height, 7);
  const labels = sites.map((_, i) => 5 + 3 * i); // not consecutive: the result reports the original labels
  const basal = Buffer.from(png16(rasterizeVoronoi(width, height, sites, labels, true)));
  const apical = Buffer.from(
    png16(
      rasterizeVoronoi(
        2 * width,
        height,
        sites.map(([x, y]) => [2 * x, y]),
        labels,
        true,
      ),
    ),
  );
  writeFileSync(join(dir, 'basal.png'), basal);
  writeFileSync(join(dir, 'apical.png'), apical);
  const out = join(dir, 'cli.json');
  runCli(['measure', join(dir, 'basal.png'), join(dir, 'apical.png'), '--out', out, '--pixel-size', '0.5', '--periodic-x', '--compare', '--force']);
  return { dir, basal, apical, cli: JSON.parse(readFileSync(out, 'utf8')) as MeasuredResult };
}

/** Drops files (name, bytes) on the page body, as a user dragging them from a file manager. */
async function dropFiles(page: Page, files: { name: string; bytes: Buffer; type: string }[]): Promise<void> {
  const payload = files.map((f) => ({ name: f.name, type: f.type, base64: f.bytes.toString('base64') }));
  await page.evaluate((payload) => {
    const transfer = new DataTransfer();
    for (const f of payload) {
      const bytes = Uint8Array.from(atob(f.base64), (c) => c.charCodeAt(0));
      transfer.items.add(new File([bytes], f.name, { type: f.type }));
    }
    const target = document.querySelector('#results-title')!;
    target.dispatchEvent(new DragEvent('dragover', { dataTransfer: transfer, bubbles: true, cancelable: true }));
    target.dispatchEvent(new DragEvent('drop', { dataTransfer: transfer, bubbles: true, cancelable: true }));
  }, payload);
}

async function openApp(page: Page): Promise<void> {
  await installLongTaskObserver(page);
  await page.goto(linkTo(small));
  // The simulated sheet's own first run is not part of the measurement.
  await page.waitForFunction(() => ['done', 'no-webgl', 'error'].includes(document.body.dataset.state ?? ''), null, { timeout: 120_000 });
  await page.waitForTimeout(300);
  await takeLongTasks(page);
}

const dataValue = async (page: Page, selector: string) => Number(await page.locator(selector).getAttribute('data-value'));

test.describe('measure a tissue in the app', () => {
  let inputs: Inputs;
  test.beforeAll(async () => {
    // A folder of its own: a test's output folder is emptied when that test (re)starts.
    inputs = makeInputs(tempDir('measure'));
  });

  test('dropped label PNGs give the CLI numbers and the model comparison, without long tasks; cells can be picked', async ({ page }, testInfo) => {
    const cli = inputs.cli;
    expect(cli.analyses[0].summary.validCells).toBeGreaterThan(20);
    expect(cli.comparison).not.toBeNull();
    await openApp(page);
    await page.locator('#measure-pixel-size').fill('0.5');
    await page.locator('#measure-periodic').check();
    await dropFiles(page, [
      { name: 'basal.png', bytes: inputs.basal, type: 'image/png' },
      { name: 'apical.png', bytes: inputs.apical, type: 'image/png' },
    ]);
    await expect(page.locator('#measure')).toHaveAttribute('data-state', 'compared', { timeout: 120_000 });
    await expectNoLongTasks(page);

    const summary = cli.analyses[0].summary;
    expect(await dataValue(page, '#measured-percent')).toBe(summary.percentScutoids);
    expect(await dataValue(page, '#measure-summary tr[data-key="validCells"]')).toBe(summary.validCells);
    expect(await dataValue(page, '#measure-summary tr[data-key="percentScutoids"]')).toBe(summary.percentScutoids);
    expect(await dataValue(page, '#measure-summary tr[data-key="meanTransitions"]')).toBeCloseTo(summary.meanTransitions, 12);
    // The model: the CLI's best k and its mean % scutoids over the same realizations and seeds.
    const comparison = cli.comparison!;
    await expect(page.locator('#model-percent')).toHaveAttribute('data-best-k', String(comparison.bestK));
    expect(await dataValue(page, '#model-percent')).toBeCloseTo(comparison.meanPercentScutoids, 9);
    expect(Number(await page.locator('#measure-summary tr[data-key="percentScutoids"] td').nth(1).getAttribute('data-value'))).toBeCloseTo(
      comparison.meanPercentScutoids,
      9,
    );
    await expect(page.locator('#measure-summary th').nth(2)).toContainText(`Voronoi ${comparison.bestK}`);
    await expect(page.locator('#measure-chart .u-title')).toHaveText(/Polygon distribution/);

    // Both layers drawn at their size (the apical one twice as wide), coloured like simulated cells.
    const canvases = page.locator('#measure-layers canvas');
    await expect(canvases).toHaveCount(2);
    expect(await canvases.nth(0).evaluate((c: HTMLCanvasElement) => [c.width, c.height])).toEqual([256, 192]);
    expect(await canvases.nth(1).evaluate((c: HTMLCanvasElement) => [c.width, c.height])).toEqual([512, 192]);

    // Picking: the cell under the click is described with the CLI's record of that label.
    const box = (await canvases.nth(0).boundingBox())!;
    await canvases.nth(0).click({ position: { x: box.width * 0.5, y: box.height * 0.5 } });
    const info = page.locator('#measure-cell');
    await expect(info).toHaveAttribute('data-label', /\d+/);
    const label = Number(await info.getAttribute('data-label'));
    const record = cli.cells.find((c) => c.label === label)!;
    expect(record).toBeDefined();
    await expect(info).toHaveAttribute('data-scutoid', String(record.scutoid));
    await expect(info).toContainText(`Neighbours on basal: ${record.neighbours[0].join(', ')}.`);
    await expect(info).toContainText(`Neighbours on apical: ${record.neighbours[1].join(', ')}.`);
    // The picked cell is white on both layers.
    const whiteOnEvery = await canvases.evaluateAll((list: HTMLCanvasElement[]) =>
      list.map((c) => {
        const d = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
        let white = 0;
        for (let k = 0; k < d.length; k += 4) if (d[k] === 255 && d[k + 1] === 255 && d[k + 2] === 255) white++;
        return white;
      }),
    );
    expect(whiteOnEvery.every((n) => n > 0)).toBe(true);
    // The result JSON: the CLI's document (timings and file paths aside).
    const saved = JSON.parse((await download(page, '#measure-json')).text) as MeasuredResult;
    expect(saved.analyses).toEqual(cli.analyses);
    expect(saved.cells).toEqual(cli.cells);
    expect(saved.comparison!.bestK).toBe(comparison.bestK);
    expect(saved.comparison!.percentScutoids).toEqual(comparison.percentScutoids);
    await page.locator('#measure').screenshot({ path: process.env.MEASURE_SHOT ?? testInfo.outputPath('measure-panel.png') });
  });

  test('a bad file shows an alert naming it and leaves the measured tissue shown; one PNG from the picker is refused', async ({ page }) => {
    await openApp(page);
    await page.locator('#measure-pixel-size').fill('0.5');
    await page.locator('#measure-periodic').check();
    await page.locator('#measure-files').setInputFiles([join(inputs.dir, 'basal.png'), join(inputs.dir, 'apical.png')]);
    await expect(page.locator('#measure')).toHaveAttribute('data-state', 'compared', { timeout: 120_000 });
    const shown = await dataValue(page, '#measured-percent');
    expect(shown).toBe(inputs.cli.analyses[0].summary.percentScutoids);

    await dropFiles(page, [
      { name: 'basal.png', bytes: inputs.basal, type: 'image/png' },
      { name: 'notes.txt', bytes: Buffer.from('not an image'), type: 'text/plain' },
    ]);
    const alert = page.locator('#measure-alert');
    await expect(alert).toBeVisible();
    await expect(alert).toHaveAttribute('role', 'alert');
    await expect(alert).toContainText('notes.txt: not a PNG or TIFF image');
    await expect(page.locator('#measure')).toHaveAttribute('data-state', 'shown');
    expect(await dataValue(page, '#measured-percent')).toBe(shown);
    await expect(page.locator('#measure-layers canvas')).toHaveCount(2);

    // One 2D image alone is not a stack.
    await page.locator('#measure-files').setInputFiles(join(inputs.dir, 'basal.png'));
    await expect(alert).toContainText('basal.png: one 2D image');
    // No pixel size anywhere: the page names its field, not the CLI's option.
    await page.locator('#measure-alert [data-dismiss]').click();
    await page.locator('#measure-pixel-size').fill('');
    await page.locator('#measure-again').click();
    await expect(alert).toBeVisible();
    await page.locator('#measure-files').setInputFiles([join(inputs.dir, 'basal.png'), join(inputs.dir, 'apical.png')]);
    await expect(alert).toContainText('basal.png: no pixel size in the metadata; give a pixel size (µm) above');
    expect(await dataValue(page, '#measured-percent')).toBe(shown);
  });
});
