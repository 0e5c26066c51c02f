import { expect, test } from '@playwright/test';

type WorkerTest = Record<string, (input: unknown) => Promise<Record<string, unknown>>>;
const call =
  (name: string, input: unknown) =>
  async ({ page }: { page: import('@playwright/test').Page }) =>
    page.evaluate(([name, input]) => (window as unknown as { tissueSheetWorkerTest: WorkerTest }).tissueSheetWorkerTest[name as string](input), [
      name,
      input,
    ] as const);

const tube = {
  surface: { kind: 'tube', radius: 40, length: 300 },
  resolution: 256,
  cells: 60,
  seed: 5,
  lloyd: { maxIterations: 4 },
  sheet: { surfaceRatio: 1.8, layers: 1 },
};
const sphere = { surface: { kind: 'sphere', radius: 40 }, resolution: 48, cells: 80, seed: 2, lloyd: { maxIterations: 3 }, sheet: { thickness: 8 } };

test.describe('the pipeline in a Web Worker', () => {
  test.beforeEach(async ({ page }) => {
    await page.goto('/e2e/pages/worker.html');
    await expect(page).toHaveTitle('ready');
  });

  for (const [name, input] of [
    ['tube', tube],
    ['sphere', sphere],
  ] as const) {
    test(`${name}: the worker's result equals the page's, iteration reports arrive, no long task on the page`, async ({ page }) => {
      const result = await call('compareWorkerAndPage', input)({ page });
      console.log(`${name}: computed in the ${JSON.stringify(result.site)}; page long tasks during the run: ${JSON.stringify(result.longTasks)}`);
      expect(result.site).toEqual({ where: 'worker' });
      expect(result.same).toBe(true);
      expect(result.labelsSame).toBe(true);
      expect((result.iterations as number[]).length).toBe(input.lloyd.maxIterations);
      // The page only posts and receives messages: nothing near the 50 ms budget.
      expect(Math.max(0, ...(result.longTasks as number[]))).toBeLessThan(50);
    });
  }

  test('without a worker, runs fall back to the page and say why', async ({ page }) => {
    const result = await call('fallBack', tube)({ page });
    expect(result.cells).toBe(60);
    expect(result.site).toMatchObject({ where: 'page' });
    expect(String((result.site as { reason: string }).reason)).toMatch(/no workers in this test/);
  });

  test('a result-only run (views: false) returns the same result without label images', async ({ page }) => {
    const result = await call('resultOnly', tube)({ page });
    expect(result.same).toBe(true);
    expect(result.images).toBe(0);
    expect(result.fullImages).toBe(3);
  });

  test('a cancelled run rejects with AbortError and the worker serves the next run', async ({ page }) => {
    const result = await call('cancelThenRun', tube)({ page });
    expect(result.firstError).toBe('AbortError');
    expect(result.cells).toBe(60);
  });
});
