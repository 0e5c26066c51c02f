import type { Page } from '@playwright/test';

/**
 * Opens examples/element.html (two `<tissue-sheet>` elements that run on their own) and, unless
 * told not to, waits until every element on it has drawn its first result (`data-done`).
 */
export async function openElementExample(page: Page, options: { waitForRuns?: boolean } = {}): Promise<void> {
  await page.goto('/examples/element.html');
  if (options.waitForRuns === false) return;
  await page.waitForFunction(() => [...document.querySelectorAll('tissue-sheet')].every((e) => (e as HTMLElement).dataset.done), null, {
    timeout: 120_000,
  });
}

/** A small mesh element whose `src` is on another origin (lab.example): it asks before loading it. */
export const REMOTE_MESH: Record<string, string> = {
  id: 'remote',
  surface: 'mesh',
  src: 'https://lab.example/shared/egg.ply',
  cells: '40',
  iterations: '1',
  resolution: '24',
};
