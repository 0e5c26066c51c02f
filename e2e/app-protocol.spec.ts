import { expect, test } from '@playwright/test';
import { downloadExport, linkTo, runs, smallTube, waitForRun } from './appHelpers';

/**
 * Issue 26: every schema field is reachable in the form (the protocol with the sheet, the rest
 * under Advanced), and "Neighbours from: labels and exact" never silently gives only the exact
 * numbers: where the exact engine ran, the page and every file say the labels method was left
 * out and why; Engine "gpu" gives both.
 */

const SMALL = smallTube(3, 2, 2);

test('every schema field has a control: the protocol in the sheet, engine settings under Advanced', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await expect(page.getByLabel('Protocol', { exact: true })).toBeVisible();
  await page.locator('details.advanced summary').click();
  for (const path of [
    'engine',
    'sheet.layerStep',
    'sheet.validityMaxRatio',
    'sheet.minContactPixels',
    'sheet.minContactLength',
    'resolution',
    'lloyd.tolerance',
    'centroidPath',
    'jumpFlood.variant',
  ]) {
    await expect(page.locator(`#controls [name="${path}"]`), path).toBeVisible();
  }
  // Fields of other kinds appear with their kind.
  await expect(page.locator('#controls [name="sheet.offset"]')).toHaveCount(1);
  await page.getByLabel('Density preset').selectOption('gaussian');
  await expect(page.getByLabel('Patch centre u (µm)')).toBeVisible();
  await expect(page.getByLabel('Patch centre v (µm)')).toBeVisible();
});

test('the lab protocol can be chosen in the form, and the result says it ran under it', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  const before = await runs(page);
  await page.getByLabel('Protocol', { exact: true }).selectOption('lab');
  await waitForRun(page, before);
  const result = JSON.parse((await downloadExport(page, 'json')).text);
  expect(result.config.sheet.protocol).toBe('lab');
  expect(result.headline.protocol).toBe('lab');
  expect(new URL(page.url()).searchParams.get('config')).toContain('"protocol":"lab"');
});

test('"labels and exact" on the exact engine says the labels method was left out and why; Engine "gpu" gives both', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await expect(page.getByLabel('Neighbours from')).toHaveValue('both');
  const note = page.locator('#methods-note');
  await expect(note).toBeVisible();
  await expect(note).toHaveAttribute('data-omitted', 'labels');
  await expect(note).toContainText('Labels method left out: engine "auto" took the exact engine');
  await expect(note).toContainText('renderer here is software');
  const result = JSON.parse((await downloadExport(page, 'json')).text);
  expect(result.analyses.map((a: { method: string }) => a.method)).toEqual(['exact']);
  expect(result.headline.omittedMethods).toEqual([{ method: 'labels', reason: expect.stringContaining('software') }]);
  const csv = (await downloadExport(page, 'cells')).text;
  expect(csv).toMatch(/^# methods: labels method left out: engine "auto" took the exact engine/m);
  expect((await downloadExport(page, 'ply')).text).toContain('comment methods: labels method left out');

  await page.locator('details.advanced summary').click();
  const before = await runs(page);
  await page.locator('#controls [name="engine"]').selectOption('gpu');
  await waitForRun(page, before);
  await expect(note).toBeHidden();
  const both = JSON.parse((await downloadExport(page, 'json')).text);
  expect(both.analyses.map((a: { method: string }) => a.method).sort()).toEqual(['exact', 'labels']);
  expect(both.headline.omittedMethods).toEqual([]);
  await expect(page.locator('#summary tr').first()).toContainText('labels');
});
