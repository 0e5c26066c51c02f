import type { Page } from '@playwright/test';

/** How many runs the app has finished (the body's data-runs). */
export async function runs(page: Page): Promise<number> {
  return Number((await page.locator('body').getAttribute('data-runs')) ?? 0);
}

/** Waits until the page has finished more than `after` runs and is idle. */
export async function waitForRun(page: Page, after = 0): Promise<void> {
  await page.waitForFunction((after) => document.body.dataset.state === 'done' && Number(document.body.dataset.runs ?? 0) > after, after, { timeout: 120_000 });
}

/** Runs a sweep of `field` from..to in `steps` points in the page and waits until it is done. */
export async function runSweep(page: Page, field: string, from: number, to: number, steps: number): Promise<void> {
  await page.locator('[name="sweep-field"]').selectOption(field);
  await page.locator('[name="sweep-from"]').fill(String(from));
  await page.locator('[name="sweep-to"]').fill(String(to));
  await page.locator('[name="sweep-steps"]').fill(String(steps));
  await page.locator('[data-sweep="run"]').click();
  await page.locator(`#sweep[data-done="${steps}"]`).waitFor({ timeout: 120_000 });
}

/** White pixels (the picked cell's fill) on each unrolled canvas. */
export function unrolledWhitePixels(page: Page): Promise<number[]> {
  return page.evaluate(() =>
    [...document.querySelectorAll<HTMLCanvasElement>('#unrolled canvas')].map((c) => {
      const d = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
      let count = 0;
      for (let k = 0; k < d.length; k += 4) if (d[k] === 255 && d[k + 1] === 255 && d[k + 2] === 255) count++;
      return count;
    }),
  );
}
