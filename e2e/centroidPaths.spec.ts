import { expect, test } from '@playwright/test';

test.describe('centroid paths in Chromium', () => {
  test('additive-blend and gather paths give the same centroids', async ({ page }) => {
    await page.goto('/e2e/pages/engine.html');
    await expect(page).toHaveTitle('ready');
    const cases = [
      { grid: { width: 256, height: 192, texelX: 1, texelY: 1, periodicX: false, periodicY: false }, count: 150, weighted: false },
      { grid: { width: 128, height: 384, texelX: 1.02, texelY: 1, periodicX: true, periodicY: false }, count: 60, weighted: true },
    ];
    for (const { grid, count, weighted } of cases) {
      const result = await page.evaluate(
        ({ grid, count, weighted }) =>
          (window as unknown as { tissueSheetTest: { compareCentroidPaths: Function } }).tissueSheetTest.compareCentroidPaths(grid, count, 3, weighted),
        { grid, count, weighted },
      );
      console.log(`${grid.width}x${grid.height}, ${count} sites: worst centroid difference ${result.worstCentroid.toExponential(2)} texel, energy ${result.worstEnergy.toExponential(2)}`);
      expect(result.capabilities.floatBlend).toBe(true);
      expect(result.emptyCells).toBe(0);
      expect(result.worstCentroid).toBeLessThanOrEqual(1e-3);
      expect(result.worstEnergy).toBeLessThanOrEqual(1e-4);
    }
  });
});
