import { expect, test, type Page } from '@playwright/test';

/**
 * Issue 27: a `surface-ratio` or `thickness` change on a converged <tissue-sheet> takes the
 * app's slider path (the worker's converged seeded surfaces reused, draft pictures, then the
 * full ones): no main-thread task over 50 ms from the change until after the full pictures, and
 * the result event's numbers (and its headline over realizations) are those of fresh runs of the
 * same configuration. The speed itself is measured by bench/elementRatio.ts, not here.
 */

interface Change {
  ms: number;
  longTasks: number[];
  config: { seed: number } & Record<string, unknown>;
  numbers: unknown;
  headline: { realizations: number; realizationSeeds: number[]; realizationValues: (number | null)[]; percentScutoids: number | null };
}

const BASE = { surface: 'tube', cells: '60', seed: '3', iterations: '6', realizations: '3' };

async function open(page: Page): Promise<void> {
  await page.goto('/e2e/pages/elementChange.html');
  await page.waitForFunction(() => document.title === 'ready');
}

async function check(page: Page, attributes: Record<string, string>, attribute: string, value: string): Promise<void> {
  await open(page);
  const changed = await page.evaluate(
    (input) => (window as unknown as { elementChange: { change(i: unknown): Promise<Change> } }).elementChange.change(input),
    { attributes, attribute, value, settleMs: 1500 },
  );
  const seeds = changed.headline.realizationSeeds;
  expect(changed.headline.realizations).toBe(3);
  expect(seeds).toHaveLength(3);
  const fresh = await page.evaluate(
    (input) =>
      (window as unknown as { elementChange: { fresh(i: unknown): Promise<{ numbers: unknown; percent: number | null }[]> } }).elementChange.fresh(input),
    { config: changed.config, seeds },
  );
  // Realization 1 is the result itself; every realization's value is its fresh run's.
  expect(changed.numbers).toEqual(fresh[0].numbers);
  expect(changed.headline.realizationValues).toEqual(fresh.map((f) => f.percent));
  const mean = fresh.reduce((sum, f) => sum + (f.percent ?? 0), 0) / fresh.length;
  expect(changed.headline.percentScutoids).toBeCloseTo(mean, 9);
  expect(
    changed.longTasks.filter((ms) => ms > 50),
    `long tasks ${changed.longTasks.join(', ')} ms`,
  ).toEqual([]);
}

test("a surface-ratio change: the fresh run's numbers, no main-thread task over 50 ms", async ({ page }) => {
  await check(page, { ...BASE, 'surface-ratio': '1.5' }, 'surface-ratio', '2.75');
});

test("a thickness change: the fresh run's numbers, no main-thread task over 50 ms", async ({ page }) => {
  await check(page, { ...BASE, thickness: '4' }, 'thickness', '11');
});
