import { expect, test } from '@playwright/test';
import { linkTo, runSweep, smallTube, waitForRun } from './appHelpers';

/** The Flintstones law (Gómez-Gálvez et al. 2022) fitted and drawn after a sweep over the surface ratio. */
test('a sweep over the surface ratio draws the Flintstones fit with its parameters', async ({ page }) => {
  const small = smallTube(2, 3, 1.5);

  await page.goto(linkTo(small));
  await waitForRun(page);
  await runSweep(page, 'sheet.surfaceRatio', 1, 6, 6);
  const chart = page.locator('#chart-flintstones');
  await expect(chart).toBeVisible();
  await expect(chart).toHaveAttribute('data-fits', '1');
  // Voronoi k = Lloyd iterations + 1; the parameters are named with their standard errors, or
  // the fit says why it is not determined.
  await expect(chart.locator('li')).toHaveCount(1);
  await expect(chart.locator('li')).toContainText(/Voronoi 4: (Nmax [\d.]+.*c [\d.e+-]+.*R²|no fit)/);
  await expect(chart.locator('canvas')).toHaveCount(1);

  // A sweep over another field draws none.
  await runSweep(page, 'cells', 40, 60, 2);
  await expect(chart).toBeHidden();
});
