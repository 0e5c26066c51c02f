import { expect, test, type Page } from '@playwright/test';
import { linkTo, waitForRun } from './appHelpers';

/**
 * Issue 24: sweeps on closed surfaces other than a sphere, with the default adjacency ("both"),
 * in the page's sweep panel and through `<tissue-sheet>.sweep()`: every run is written with the
 * exact method's columns (the restricted Voronoi diagram) beside the labels method's; a page
 * sweep that fails says so and stops. Small sizes: 24-texel cube faces, 40 cells.
 */

const ELLIPSOID = {
  surface: { kind: 'ellipsoid', a: 44, b: 27, c: 23 },
  resolution: 24,
  cells: 40,
  seed: 3,
  lloyd: { maxIterations: 1 },
  sheet: { thickness: 6 },
};
const MESH = {
  surface: { kind: 'mesh', src: '/meshes/organoid.ply', scale: 40 },
  resolution: 24,
  cells: 40,
  seed: 3,
  lloyd: { maxIterations: 1 },
  sheet: { thickness: 2 },
};

/** The page's sweep panel over `field`, from..to in `steps` points; resolves with the panel's final state. */
async function panelSweep(page: Page, from: number, to: number, steps: number, field = 'sheet.thickness'): Promise<string> {
  await page.locator('[name="sweep-field"]').selectOption(field);
  await page.locator('[name="sweep-from"]').fill(String(from));
  await page.locator('[name="sweep-to"]').fill(String(to));
  await page.locator('[name="sweep-steps"]').fill(String(steps));
  await page.locator('[name="sweep-realizations"]').fill('1');
  await page.locator('[data-sweep="run"]').click();
  await page.waitForFunction(() => ['done', 'error', 'cancelled'].includes(document.querySelector<HTMLElement>('#sweep')?.dataset.state ?? ''), null, {
    timeout: 150_000,
  });
  return (await page.locator('#sweep').getAttribute('data-state')) ?? '';
}

for (const [name, config] of [
  ['an ellipsoid', ELLIPSOID],
  ['a mesh', MESH],
] as const) {
  test(`the page's sweep panel sweeps ${name} with both methods to the end`, async ({ page }) => {
    await page.goto(linkTo(config));
    await waitForRun(page);
    expect(await panelSweep(page, 2, 6, 2)).toBe('done');
    await expect(page.locator('#sweep')).toHaveAttribute('data-done', '2');
    await expect(page.locator('[data-sweep="status"]')).toContainText('Sweep done: 2 runs');
    const [download] = await Promise.all([page.waitForEvent('download'), page.locator('[data-sweep="runs-csv"]').click()]);
    const text = await (await download.createReadStream()).toArray();
    const lines = Buffer.concat(text).toString('utf8').trim().split(/\r?\n/);
    const header = lines[0].split(',');
    expect(lines).toHaveLength(3);
    for (const method of ['labels', 'exact']) {
      const column = header.indexOf(`${method}.percentScutoids_pct`);
      expect(column, method).toBeGreaterThan(0);
      for (const line of lines.slice(1)) expect(Number(line.split(',')[column]), `${method}: ${line}`).toBeGreaterThanOrEqual(0);
    }
  });

  test(`<tissue-sheet>.sweep() sweeps ${name} with both methods`, async ({ page }) => {
    await page.goto('/e2e/pages/interactive.html');
    await expect(page).toHaveTitle('ready');
    const spec = { base: config, vary: { 'sheet.thickness': [2, 5] }, realizations: 1, seed: 4 };
    const result = await page.evaluate(
      (spec) =>
        (
          window as unknown as { tissueSheetInteractive: { sweep(i: unknown): Promise<{ header: string[]; runs: Record<string, string>[] }> } }
        ).tissueSheetInteractive.sweep({ spec }),
      spec,
    );
    expect(result.runs).toHaveLength(2);
    for (const method of ['labels', 'exact']) {
      expect(result.header).toContain(`${method}.percentScutoids`);
      for (const row of result.runs) {
        expect(Number(row[`${method}.percentScutoids`])).toBeGreaterThanOrEqual(0);
        expect(row[`${method}.validCells`]).toBe('40');
      }
    }
  });
}

test('a page sweep refused before its first run, or failing in a run, says so and stops', async ({ page }) => {
  // Inward past the sphere's radius: the second grid point is refused before anything runs.
  await page.goto(
    linkTo({
      surface: { kind: 'sphere', radius: 30 },
      resolution: 24,
      cells: 40,
      seed: 3,
      lloyd: { maxIterations: 1 },
      sheet: { thickness: 5, direction: 'inward' },
    }),
  );
  await waitForRun(page);
  expect(await panelSweep(page, 5, 45, 2)).toBe('error');
  await expect(page.locator('[data-sweep="status"]')).toContainText('Sweep not run: grid point sheet.thickness=45');
  await expect(page.locator('[data-sweep="run"]')).toBeEnabled();

  // A mesh shrunk until the inward offset folds: known only once the mesh is loaded, in the run.
  await page.goto(linkTo({ ...MESH, sheet: { thickness: 2, direction: 'inward' } }));
  await waitForRun(page);
  expect(await panelSweep(page, 40, 2, 2, 'surface.scale')).toBe('error');
  await expect(page.locator('[data-sweep="status"]')).toContainText('Sweep failed after');
  await expect(page.locator('[data-sweep="status"]')).toContainText('radius of curvature');
  await expect(page.locator('#error')).toContainText('Sweep failed: ');
  await expect(page.locator('[data-sweep="run"]')).toBeEnabled();
});
