import { expect, test } from '@playwright/test';
import { defaultResolution, validateConfig } from '../src/core/config';
import { downloadExport, linkTo, runs, waitForRun } from './appHelpers';
import { cliRun } from './cli';

/**
 * One set of defaults (issue 24): a config that leaves out lloyd and resolution runs the same
 * sheet in the app (a link), in `<tissue-sheet>` (attributes) and in the CLI, and gives the same
 * headline; the app's default resolution follows the cells until the user types one.
 */

const TUBE = { surface: { kind: 'tube', radius: 20, length: 200 }, cells: 50, seed: 2, sheet: { surfaceRatio: 2 } };

test('a link, the element and the CLI run the same config with the schema defaults and give the same headline', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  await expect(page.locator('#run-info')).toContainText('50 Lloyd iterations (Voronoi 51)');
  await expect(page.locator('#field-resolution')).toHaveValue('');
  await expect(page.locator('#field-resolution')).toHaveAttribute('placeholder', 'default: 512');
  // The realization drawn (the seed's own sites): its exact analysis, from the result JSON export.
  const shown = JSON.parse((await downloadExport(page, 'json')).text);
  const app = shown.analyses.find((a: { method: string }) => a.method === 'exact').summary.percentScutoids;

  await page.goto('/e2e/pages/interactive.html');
  await expect(page).toHaveTitle('ready');
  const element = await page.evaluate(async () => {
    const el = document.createElement('tissue-sheet');
    for (const [name, value] of Object.entries({ manual: '', surface: 'tube', radius: '20', length: '200', cells: '50', seed: '2', 'surface-ratio': '2' }))
      el.setAttribute(name, value);
    document.body.append(el);
    const detail = new Promise<{ result: { analyses: { method: string; summary: { percentScutoids: number } }[] }; headline: { voronoiK: number } | null }>(
      (resolve) => el.addEventListener('result', (e) => resolve((e as CustomEvent).detail), { once: true }),
    );
    await el.run();
    const d = await detail;
    const exact = d.result.analyses.find((a) => a.method === 'exact')!;
    return { config: el.config, percent: exact.summary.percentScutoids, voronoiK: d.headline?.voronoiK };
  });
  expect(element.config).toEqual(validateConfig(TUBE));
  expect(element.voronoiK).toBe(51);

  const cli = cliRun<{ config: unknown; analyses: { method: string; summary: { percentScutoids: number } }[] }>(TUBE).result;
  expect(cli.config).toEqual(validateConfig(TUBE));
  // The same sites, the same exact analysis, whichever entry point ran them.
  expect(element.percent).toBeCloseTo(app, 9);
  expect(cli.analyses.find((a: { method: string }) => a.method === 'exact')!.summary.percentScutoids).toBeCloseTo(element.percent, 9);
});

test("the app's default resolution follows the cells until one is typed", async ({ page }) => {
  const sphere = { surface: { kind: 'sphere', radius: 40 }, cells: 60, seed: 3, lloyd: { maxIterations: 1 }, sheet: { thickness: 5 } };
  await page.goto(linkTo(sphere));
  await waitForRun(page);
  const resolutionOf = (cells: number) => defaultResolution(validateConfig({ ...sphere, cells }));
  await expect(page.locator('#run-info')).toContainText(`cube map 6 x ${resolutionOf(60)}²`);
  await expect(page.locator('#field-resolution')).toHaveAttribute('placeholder', `default: ${resolutionOf(60)}`);

  // More cells: a finer default cube map, in the form and in the run.
  let before = await runs(page);
  await page.getByLabel('Cells', { exact: true }).fill('120');
  await page.getByLabel('Cells', { exact: true }).press('Enter');
  await waitForRun(page, before);
  expect(resolutionOf(120)).toBeGreaterThan(resolutionOf(60));
  await expect(page.locator('#run-info')).toContainText(`cube map 6 x ${resolutionOf(120)}²`);
  await expect(page.locator('#field-resolution')).toHaveAttribute('placeholder', `default: ${resolutionOf(120)}`);
  expect(JSON.parse(new URL(page.url()).searchParams.get('config')!).resolution).toBeNull();

  // A typed resolution stays, whatever the cells (the field is under Advanced).
  await page.locator('details.advanced > summary').click();
  before = await runs(page);
  await page.locator('#field-resolution').fill('48');
  await page.locator('#field-resolution').press('Enter');
  await waitForRun(page, before);
  before = await runs(page);
  await page.getByLabel('Cells', { exact: true }).fill('200');
  await page.getByLabel('Cells', { exact: true }).press('Enter');
  await waitForRun(page, before);
  await expect(page.locator('#run-info')).toContainText('cube map 6 x 48²');
});
