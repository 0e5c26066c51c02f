import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { downloadExport, injectedScriptRuns, linkTo, runs, smallTube, waitForRun } from './appHelpers';
import { readPngText } from '../tests/app/pngRead';
import { parseCsv } from '../src/core/sweep/csv';

/**
 * Issues 14 and 19 in the page: links are untrusted input (validated, shown, never stored,
 * bounded, foreign sources only after a click), the headline says its method, 0 % by
 * construction says why, exports carry provenance, help and tooltips, layout at 800 px, CSP.
 * Runs stay tiny (≤ 80 cells, resolution ≤ 256).
 */

const SMALL = smallTube(3, 2, 2);

const STORAGE_KEY = 'tissue-sheet:last-config';

test('a broken link shows a lasting alert, runs nothing and leaves the address as it was', async ({ page }) => {
  for (const bad of ['{not json', JSON.stringify({ ...SMALL, cells: -4 })]) {
    const address = linkTo(bad);
    await page.goto(address);
    const alert = page.locator('#link-alert');
    await expect(alert).toBeVisible();
    await expect(alert).toHaveAttribute('role', 'alert');
    await expect(alert).toContainText(bad.startsWith('{not') ? 'not valid JSON' : 'cells');
    await page.waitForTimeout(2500);
    // Still there, nothing ran, the address untouched.
    await expect(alert).toBeVisible();
    expect(await runs(page)).toBe(0);
    await expect(page.locator('body')).toHaveAttribute('data-state', 'refused');
    expect(page.url()).toBe(new URL(address, page.url()).toString());
    await alert.getByRole('button', { name: 'Dismiss' }).click();
    await expect(alert).toBeHidden();
  }
});

test('a valid link is shown and run, never stored; a run of the user’s own is', async ({ page }) => {
  await page.goto('/');
  await page.evaluate((key) => localStorage.removeItem(key), STORAGE_KEY);
  const address = linkTo(SMALL);
  await page.goto(address);
  await waitForRun(page);
  await expect(page.getByLabel('Cells', { exact: true })).toHaveValue('60');
  expect(await page.evaluate((key) => localStorage.getItem(key), STORAGE_KEY)).toBeNull();
  expect(new URL(page.url()).searchParams.get('config')).toBe(new URL(address, page.url()).searchParams.get('config'));
  // The user's own edit is theirs: stored.
  const before = await runs(page);
  await page.getByLabel('Random seed').fill('5');
  await page.getByLabel('Random seed').press('Enter');
  await waitForRun(page, before);
  expect(await page.evaluate((key) => localStorage.getItem(key), STORAGE_KEY)).toContain('"seed":5');
});

test('a link over the compute budget is refused before it runs', async ({ page }) => {
  const huge = { surface: { kind: 'plane', width: 1000, height: 1000 }, resolution: 8192, cells: 200, lloyd: { maxIterations: 5000 } };
  const started = Date.now();
  await page.goto(linkTo(huge));
  await expect(page.locator('#link-alert')).toContainText('above the limit', { timeout: 30_000 });
  expect(Date.now() - started).toBeLessThan(30_000);
  await expect(page.locator('#link-alert')).toContainText('texel-floods');
  expect(await runs(page)).toBe(0);
  await expect(page.locator('body')).toHaveAttribute('data-state', 'refused');
});

test('a source on another origin is named and requested only after the click', async ({ page }) => {
  let foreign = 0;
  const ply = readFileSync('public/meshes/egg-chamber.ply');
  await page.route(
    (url) => url.hostname === 'foreign.example',
    (route) => {
      foreign += 1;
      return route.fulfill({ status: 200, body: ply, headers: { 'content-type': 'application/octet-stream', 'access-control-allow-origin': '*' } });
    },
  );
  const config = {
    surface: { kind: 'mesh', src: 'https://foreign.example/lab/egg.ply', scale: 50 },
    resolution: 24,
    cells: 40,
    lloyd: { maxIterations: 1 },
    sheet: { thickness: 3 },
  };
  await page.goto(linkTo(config));
  const question = page.locator('#source-question');
  await expect(question).toBeVisible();
  await expect(question).toContainText('This link asks to load a mesh, /lab/egg.ply, from foreign.example');
  await page.waitForTimeout(1500);
  expect(foreign).toBe(0);
  expect(await runs(page)).toBe(0);
  await question.getByRole('button', { name: 'Load /lab/egg.ply from foreign.example' }).click();
  await waitForRun(page);
  expect(foreign).toBe(1);
});

test('the headline says its method; 0 by construction says why; Voronoi k is shown', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  const headline = page.locator('#percent-scutoids');
  await expect(headline).toHaveAttribute('data-method', 'exact');
  await expect(page.locator('#percent-scutoids-caption')).toContainText('exact adjacency');
  await expect(page.locator('#by-construction')).toBeHidden();
  await expect(page.locator('#run-info')).toContainText('2 Lloyd iterations (Voronoi 3)');
  await expect(page.locator('.live-note')).toContainText('Voronoi 3');
  // The exact analysis in the result gives the headline.
  const result = JSON.parse((await downloadExport(page, 'json')).text);
  const exact = result.analyses.find((a: { method: string }) => a.method === 'exact');
  expect(Number(await headline.getAttribute('data-drawn'))).toBe(exact.summary.percentScutoids);

  const before = await runs(page);
  await page.getByLabel('Surface ratio R_outer / R_inner').fill('1');
  await waitForRun(page, before);
  await expect(page.locator('#by-construction')).toBeVisible();
  await expect(page.locator('#by-construction')).toHaveAttribute('data-reason', 'surface-ratio-1');
  await expect(page.locator('#by-construction')).toContainText('0 by construction');
});

test('every surface kind starts from a sheet with a thickness', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  for (const kind of ['plane', 'sphere', 'ellipsoid', 'mesh']) {
    await page.getByLabel('Surface', { exact: true }).selectOption(kind);
    expect(Number(await page.getByLabel('Thickness (µm)').inputValue()), kind).toBeGreaterThan(0);
  }
});

test('"Copy link" copies the configuration of the result on screen, not the form', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await page.getByLabel('Cells', { exact: true }).fill('-3'); // invalid: not run
  await page.getByLabel('Cells', { exact: true }).press('Enter');
  await expect(page.locator('#error')).toContainText('cells');
  await page.locator('#share').click();
  const link = await page.locator('#share').getAttribute('data-link');
  const shared = JSON.parse(new URL(link!).searchParams.get('config')!);
  expect(shared.cells).toBe(60);
  expect(shared.seed).toBe(3);
});

test('exports carry provenance: CSV comments, PNG text, PLY comments; an empty view is not saved', async ({ page }) => {
  await page.goto(linkTo({ ...SMALL, lloyd: { maxIterations: 2000 } }));
  // Before any result: the PNG is refused with a message.
  await page.locator('[data-export="png"]').click();
  await expect(page.locator('#error')).toContainText('Nothing to save yet');
  await page.locator('#cancel').click();
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  const get = async (name: string) => (await downloadExport(page, name)).bytes;
  const csv = (await get('cells')).toString('utf8');
  const comments = csv.split('\r\n').filter((l) => l.startsWith('#'));
  expect(comments[0]).toMatch(/tissue-sheet \d+\.\d+\.\d+/);
  const config = JSON.parse(comments.find((l) => l.includes('config'))!.replace(/^.*?config[^:]*: /, ''));
  expect(config.cells).toBe(60);
  const records = parseCsv(
    csv
      .split('\r\n')
      .filter((l) => !l.startsWith('#'))
      .join('\r\n'),
  ).records;
  const header = records[0];
  for (const column of ['area_um2_basal', 'area_um2_apical', 'sides_basal', 'sides_apical', 'label_neighbours_basal', 'scutoid', 'transitions'])
    expect(header).toContain(column);
  expect(records.length - 1).toBe(60);

  const png = await get('png');
  const text = readPngText(new Uint8Array(png));
  expect(JSON.parse(text['tissue-sheet:config']).seed).toBe(3);
  expect(text['tissue-sheet:seed']).toBe('3');
  expect(text['tissue-sheet:version']).toMatch(/^\d+\.\d+\.\d+/);

  const ply = (await get('ply')).toString('utf8');
  const header2 = ply.slice(0, ply.indexOf('end_header'));
  expect(header2).toMatch(/comment .*config.*"cells":60/);
});

test('help, glossary, version, citations and a tooltip on every control', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await page.locator('#help-open').click();
  const help = page.locator('#help');
  await expect(help).toBeVisible();
  for (const term of ['Scutoid', 'Surface ratio s', 'Voronoi k', 'Label vs exact adjacency', 'Valid cells', "Lewis's law", 'Aboav-Weaire law']) {
    await expect(help.locator('dt', { hasText: term })).toBeVisible();
  }
  await expect(help).toContainText('Nat. Commun.');
  await expect(help.locator('#how-to-cite [data-version]')).toHaveText(/^\d+\.\d+\.\d+/);
  await help.getByRole('button', { name: 'Close help' }).click();
  await expect(help).toBeHidden();
  await page.locator('details.advanced > summary').click();
  const untitled = await page
    .locator('#controls .field:not([hidden])')
    .evaluateAll((rows) => rows.filter((r) => !(r.querySelector('input, select') as HTMLElement | null)?.title).map((r) => (r as HTMLElement).dataset.path));
  expect(untitled).toEqual([]);
  // Engine internals are in the Advanced section.
  for (const path of ['resolution', 'jumpFlood.variant', 'centroidPath']) {
    await expect(page.locator(`details.advanced .field[data-path="${path}"]`)).toHaveCount(1);
  }
});

test('at 800 px the results fit, charts (Lewis, Aboav-Weaire too) follow the width, a favicon is served', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await expect(page.locator('#chart-lewis .uplot')).toHaveCount(1);
  await expect(page.locator('#chart-aboav .uplot')).toHaveCount(1);
  const wide = await page.locator('#chart-lewis canvas').evaluate((c) => c.getBoundingClientRect().width);
  await page.setViewportSize({ width: 800, height: 800 });
  await page.waitForTimeout(500);
  const narrow = await page.locator('#chart-lewis canvas').evaluate((c) => c.getBoundingClientRect().width);
  expect(narrow).not.toBe(wide);
  const overflow = await page.evaluate(() => ({
    page: document.documentElement.scrollWidth,
    card: (document.querySelector('.results') as HTMLElement).getBoundingClientRect().right,
    table: (document.querySelector('#summary table') as HTMLElement).getBoundingClientRect().right,
  }));
  expect(overflow.page).toBeLessThanOrEqual(800);
  expect(overflow.table).toBeLessThanOrEqual(overflow.card);
  const icon = await page.locator('link[rel="icon"]').getAttribute('href');
  expect((await page.request.get(icon!)).status()).toBe(200);
});

test('the page runs under its Content-Security-Policy, which stops an injected inline script', async ({ page }) => {
  const violations: string[] = [];
  await page.exposeFunction('reportViolation', (v: string) => violations.push(v));
  await page.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (e) =>
      (window as unknown as { reportViolation(v: string): void }).reportViolation(`${e.violatedDirective} ${e.blockedURI}`),
    );
  });
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await expect(page.locator('meta[http-equiv="Content-Security-Policy"]')).toHaveCount(1);
  expect(violations).toEqual([]);
  expect(await injectedScriptRuns(page)).toBe(false);
  expect(violations.some((v) => v.startsWith('script-src'))).toBe(true);
});
