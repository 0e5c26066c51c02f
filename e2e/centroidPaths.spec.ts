import { expect, test } from '@playwright/test';

interface PathDifference {
  worstCentroid: number;
  worstEnergy: number;
}
/** What the test page's compareCentroidPaths returns: blend against gather and readback. */
interface PathComparison {
  capabilities: { floatBlend: boolean };
  emptyCells: number;
  gather: PathDifference;
  readback: PathDifference;
}

test.describe('centroid paths in Chromium', () => {
  test('additive-blend, gather and readback paths give the same centroids', async ({ page }) => {
    await page.goto('/e2e/pages/engine.html');
    await expect(page).toHaveTitle('ready');
    const cases = [
      { grid: { width: 256, height: 192, texelX: 1, texelY: 1, periodicX: false, periodicY: false }, count: 150, weighted: false },
      { grid: { width: 128, height: 384, texelX: 1.02, texelY: 1, periodicX: true, periodicY: false }, count: 60, weighted: true },
    ];
    for (const { grid, count, weighted } of cases) {
      const result = await page.evaluate(
        ({ grid, count, weighted }) =>
          (window as unknown as { tissueSheetTest: { compareCentroidPaths: (...args: unknown[]) => PathComparison } }).tissueSheetTest.compareCentroidPaths(
            grid,
            count,
            3,
            weighted,
          ),
        { grid, count, weighted },
      );
      expect(result.capabilities.floatBlend).toBe(true);
      expect(result.emptyCells).toBe(0);
      for (const path of ['gather', 'readback'] as const) {
        const { worstCentroid, worstEnergy } = result[path];
        console.log(
          `${grid.width}x${grid.height}, ${count} sites, blend vs ${path}: worst centroid difference ${worstCentroid.toExponential(2)} texel, energy ${worstEnergy.toExponential(2)}`,
        );
        expect(worstCentroid).toBeLessThanOrEqual(1e-3);
        expect(worstEnergy).toBeLessThanOrEqual(1e-4);
      }
    }
  });
});
