import { readFileSync } from 'node:fs';
import { expect, test } from '@playwright/test';
import { openElementExample, REMOTE_MESH } from './elementHelpers';

/**
 * `<tissue-sheet>` as untrusted input (issue 19) and as a trustworthy report (issue 14): the
 * `result` event says its method and why a 0 is one by construction; a `src` on another origin
 * is named and requested only after the click; a run over the page budget is refused before
 * anything is allocated. Tiny runs (≤ 80 cells).
 */

test('the result event carries the method and the by-construction reason', async ({ page }) => {
  await openElementExample(page, { waitForRuns: false });
  const details = await page.evaluate(async () => {
    const run = async (attributes: Record<string, string>) => {
      const element = document.createElement('tissue-sheet');
      element.setAttribute('manual', '');
      for (const [k, v] of Object.entries({ cells: '60', iterations: '2', resolution: '128', ...attributes })) element.setAttribute(k, v);
      document.body.append(element);
      const detail = new Promise<{ method: string; percentScutoids: number; byConstruction?: string }>((resolve) =>
        element.addEventListener('result', (e) => resolve(e.detail), { once: true }),
      );
      await element.run();
      const d = await detail;
      const status = element.shadowRoot!.querySelector('.status')!.textContent;
      element.remove();
      return { method: d.method, percent: d.percentScutoids, byConstruction: d.byConstruction ?? null, status };
    };
    return { tube: await run({ 'surface-ratio': '2' }), flat: await run({ 'surface-ratio': '1' }) };
  });
  expect(details.tube.method).toBe('exact');
  expect(details.tube.byConstruction).toBeNull();
  expect(details.flat.percent).toBe(0);
  expect(details.flat.byConstruction).toContain('s = 1');
  expect(details.flat.status).toContain('0 by construction');
});

test('a src on another origin is asked about and fetched only after the click', async ({ page }) => {
  let foreign = 0;
  const ply = readFileSync('public/meshes/egg-chamber.ply');
  await page.route(
    (url) => url.hostname === 'lab.example',
    (route) => {
      foreign += 1;
      return route.fulfill({ status: 200, body: ply, headers: { 'access-control-allow-origin': '*' } });
    },
  );
  await openElementExample(page, { waitForRuns: false });
  await page.evaluate((attributes) => {
    const element = document.createElement('tissue-sheet');
    for (const [name, value] of Object.entries(attributes)) element.setAttribute(name, value);
    element.addEventListener('result', () => (element.dataset.result = 'yes'));
    document.body.append(element);
  }, REMOTE_MESH);
  const ask = page.locator('#remote').locator('.ask');
  await expect(ask).toBeVisible();
  await expect(ask).toContainText('This element asks to load a mesh, /shared/egg.ply, from lab.example');
  await page.waitForTimeout(1500);
  expect(foreign).toBe(0);
  await ask.getByRole('button', { name: 'Load /shared/egg.ply from lab.example' }).click();
  await expect(page.locator('#remote')).toHaveAttribute('data-result', 'yes', { timeout: 120_000 });
  expect(foreign).toBe(1);
});

test('a run over the page budget is refused at once, naming the field and the limit', async ({ page }) => {
  await openElementExample(page, { waitForRuns: false });
  const outcome = await page.evaluate(async () => {
    const element = document.createElement('tissue-sheet');
    element.setAttribute('manual', '');
    element.setAttribute('surface', 'plane');
    element.setAttribute('resolution', '8192');
    element.setAttribute('iterations', '5000');
    document.body.append(element);
    const errors: { field?: string; message: string }[] = [];
    element.addEventListener('error', (e) => errors.push(e.detail));
    const started = performance.now();
    const failed = await element.run().then(
      () => 'ran',
      (e: Error) => e.name,
    );
    return { failed, errors, ms: performance.now() - started };
  });
  expect(outcome.failed).toBe('ConfigError');
  expect(outcome.errors[0].field).toBe('resolution');
  expect(outcome.errors[0].message).toContain('above the limit');
  expect(outcome.ms).toBeLessThan(2000);
});
