import { readFileSync } from 'node:fs';
import { expect, type Browser, type Page } from '@playwright/test';
import { takeLongTasks } from './pages/longTasks';

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

/** The app's address for a `?config=` link (a string is sent as it is: a malformed link). */
export const linkTo = (config: unknown): string => `/?config=${encodeURIComponent(typeof config === 'string' ? config : JSON.stringify(config))}`;

/**
 * The small tube most app tests run, seconds on SwiftShader: 60 cells at resolution 128 on a
 * tube 256 µm round and 512 µm long; the seed, the Lloyd iterations and the surface ratio vary.
 */
export function smallTube(seed: number, maxIterations: number, surfaceRatio: number) {
  return {
    surface: { kind: 'tube', radius: 256 / (2 * Math.PI), length: 512 },
    resolution: 128,
    cells: 60,
    seed,
    lloyd: { maxIterations },
    sheet: { surfaceRatio },
  };
}

/** Clicks `selector` and reads the file it downloads: its suggested name, bytes and text. */
export async function download(page: Page, selector: string): Promise<{ name: string; bytes: Buffer; text: string }> {
  const [file] = await Promise.all([page.waitForEvent('download'), page.locator(selector).click()]);
  const bytes = readFileSync(await file.path());
  return { name: file.suggestedFilename(), bytes, text: bytes.toString('utf8') };
}

/** The file of the app's export button `key` (its `data-export`). */
export const downloadExport = (page: Page, key: string) => download(page, `[data-export="${key}"]`);

/** What the app shows of its result: the drawn % scutoids, the summary, the cell table and the seed. */
export async function shownResult(page: Page) {
  return {
    percent: await page.locator('#percent-scutoids').getAttribute('data-drawn'),
    summary: await page.locator('#summary').textContent(),
    cells: await page.locator('#cell-table').textContent(),
    seed: await page.getByLabel('Random seed').inputValue(),
  };
}

/** What `link` shows once run in a fresh browser context (no saved session): a link shared with someone else. */
export async function shownElsewhere(browser: Browser, link: string): Promise<Awaited<ReturnType<typeof shownResult>>> {
  const other = await browser.newContext();
  try {
    const shared = await other.newPage();
    await shared.goto(link);
    await waitForRun(shared);
    return await shownResult(shared);
  } finally {
    await other.close();
  }
}

/** Whether a script injected into the page runs (the Content-Security-Policy must stop it). */
export function injectedScriptRuns(page: Page): Promise<boolean> {
  return page.evaluate(async () => {
    const script = document.createElement('script');
    script.textContent = 'window.__injected = true;';
    document.body.append(script);
    await new Promise((r) => setTimeout(r, 100));
    return (window as unknown as { __injected?: boolean }).__injected === true;
  });
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

/** Fails the test if the page had a task over 50 ms since the last take (their durations in the message). */
export async function expectNoLongTasks(page: Page): Promise<void> {
  const tasks = await takeLongTasks(page);
  expect(
    tasks.filter((d) => d > 50),
    `long tasks ${tasks.join(', ')} ms`,
  ).toEqual([]);
}
