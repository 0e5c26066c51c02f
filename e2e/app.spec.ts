import { expect, test, type Page } from '@playwright/test';
import { runs, waitForRun } from './appHelpers';

/**
 * The biologist's page on Debian's Chromium (SwiftShader WebGL2). The default run is small
 * (150 cells, 128 x 256 texels, 5 Lloyd iterations) and takes a few seconds here.
 * Screenshot tolerance: maxDiffPixelRatio 0.02 (playwright.config.ts); the timings are masked.
 */

async function percentScutoids(page: Page): Promise<number> {
  return Number(await page.locator('#percent-scutoids').getAttribute('data-drawn'));
}

test('default view (screenshot)', async ({ page }) => {
  await page.goto('/');
  await waitForRun(page);
  await expect(page.locator('#error')).toBeHidden();
  await expect(page.locator('#percent-scutoids')).toHaveText(/\d+\.\d %/);
  await expect(page.locator('#unrolled canvas')).toHaveCount(2);
  // The headline over its realizations (mean, 95 % CI, n) is what a person reads.
  await page.waitForFunction(() => document.body.dataset.headline === 'complete', undefined, { timeout: 120_000 });
  await page.evaluate(() => new Promise(requestAnimationFrame));
  await expect(page).toHaveScreenshot('app-default.png', {
    fullPage: true,
    mask: [page.locator('#status'), page.locator('#run-info')],
    maxDiffPixelRatio: 0.02,
  });
});

test('moving the surface ratio changes the reported % scutoids', async ({ page }) => {
  await page.goto('/');
  await waitForRun(page);
  const atDefault = await percentScutoids(page);
  const slider = page.getByLabel('Surface ratio R_outer / R_inner');
  await expect(slider).toHaveValue('1.5');

  let before = await runs(page);
  await slider.fill('1');
  await waitForRun(page, before);
  const atOne = await percentScutoids(page);

  before = await runs(page);
  await slider.fill('3');
  await waitForRun(page, before);
  const atThree = await percentScutoids(page);

  // Same sites on identical surfaces: no neighbour can change.
  expect(atOne).toBe(0);
  expect(atDefault).toBeGreaterThan(atOne);
  expect(atThree).toBeGreaterThan(atDefault);
  await expect(page.locator('#unrolled figcaption').nth(1)).toContainText('ratio 3.00');
  expect(new URL(page.url()).searchParams.get('config')).toContain('"surfaceRatio":3');
});

test('an impossible configuration is explained in words and the previous result stays', async ({ page }) => {
  await page.goto('/');
  await waitForRun(page);
  const shown = await percentScutoids(page);
  const table = await page.locator('#summary').textContent();

  await page.getByLabel('Cells', { exact: true }).fill('100000');
  await page.getByLabel('Cells', { exact: true }).press('Enter');
  await expect(page.locator('#error')).toBeVisible({ timeout: 60_000 });
  await expect(page.locator('#error')).toContainText('cells: 100000 cells need at least');
  await expect(page.locator('#error')).toContainText('raise resolution');
  expect(await percentScutoids(page)).toBe(shown);
  expect(await page.locator('#summary').textContent()).toBe(table);

  await page.locator('#field-lloyd-maxIterations').fill('-2');
  await page.locator('#field-lloyd-maxIterations').press('Enter');
  await expect(page.locator('#error')).toContainText('lloyd.maxIterations: must be an integer from 0 to 100000 (got -2)');
  expect(await percentScutoids(page)).toBe(shown);
});

test('closed surfaces are offered: sphere, ellipsoid and mesh (sample or upload)', async ({ page }) => {
  await page.goto('/');
  const surface = page.getByLabel('Surface', { exact: true });
  for (const kind of ['sphere', 'ellipsoid', 'mesh']) await expect(surface.locator(`option[value="${kind}"]`)).toBeEnabled();
  // Choosing one shows its own fields in place of the tube's.
  const fields: Record<string, string[]> = {
    sphere: ['Radius (µm)'],
    ellipsoid: ['Semi-axis a (x) (µm)', 'Semi-axis b (y) (µm)', 'Semi-axis c (z) (µm)'],
    mesh: ['Mesh', 'Mesh file (.ply, .obj, .stl)'],
  };
  for (const [kind, labels] of Object.entries(fields)) {
    await surface.selectOption(kind);
    for (const label of labels) await expect(page.getByLabel(label, { exact: true })).toBeVisible();
    await expect(page.getByLabel('Surface ratio R_outer / R_inner')).toBeHidden();
    await expect(page.getByLabel('Thickness (µm)')).toBeVisible();
  }
});

test('a plane runs, with thickness instead of a surface ratio', async ({ page }) => {
  await page.goto('/');
  await waitForRun(page);
  const before = await runs(page);
  await page.getByLabel('Surface', { exact: true }).selectOption('plane');
  await waitForRun(page, before);
  await expect(page.getByLabel('Thickness (µm)')).toBeVisible();
  await expect(page.getByLabel('Surface ratio R_outer / R_inner')).toBeHidden();
  // Parallel planes: the projected sites give the same diagram, so no scutoids.
  expect(await percentScutoids(page)).toBe(0);
});

test('without WebGL2 the page says so', async ({ browser }) => {
  const context = await browser.newContext();
  await context.addInitScript(() => {
    const original = HTMLCanvasElement.prototype.getContext;
    HTMLCanvasElement.prototype.getContext = function (this: HTMLCanvasElement, type: string, ...rest: unknown[]) {
      if (type === 'webgl2' || type === 'webgl' || type === 'experimental-webgl') return null;
      return (original as (...a: unknown[]) => unknown).call(this, type, ...rest);
    } as typeof original;
  });
  const page = await context.newPage();
  await page.goto('/');
  await expect(page.locator('#error')).toContainText('WebGL2 is not available here');
  await expect(page.locator('body')).toHaveAttribute('data-state', 'no-webgl');
  await expect(page.locator('#run')).toBeDisabled();
  await expect(page.locator('#view-message')).toContainText('needs WebGL');
  await context.close();
});
