import { expect, test } from '@playwright/test';
import { openElementExample, REMOTE_MESH } from './elementHelpers';

/**
 * Issue 26, embedding: the element fires `waiting` while it waits for permission to load a
 * foreign source, and the question goes once an unrelated configuration runs; a misspelled
 * attribute is said (a `warning` event with a suggestion), never ignored silently; an empty or
 * decimal-comma attribute is read in words; reading `config` works; the status line is under
 * the 3D view, not over it.
 */

test('waiting event; the question goes with a later unrelated run', async ({ page }) => {
  await page.route(
    (url) => url.hostname === 'lab.example',
    (route) => route.abort(),
  );
  await openElementExample(page, { waitForRuns: false });
  const waiting = await page.evaluate(
    async (attributes) => {
      const element = document.createElement('tissue-sheet');
      for (const [name, value] of Object.entries(attributes)) element.setAttribute(name, value);
      const event = new Promise<unknown>((resolve) => element.addEventListener('waiting', (e) => resolve((e as CustomEvent).detail), { once: true }));
      document.body.append(element);
      return event;
    },
    { ...REMOTE_MESH, realizations: '1' },
  );
  expect(waiting).toEqual({ sources: [{ path: '/shared/egg.ply', host: 'lab.example' }] });
  const ask = page.locator('#remote').locator('.ask');
  await expect(ask).toBeVisible();
  // An unrelated configuration (a tube) runs: the question about the mesh goes.
  await page.evaluate(async () => {
    const element = document.getElementById('remote')!;
    const done = new Promise((resolve) => element.addEventListener('result', resolve, { once: true }));
    element.setAttribute('surface', 'tube');
    element.removeAttribute('src');
    element.setAttribute('resolution', '128');
    await done;
  });
  await expect(ask).toBeHidden();
});

test('a misspelled attribute is said with a suggestion; "22,5" is 22.5; an empty attribute is named; the status is under the view', async ({ page }) => {
  await openElementExample(page, { waitForRuns: false });
  const out = await page.evaluate(async () => {
    const element = document.createElement('tissue-sheet');
    element.id = 'typo';
    element.setAttribute('cels', '50');
    element.setAttribute('radius', '22,5');
    element.setAttribute('iterations', '1');
    element.setAttribute('realizations', '1');
    const warnings: unknown[] = [];
    element.addEventListener('warning', (e) => warnings.push((e as CustomEvent).detail));
    const result = new Promise<{ radius: number }>((resolve) =>
      element.addEventListener('result', (e) => resolve((e as CustomEvent).detail.result.config.surface), { once: true }),
    );
    document.body.append(element);
    const surface = await result;
    return { warnings, radius: surface.radius, config: (element as unknown as { config: { surface: { radius: number } } }).config.surface.radius };
  });
  expect(out.warnings).toEqual([{ message: 'unknown attribute "cels" ignored (did you mean "cells"?)', attribute: 'cels', suggestion: 'cells' }]);
  expect(out.radius).toBe(22.5);
  expect(out.config).toBe(22.5);
  const status = page.locator('#typo').locator('.status');
  await expect(status).toContainText('unknown attribute "cels" ignored');
  const view = await page.locator('#typo').locator('canvas').boundingBox();
  const line = await status.boundingBox();
  expect(line!.y).toBeGreaterThanOrEqual(view!.y + view!.height - 1);

  const error = await page.evaluate(async () => {
    const element = document.getElementById('typo')!;
    const failed = new Promise<{ message: string }>((resolve) =>
      element.addEventListener('error', (e) => resolve((e as unknown as CustomEvent).detail), { once: true }),
    );
    element.setAttribute('cells', '');
    const message = (await failed).message;
    // Reading config does not throw while an attribute is invalid; configError says why.
    const el = element as unknown as { config: { surface: { radius: number } }; configError: string | null };
    return { message, radius: el.config.surface.radius, configError: el.configError };
  });
  expect(error).toEqual({
    message: 'cells: the attribute is empty; give a number or remove it',
    radius: 22.5,
    configError: 'cells: the attribute is empty; give a number or remove it',
  });
});
