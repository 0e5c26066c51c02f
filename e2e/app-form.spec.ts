import { readFileSync, writeFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { downloadExport, linkTo, runs, waitForRun } from './appHelpers';

/**
 * Issue 26, the form: the address, the form and the result always agree (seed 1 -> 2 -> 1,
 * radius 20 -> 225 -> 20); a result that no longer matches the form is marked stale; a refusal
 * says what to change in µm and cells, engine words only on a details line; a decimal comma is a
 * decimal ("22,5" is 22.5 µm, never 225); every slider has a number box. Values are typed as a
 * person types: click, select all, keys, Enter. Runs stay tiny (60 cells).
 */

const TUBE = {
  surface: { kind: 'tube', radius: 20, length: 256 },
  resolution: 128,
  cells: 40,
  seed: 1,
  lloyd: { maxIterations: 2 },
  sheet: { surfaceRatio: 2 },
};

async function typeInto(page: Page, label: string, text: string): Promise<void> {
  const field = page.getByLabel(label, { exact: true });
  await field.click();
  await field.press('ControlOrMeta+a');
  await field.pressSequentially(text);
  await field.press('Enter');
}

const urlConfig = (page: Page) => JSON.parse(new URL(page.url()).searchParams.get('config')!);
const drawn = async (page: Page) => page.locator('#percent-scutoids').getAttribute('data-drawn');

const resultJson = async (page: Page) => JSON.parse((await downloadExport(page, 'json')).text);

test('seed 1 -> 2 -> 1: the address is the link again, and reloading shows the same result', async ({ page }) => {
  const link = linkTo(TUBE);
  await page.goto(link);
  await waitForRun(page);
  const first = await drawn(page);
  let before = await runs(page);
  await typeInto(page, 'Random seed', '2');
  await waitForRun(page, before);
  expect(urlConfig(page).seed).toBe(2);
  await expect(page.locator('body')).toHaveAttribute('data-stale', 'false');
  before = await runs(page);
  await typeInto(page, 'Random seed', '1');
  await waitForRun(page, before);
  expect(urlConfig(page).seed).toBe(1);
  expect(page.url()).toBe(new URL(link, page.url()).toString());
  expect(await drawn(page)).toBe(first);
  await page.reload();
  await waitForRun(page);
  expect(await drawn(page)).toBe(first);
  await expect(page.getByLabel('Random seed', { exact: true })).toHaveValue('1');
});

test('radius 20 -> 225 -> 20: the address, the form and the result agree at every step', async ({ page }) => {
  const link = linkTo(TUBE);
  await page.goto(link);
  await waitForRun(page);
  const first = await drawn(page);
  for (const [typed, radius] of [
    ['225', 225],
    ['20', 20],
  ] as const) {
    const before = await runs(page);
    await typeInto(page, 'Radius (µm)', typed);
    await waitForRun(page, before);
    expect(urlConfig(page).surface.radius).toBe(radius);
    expect((await resultJson(page)).config.surface.radius).toBe(radius);
    await expect(page.getByLabel('Radius (µm)', { exact: true })).toHaveValue(typed);
  }
  expect(page.url()).toBe(new URL(link, page.url()).toString());
  await page.reload();
  await waitForRun(page);
  expect(await drawn(page)).toBe(first);
});

test('a decimal comma is a decimal: "22,5" µm runs a 22.5 µm tube, never 225; "1,234.5" is refused in words', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  let before = await runs(page);
  await typeInto(page, 'Radius (µm)', '22,5');
  await waitForRun(page, before);
  expect(urlConfig(page).surface.radius).toBe(22.5);
  expect((await resultJson(page)).config.surface.radius).toBe(22.5);
  await expect(page.locator('#error')).toBeHidden();

  before = await runs(page);
  await typeInto(page, 'Radius (µm)', '1,234.5');
  await expect(page.locator('#error')).toContainText('Radius (µm): "1,234.5" has both a comma and a point');
  await expect(page.getByLabel('Radius (µm)', { exact: true })).toHaveAttribute('aria-invalid', 'true');
  await page.waitForTimeout(800);
  expect(await runs(page)).toBe(before);
  expect(urlConfig(page).surface.radius).toBe(22.5);

  // The number box beside a slider reads a comma too: surface ratio "2,5".
  before = await runs(page);
  await typeInto(page, 'Surface ratio R_outer / R_inner', '2,5');
  await waitForRun(page, before);
  expect(urlConfig(page).sheet.surfaceRatio).toBe(2.5);
  await expect(page.locator('input[name="sheet.surfaceRatio"]')).toHaveValue('2.5');
});

test('every slider has a number box beside it that takes any valid value (thickness 12.5 µm beyond a step of 1)', async ({ page }) => {
  await page.goto(linkTo({ ...TUBE, sheet: { surfaceRatio: null, thickness: 10 } }));
  await waitForRun(page);
  const sliders = page.locator('#controls .field-range:not([hidden])');
  expect(await sliders.count()).toBeGreaterThan(0);
  for (const row of await sliders.all()) {
    await expect(row.locator('input[type="range"]')).toHaveCount(1);
    await expect(row.locator('input.number-box')).toHaveCount(1);
  }
  const box = page.getByLabel('Thickness (µm)', { exact: true });
  await expect(box).toHaveValue('10');
  const before = await runs(page);
  await typeInto(page, 'Thickness (µm)', '12,5');
  await waitForRun(page, before);
  expect(urlConfig(page).sheet.thickness).toBe(12.5);
  expect((await resultJson(page)).config.sheet.thickness).toBe(12.5);
  // Beyond the slider's end: the box takes it, nothing is clamped.
  const max = Number(await page.locator('input[name="sheet.thickness"]').getAttribute('max'));
  const after = await runs(page);
  await typeInto(page, 'Thickness (µm)', String(max + 50));
  await waitForRun(page, after);
  expect(urlConfig(page).sheet.thickness).toBe(max + 50);
  await expect(box).toHaveValue(String(max + 50));
});

test('a refused inward thickness (19 µm) keeps the 17 µm result marked stale, and says what to change in µm', async ({ page }) => {
  const inward = {
    ...TUBE,
    surface: { kind: 'tube', radius: 20, length: 512 },
    resolution: null,
    sheet: { direction: 'inward', surfaceRatio: null, thickness: 17 },
  };
  await page.goto(linkTo(inward));
  await waitForRun(page);
  await expect(page.locator('body')).toHaveAttribute('data-stale', 'false');
  await expect(page.locator('#stale-note')).toBeHidden();
  const shown = await drawn(page);
  const before = await runs(page);
  await typeInto(page, 'Thickness (µm)', '19');
  const error = page.locator('#error');
  await expect(error).toBeVisible();
  const main = error.locator('.error-main');
  await expect(main).toContainText('Thickness 19 µm inward leaves the inner surface of this tube (radius 20 µm) a radius of only 1 µm');
  await expect(main).toContainText('Use a thickness of at most');
  expect(await main.textContent()).not.toMatch(/texel|resolution/i);
  await expect(error.locator('.error-details')).toContainText('texels');
  // The 17 µm result stays, marked stale, beside a form reading 19.
  await expect(page.locator('body')).toHaveAttribute('data-stale', 'true');
  const note = page.locator('#stale-note');
  await expect(note).toBeVisible();
  await expect(note).toContainText('this result is for Thickness 17 µm; the form says Thickness 19 µm; the new values were not run');
  expect(await drawn(page)).toBe(shown);
  expect(await runs(page)).toBe(before);
  expect(urlConfig(page).sheet.thickness).toBe(17);
  await expect(page).toHaveScreenshot('stale-result.png', {
    clip: (await page.locator('section.results').boundingBox())!,
    mask: [page.locator('#run-info'), page.locator('#summary')],
  });
  // A thickness that fits runs, and the mark goes.
  await typeInto(page, 'Thickness (µm)', '16,5');
  await waitForRun(page, before);
  await expect(page.locator('body')).toHaveAttribute('data-stale', 'false');
  await expect(note).toBeHidden();
  await expect(error).toBeHidden();
});

test('smaller items: ratio <-> thickness converts the wall; the cells around a tube are said; won/lost name cells, not counts', async ({ page }) => {
  await page.goto(linkTo({ ...TUBE, sheet: { surfaceRatio: 1.5 } }));
  await waitForRun(page);
  // 40 cells on a 2π·20 x 256 µm tube.
  const note = page.locator('[data-path="surface.length"] .field-note');
  await expect(note).toContainText('40 cells of about');
  await expect(note).toContainText('cells around the tube (2π·radius = 125.7 µm)');
  let before = await runs(page);
  await page.getByLabel('Set the other surface by').selectOption('thickness');
  await waitForRun(page, before);
  // s = 1.5 outward on R = 20 µm: a 10 µm wall.
  expect(urlConfig(page).sheet).toMatchObject({ surfaceRatio: null, thickness: 10 });
  await expect(page.getByLabel('Thickness (µm)', { exact: true })).toHaveValue('10');
  before = await runs(page);
  await typeInto(page, 'Thickness (µm)', '30');
  await waitForRun(page, before);
  before = await runs(page);
  await page.getByLabel('Set the other surface by').selectOption('ratio');
  await waitForRun(page, before);
  expect(urlConfig(page).sheet).toMatchObject({ surfaceRatio: 2.5, thickness: 0 });

  await page.locator('#cell-id').fill('3');
  await page.locator('#cell-id').press('Enter');
  const info = page.locator('#cell-info');
  await expect(info).toContainText(
    /Neighbours won from basal to apical: (none|cell #\d+|cells #\d+(, #\d+)* \(\d+\)); lost: (none|cell #\d+|cells #\d+(, #\d+)* \(\d+\))/,
  );
});

test('closed surfaces: a mesh thickness slider follows the mesh geometry; a typed thickness is never clamped; cells far too small are said', async ({
  page,
}) => {
  const MESH = {
    surface: { kind: 'mesh', src: '/meshes/egg-chamber.ply', scale: 1 },
    resolution: 32,
    cells: 40,
    seed: 1,
    lloyd: { maxIterations: 1 },
    sheet: { thickness: 0.1 },
  };
  await page.goto(linkTo({ ...MESH, surface: { ...MESH.surface, scale: 50 }, sheet: { thickness: 5 } }));
  await waitForRun(page);
  // The slider's end from the mesh's size (equivalent radius of its area), not its scale (50).
  const area = Number(/area ([\d.]+) µm²/.exec((await page.locator('#run-info').textContent()) ?? '')![1]);
  const slider = page.locator('input[name="sheet.thickness"]');
  await expect(slider).toHaveAttribute('max', String(Math.ceil(Math.sqrt(area / (4 * Math.PI)))));
  const before = await runs(page);
  await typeInto(page, 'Thickness (µm)', '15');
  await waitForRun(page, before);
  expect(urlConfig(page).sheet.thickness).toBe(15);
  await expect(page.getByLabel('Thickness (µm)', { exact: true })).toHaveValue('15');

  // 100,000 cells on a 25 µm sphere: 0.28 µm across, said at once.
  await page.goto(linkTo({ surface: { kind: 'sphere', radius: 25 }, cells: 100000, lloyd: { maxIterations: 1 }, sheet: { thickness: 2 } }));
  await expect(page.locator('#status')).toContainText('100000 cells on 7850 µm² are about 0.28 µm across', { timeout: 30_000 });
  await page.locator('#cancel').click();
});

test('a value filled in without Enter runs once typing pauses', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const before = await runs(page);
  await page.getByLabel('Radius (µm)', { exact: true }).fill('24,5');
  await waitForRun(page, before);
  expect(urlConfig(page).surface.radius).toBe(24.5);
});

test("the sweep's vary list says when a mode switch changes its field; a loaded sweep shows its spec in the form", async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const field = page.locator('[name="sweep-field"]');
  await page.locator('[name="sweep-from"]').click();
  await expect(field).toHaveValue('sheet.surfaceRatio');
  const before = await runs(page);
  await page.getByLabel('Set the other surface by').selectOption('thickness');
  await waitForRun(page, before);
  await page.locator('[name="sweep-from"]').click();
  await expect(field).toHaveValue('sheet.thickness');
  await expect(page.locator('[data-sweep="status"]')).toHaveText(
    'vary: Surface ratio R_outer / R_inner is not a field of this configuration now; the sweep varies Thickness instead.',
  );

  // A sweep, its files, then a fresh page loads them: the form shows the loaded spec.
  await page.locator('[name="sweep-from"]').fill('2');
  await page.locator('[name="sweep-to"]').fill('6');
  await page.locator('[name="sweep-steps"]').fill('3');
  await page.locator('[data-sweep="run"]').click();
  await page.locator('#sweep[data-done="3"]').waitFor({ timeout: 120_000 });
  const save = async (name: string) => {
    const [file] = await Promise.all([page.waitForEvent('download'), page.locator(`[data-sweep="${name}"]`).click()]);
    const path = `${await file.path()}-${file.suggestedFilename()}`;
    await file.saveAs(path);
    return path;
  };
  const files = [await save('spec'), await save('runs-csv')];
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  await page.locator('[name="sweep-load"]').setInputFiles(files);
  await expect(page.locator('[data-sweep="status"]')).toContainText('Loaded a sweep of 3 runs');
  await expect(field).toHaveValue('sheet.thickness');
  await expect(page.locator('[name="sweep-from"]')).toHaveValue('2');
  await expect(page.locator('[name="sweep-to"]')).toHaveValue('6');
  await expect(page.locator('[name="sweep-steps"]')).toHaveValue('3');
  await expect(page.locator('[name="sweep-realizations"]')).toHaveValue('1');
  // A file holding no spec is refused; the sweep loaded stays.
  await page.locator('[name="sweep-load"]').setInputFiles({ name: 'sweep.json', mimeType: 'application/json', buffer: Buffer.from('null') });
  await expect(page.locator('#error')).toContainText('sweep.json: holds no sweep spec (got null)');
  await expect(page.locator('#sweep')).toHaveAttribute('data-done', '3');
  await expect(page.locator('[name="sweep-to"]')).toHaveValue('6');
  // A row of another configuration (its cells edited) is set aside at load: not drawn, not
  // counted, and Resume is offered to compute it again.
  const [header, ...rows] = readFileSync(files[1], 'utf8').trimEnd().split('\n');
  const cellsColumn = header.split(',').indexOf('cells');
  const edited = rows.map((row, k) =>
    k === 1
      ? row
          .split(',')
          .map((cell, c) => (c === cellsColumn ? String(Number(cell) + 1) : cell))
          .join(',')
      : row,
  );
  const foreign = `${files[1]}-foreign.csv`;
  writeFileSync(foreign, [header, ...edited].join('\n') + '\n');
  await page.locator('[name="sweep-load"]').setInputFiles([files[0], foreign]);
  await expect(page.locator('[data-sweep="status"]')).toContainText('Loaded a sweep of 3 runs with 2 valid rows');
  await expect(page.locator('[data-sweep="status"]')).toContainText('1 rows do not fit this spec and are not drawn');
  await expect(page.locator('#sweep')).toHaveAttribute('data-done', '2');
  await expect(page.locator('[data-sweep="resume"]')).toBeEnabled();
});

test('a mesh missing on the server is said to be missing, not "not a PLY"', async ({ page }) => {
  await page.goto(
    linkTo({
      surface: { kind: 'mesh', src: '/meshes/no-such-mesh.ply', scale: 50 },
      resolution: 32,
      cells: 40,
      lloyd: { maxIterations: 1 },
      sheet: { thickness: 5 },
    }),
  );
  // The link's own configuration: said in the link's alert.
  const alert = page.locator('#link-alert');
  await expect(alert).toContainText('cannot fetch "/meshes/no-such-mesh.ply" (not found', { timeout: 60_000 });
  expect(await alert.textContent()).not.toMatch(/not a PLY/i);
});

test("an uploaded mesh does not keep the sample's scale: its coordinates are taken as µm", async ({ page }) => {
  await page.goto(
    linkTo({
      surface: { kind: 'mesh', src: '/meshes/egg-chamber.ply', scale: 50 },
      resolution: 32,
      cells: 40,
      lloyd: { maxIterations: 1 },
      sheet: { thickness: 0.2 },
    }),
  );
  await waitForRun(page);
  const before = await runs(page);
  await page.locator('input[name="surface.src"]').setInputFiles('public/meshes/organoid.ply');
  await waitForRun(page, before);
  expect(urlConfig(page).surface).toMatchObject({ src: 'organoid.ply', scale: 1 });
  await expect(page.locator('input[name="surface.scale"]')).toHaveValue('1');
});

test('uploading the file a link asked for runs it, and the error goes', async ({ page }) => {
  await page.goto(
    linkTo({ surface: { kind: 'mesh', src: 'my-organoid.ply', scale: 50 }, resolution: 32, cells: 40, lloyd: { maxIterations: 1 }, sheet: { thickness: 5 } }),
  );
  // The link's own configuration: said in the link's alert; it goes once the file runs.
  await expect(page.locator('#link-alert')).toContainText('"my-organoid.ply" is a file uploaded from a computer', { timeout: 60_000 });
  const before = await runs(page);
  await page
    .locator('input[name="surface.src"]')
    .setInputFiles({ name: 'my-organoid.ply', mimeType: 'application/octet-stream', buffer: readFileSync('public/meshes/organoid.ply') });
  await waitForRun(page, before);
  await expect(page.locator('#error')).toBeHidden();
  await expect(page.locator('#link-alert')).toBeHidden();
  await expect(page.locator('#run-info')).toContainText('my-organoid.ply (2562 vertices');
});
