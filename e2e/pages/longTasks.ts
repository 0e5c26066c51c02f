/**
 * The page's long tasks (over 50 ms, the browser's own threshold: "no main-thread task over
 * 50 ms" is the project's rule for the page), for the e2e tests and their test pages alike.
 * `observeLongTasks` runs in the page: a test page imports it, a spec installs it before the
 * page's own scripts with `installLongTaskObserver` (it is self-contained for that: Playwright
 * sends its source).
 */
import type { Page } from '@playwright/test';

/** Starts collecting the durations (ms) of the page's long tasks into `window.longTasks`, and returns that array. */
export function observeLongTasks(): number[] {
  const w = window as unknown as { longTasks?: number[] };
  const longTasks = (w.longTasks ??= []);
  new PerformanceObserver((list) => list.getEntries().forEach((entry) => longTasks.push(entry.duration))).observe({ type: 'longtask' });
  return longTasks;
}

/** Long tasks are collected from the page's first script on, in every page `page` opens. */
export async function installLongTaskObserver(page: Page): Promise<void> {
  await page.addInitScript(observeLongTasks);
}

/** The long tasks (ms) since the last call, taken from the page. */
export function takeLongTasks(page: Page): Promise<number[]> {
  return page.evaluate(() => (window as unknown as { longTasks: number[] }).longTasks.splice(0));
}
