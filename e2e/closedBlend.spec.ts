import { expect, test } from '@playwright/test';

interface ClosedComparison {
  paths: string[];
  worstCentroid: number;
  worstEnergy: number;
  energies: number[];
  increases: number;
  capabilities: { renderer: string; floatBlend: boolean };
}

// The closed-surface engine's additive-blend centroid path (SwiftShader has EXT_float_blend,
// headless-gl does not) against the readback path on the same labels.
test('closed surfaces: blend and readback centroid paths agree, and blend-path Lloyd never raises the energy', async ({ page }) => {
  await page.goto('/e2e/pages/closed.html');
  await expect(page).toHaveTitle('ready', { timeout: 120_000 });
  const r = (await page.evaluate(() =>
    (window as unknown as { closedTest: { compare(n: number, c: number): unknown } }).closedTest.compare(64, 200),
  )) as ClosedComparison;
  console.log(
    `ellipsoid 80:40:40 µm, n = 64, 200 sites: worst centroid difference ${r.worstCentroid.toExponential(2)} µm, ` +
      `energy ${r.worstEnergy.toExponential(2)}; Lloyd energy ${r.energies[0].toExponential(4)} -> ${r.energies.at(-1)!.toExponential(4)}`,
  );
  expect(r.paths[0]).toBe('blend');
  expect(r.worstCentroid).toBeLessThanOrEqual(1e-3);
  expect(r.worstEnergy).toBeLessThanOrEqual(1e-4);
  expect(r.increases).toBe(0);
});
