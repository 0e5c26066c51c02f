import type { Page } from '@playwright/test';

/** How many runs the app has finished (the body's data-runs). */
export async function runs(page: Page): Promise<number> {
  return Number((await page.locator('body').getAttribute('data-runs')) ?? 0);
}

/** Waits until the page has finished more than `after` runs and is idle. */
export async function waitForRun(page: Page, after = 0): Promise<void> {
  await page.waitForFunction(
    (after) => document.body.dataset.state === 'done' && Number(document.body.dataset.runs ?? 0) > after,
    after,
    { timeout: 120_000 },
  );
}
