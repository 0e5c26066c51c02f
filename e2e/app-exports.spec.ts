import { expect, test } from '@playwright/test';
import { downloadExport, runs, shownElsewhere, shownResult, waitForRun } from './appHelpers';
import { parseCsv } from '../src/core/sweep/csv';

/** Exports parse and match the numbers on screen; the URL (and the saved session) reproduce a run. */

function table(text: string): Record<string, string>[] {
  // Provenance comment lines ("# ...") come first in the per-cell CSV.
  const body = text
    .split(/\r?\n/)
    .filter((line) => !line.startsWith('#'))
    .join('\r\n');
  const [header, ...rows] = parseCsv(body).records;
  return rows.map((r) => Object.fromEntries(header.map((h, k) => [h, r[k]])));
}

test('exports download files that parse and match the on-screen numbers', async ({ page }) => {
  await page.goto('/');
  await waitForRun(page);
  const percent = Number(await page.locator('#percent-scutoids').getAttribute('data-drawn'));
  const scutoidsShown = Number(await page.locator('#summary tr[data-key="scutoids"]').getAttribute('data-value'));
  const validShown = Number(await page.locator('#summary tr[data-key="validCells"]').getAttribute('data-value'));

  const json = await downloadExport(page, 'json');
  expect(json.name).toBe('tissue-sheet-tube-seed1.json');
  const result = JSON.parse(json.text);
  // The headline's analysis: the exact method wherever the result has one (a tube has).
  const method = await page.locator('#percent-scutoids').getAttribute('data-method');
  expect(method).toBe('exact');
  const labels = result.analyses.find((a: { method: string }) => a.method === method);
  expect(labels.summary.percentScutoids).toBe(percent);
  expect(labels.summary.scutoids).toBe(scutoidsShown);
  expect(result.config.sheet.surfaceRatio).toBe(1.5);
  expect(result.cells).toHaveLength(150);

  const cells = table((await downloadExport(page, 'cells')).text);
  expect(cells).toHaveLength(150);
  expect(cells.filter((c) => c.scutoid === '1')).toHaveLength(scutoidsShown);
  expect(cells.filter((c) => c.valid === '1')).toHaveLength(validShown);
  await page.locator('section[aria-labelledby="cells-title"] summary').click();
  const firstRow = await page.locator('#cell-table tbody tr').first().locator('th, td').allTextContents();
  expect(firstRow).toEqual(Object.values(cells[0]));
  for (const cell of cells) {
    const stats = labels.cells[Number(cell.id)];
    expect(Number(cell.sides_basal)).toBe(stats.sides[0]);
    expect(Number(cell.sides_apical)).toBe(stats.sides[1]);
    expect(Number(cell.transitions)).toBe(stats.transitions);
  }

  const ply = await downloadExport(page, 'ply');
  const header = ply.text.slice(0, ply.text.indexOf('end_header'));
  const vertices = Number(/element vertex (\d+)/.exec(header)![1]);
  const faces = Number(/element face (\d+)/.exec(header)![1]);
  expect(faces).toBe(300); // 150 cells on each of 2 surfaces
  const body = ply.text
    .slice(ply.text.indexOf('end_header') + 11)
    .trim()
    .split('\n');
  expect(body).toHaveLength(vertices + faces);
  // Per-vertex cell data: x y z cell surface sides scutoid valid.
  const scutoidCells = new Set(
    body
      .slice(0, vertices)
      .map((l) => l.split(' '))
      .filter((f) => f[6] === '1')
      .map((f) => f[3]),
  );
  expect(scutoidCells.size).toBe(scutoidsShown);

  const png = await downloadExport(page, 'png');
  expect(png.bytes.subarray(1, 4).toString('latin1')).toBe('PNG');
  expect(png.bytes.length).toBeGreaterThan(5000);

  await page.locator('[name="sweep-to"]').fill('2');
  await page.locator('[name="sweep-steps"]').fill('3');
  await page.locator('[data-sweep="run"]').click();
  await expect(page.locator('#sweep')).toHaveAttribute('data-done', '3', { timeout: 120_000 });
  const sweep = table((await downloadExport(page, 'sweep')).text);
  expect(sweep.map((r) => r['sheet.surfaceRatio'])).toEqual(['1', '1.5', '2']);
  // The CLI's runs.csv columns: one % per adjacency method. On this software renderer the
  // engine is the exact one (engine "auto"), so the exact method's columns are the filled ones.
  expect(Number(sweep[0]['exact.percentScutoids_pct'])).toBe(0);
  expect(Number(sweep[2]['exact.percentScutoids_pct'])).toBeGreaterThan(Number(sweep[0]['exact.percentScutoids_pct']));
});

test('a URL round trip reproduces the result, and reopening restores the last session', async ({ page, browser }) => {
  await page.goto('/');
  await waitForRun(page);
  let before = await runs(page);
  await page.getByLabel('Random seed').fill('7');
  await page.getByLabel('Random seed').press('Enter');
  await waitForRun(page, before);
  before = await runs(page);
  await page.getByLabel('Cells', { exact: true }).fill('120');
  await page.getByLabel('Cells', { exact: true }).press('Enter');
  await waitForRun(page, before);
  const link = page.url();
  expect(new URL(link).searchParams.get('config')).toContain('"seed":7');
  await page.locator('section[aria-labelledby="cells-title"] summary').click();
  const shown = await shownResult(page);
  expect(shown.seed).toBe('7');
  // A fresh browser context (no saved session) opening the shared link.
  expect(await shownElsewhere(browser, link)).toEqual(shown);

  // The same context reopening the bare page restores the last session from localStorage.
  await page.goto('/');
  await waitForRun(page);
  await expect(page.getByLabel('Cells', { exact: true })).toHaveValue('120');
  expect(await page.locator('#percent-scutoids').getAttribute('data-drawn')).toBe(shown.percent);
});
