import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { downloadExport, linkTo, runs, shownElsewhere, shownResult, waitForRun } from './appHelpers';
import { tempDir } from './cli';

/**
 * Closed surfaces in the page (sphere, ellipsoid, meshes from public/meshes/ or uploaded) on
 * Debian's Chromium (SwiftShader). Small runs: 32 texels per cube-face edge, <= 100 cells, two
 * Lloyd iterations.
 */

const SMALL = { resolution: 32, cells: 100, seed: 3, lloyd: { maxIterations: 2 } };
const sphere = { ...SMALL, surface: { kind: 'sphere', radius: 50 }, sheet: { thickness: 10 } };
const eggChamber = { ...SMALL, surface: { kind: 'mesh', src: '/meshes/egg-chamber.ply', scale: 50 }, sheet: { thickness: 5 } };

async function percentScutoids(page: Page): Promise<number> {
  return Number(await page.locator('#percent-scutoids').getAttribute('data-drawn'));
}

test('a sphere runs: concentric spheres keep every neighbour (0 % scutoids)', async ({ page }) => {
  await page.goto(linkTo(sphere));
  await waitForRun(page);
  await expect(page.locator('#error')).toBeHidden();
  expect(await percentScutoids(page)).toBe(0);
  await expect(page.locator('#run-info')).toContainText('sphere, area');
  // The cube-map label images, one strip of six faces per surface, and the note.
  await expect(page.locator('#unrolled canvas')).toHaveCount(2);
  await expect(page.locator('#unrolled-note')).toContainText('cube-map label image');
  expect(
    await page
      .locator('#unrolled canvas')
      .first()
      .evaluate((c: HTMLCanvasElement) => [c.width, c.height]),
  ).toEqual([192, 32]);
  await expect(page.getByLabel('Radius (µm)')).toHaveValue('50');
  await expect(page.locator('#surface-toggles input')).toHaveCount(2);

  // Exports: the per-cell CSV gives the site's direction; the PLY holds both surfaces' meshes.
  const download = async (name: string) => (await downloadExport(page, name)).text;
  // Provenance comment lines (# ...) first, then the table.
  const csv = (await download('cells'))
    .trim()
    .split('\n')
    .filter((line) => !line.startsWith('#'));
  expect(csv[0]).toContain('longitude_deg,latitude_deg');
  expect(csv).toHaveLength(101);
  const ply = await download('ply');
  const vertices = Number(/element vertex (\d+)/.exec(ply)?.[1]);
  expect(vertices).toBeGreaterThan(2 * 100 * 30);
  expect(ply.trim().split('\n').length).toBe(
    ply.indexOf('end_header') >= 0 ? ply.slice(0, ply.indexOf('end_header')).split('\n').length + vertices + Number(/element face (\d+)/.exec(ply)?.[1]) : -1,
  );

  // The thickness slider re-runs; concentric spheres stay free of scutoids.
  const before = await runs(page);
  await page.getByLabel('Thickness (µm)').fill('30');
  await waitForRun(page, before);
  expect(await percentScutoids(page)).toBe(0);
  expect(new URL(page.url()).searchParams.get('config')).toContain('"thickness":30');
});

test('switching to an ellipsoid in the controls runs it', async ({ page }) => {
  await page.goto(linkTo(sphere));
  await waitForRun(page);
  const before = await runs(page);
  await page.getByLabel('Surface', { exact: true }).selectOption('ellipsoid');
  await waitForRun(page, before);
  await expect(page.locator('#error')).toBeHidden();
  await expect(page.getByLabel('Semi-axis a (x) (µm)')).toHaveValue('90');
  await expect(page.locator('#run-info')).toContainText('ellipsoid');
  expect(new URL(page.url()).searchParams.get('config')).toContain('"kind":"ellipsoid"');
});

test('uploading a mesh runs; a corrupt file and a genus-1 mesh show their messages and leave the result', async ({ page }) => {
  await page.goto(linkTo(eggChamber));
  await waitForRun(page);
  await expect(page.locator('#run-info')).toContainText('/meshes/egg-chamber.ply (1962 vertices');

  const before = await runs(page);
  await page.locator('input[name="surface.src"]').setInputFiles('public/meshes/organoid.ply');
  await waitForRun(page, before);
  await expect(page.locator('#error')).toBeHidden();
  await expect(page.locator('#run-info')).toContainText('organoid.ply (2562 vertices, 5120 faces');
  await expect(page.locator('.field-mesh-file output')).toHaveText('using your file organoid.ply (not in links)');
  await expect(page.locator('.field-mesh-file .note')).toContainText('cannot travel in a link');
  expect(new URL(page.url()).searchParams.get('config')).toContain('"src":"organoid.ply"');
  const percent = await percentScutoids(page);
  const summary = await page.locator('#summary').textContent();

  // A corrupt file: a few garbage bytes.
  const dir = tempDir('closed');
  const garbage = join(dir, 'garbage.ply');
  writeFileSync(garbage, Buffer.from([0x70, 0x6c, 0x79, 0x0a, 0xde, 0xad, 0xbe, 0xef, 0x00, 0x13]));
  await page.locator('input[name="surface.src"]').setInputFiles(garbage);
  await expect(page.locator('#error')).toBeVisible({ timeout: 60_000 });
  await expect(page.locator('#error')).toContainText('surface.src: garbage.ply:');
  await expect(page.locator('#status')).toHaveText('Failed; the previous result is still shown.');
  expect(await percentScutoids(page)).toBe(percent);
  expect(await page.locator('#summary').textContent()).toBe(summary);
  await expect(page.locator('#run-info')).toContainText('organoid.ply (2562 vertices');

  // A genus-1 mesh.
  await page.locator('input[name="surface.src"]').setInputFiles('public/meshes/torus.ply');
  await expect(page.locator('#error')).toContainText('surface.src: torus.ply: genus 1: this mesh has a hole through it', { timeout: 60_000 });
  expect(await percentScutoids(page)).toBe(percent);
  expect(await page.locator('#summary').textContent()).toBe(summary);
  // The link still holds the configuration of the result on screen.
  expect(new URL(page.url()).searchParams.get('config')).toContain('"src":"organoid.ply"');

  // The torus sample from the list says the same, naming its URL.
  await page.getByLabel('Mesh', { exact: true }).selectOption('torus.ply');
  await expect(page.locator('#error')).toContainText('surface.src: /meshes/torus.ply: genus 1', { timeout: 60_000 });
  expect(await percentScutoids(page)).toBe(percent);
});

test('a link with an uploaded file name asks for the file again', async ({ page }) => {
  await page.goto(linkTo({ ...eggChamber, surface: { kind: 'mesh', src: 'my-organoid.ply', scale: 50 } }));
  // The link's own configuration: said in the link's alert, which stays until dismissed.
  const alert = page.locator('#link-alert');
  await expect(alert).toContainText('"my-organoid.ply" is a file uploaded from a computer', { timeout: 60_000 });
  await expect(alert).toContainText('upload it again');
  await expect(alert).toContainText("This link's configuration was not run");
});

test('a URL round trip reproduces a closed-surface result (sphere and sample mesh)', async ({ page, browser }) => {
  for (const start of [sphere, eggChamber]) {
    await page.goto(linkTo(start));
    await waitForRun(page);
    const before = await runs(page);
    await page.getByLabel('Random seed').fill('11');
    await page.getByLabel('Random seed').press('Enter');
    await waitForRun(page, before);
    const link = page.url();
    expect(new URL(link).searchParams.get('config')).toContain('"seed":11');
    const shown = await shownResult(page);
    expect(shown.seed).toBe('11');
    expect(await shownElsewhere(browser, link)).toEqual(shown);
  }
});
