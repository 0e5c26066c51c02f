import { expect, test, type Page } from '@playwright/test';
import { downloadExport, linkTo, runs, smallTube, waitForRun } from './appHelpers';
import { cliRun } from './cli';
import { readPngText } from '../tests/app/pngRead';

/**
 * Issue 26, numbers a paper can carry: the headline is a mean over realizations with its 95 %
 * CI and n, the drawn realization one of them; the exports, the element and the CLI carry the
 * same. Runs stay tiny (60 cells, resolution 128, 2 Lloyd iterations).
 */

const SMALL = smallTube(3, 2, 2);

async function waitForHeadline(page: Page): Promise<void> {
  await page.waitForFunction(() => document.body.dataset.headline === 'complete', undefined, { timeout: 120_000 });
}

/** Types into a field as a person does: click, select all, type, Enter. */
async function typeInto(page: Page, selector: string, text: string): Promise<void> {
  const field = page.locator(selector);
  await field.click();
  await field.press('ControlOrMeta+a');
  await field.pressSequentially(text);
  await field.press('Enter');
}

test('the headline is the mean over 5 realizations with its 95 % CI and n; realization 1 is the one drawn; exports and the CLI say the same', async ({
  page,
}) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  const number = page.locator('#percent-scutoids');
  // First result at once: realization 1 alone, said so while the others compute.
  await expect(page.locator('#realizations')).toHaveValue('5');
  await waitForHeadline(page);
  await expect(number).toHaveAttribute('data-realizations', '5');
  const mean = Number(await number.getAttribute('data-value'));
  const drawn = Number(await number.getAttribute('data-drawn'));
  const low = Number(await number.getAttribute('data-ci-low'));
  const high = Number(await number.getAttribute('data-ci-high'));
  expect(low).toBeLessThanOrEqual(mean);
  expect(high).toBeGreaterThanOrEqual(mean);
  await expect(number).toHaveText(`${mean.toFixed(1)} %`);
  await expect(page.locator('#headline-ci')).toHaveText(`(mean of n = 5 realizations, 95 % CI ${low.toFixed(1)}–${high.toFixed(1)} %)`);
  await expect(page.locator('#headline-realizations')).toContainText('Mean of 5 realizations, seeds 3–7');
  await expect(page.locator('#headline-realizations')).toContainText(`The cells shown are realization 1 of 5 (seed 3): ${drawn.toFixed(1)} %`);
  await expect(page).toHaveScreenshot('headline-realizations.png', {
    clip: (await page.locator('section.results').boundingBox())!,
    mask: [page.locator('#run-info'), page.locator('#summary')],
  });

  // The result JSON: realization 1's cells and analyses, the headline over the 5.
  const json = JSON.parse((await downloadExport(page, 'json')).text);
  const exact = json.analyses.find((a: { method: string }) => a.method === 'exact');
  expect(exact.summary.percentScutoids).toBe(drawn);
  expect(json.headline.realizations).toBe(5);
  expect(json.headline.percentScutoids).toBe(mean);
  expect(json.headline.ci95).toEqual([low, high]);
  expect(json.headline.realizationSeeds).toEqual([3, 4, 5, 6, 7]);
  expect(json.headline.realizationValues[0]).toBe(drawn);

  // Non-JSON exports carry the same headline, and name the engine that ran (not "auto").
  const csv = (await downloadExport(page, 'cells')).text;
  const headlineLine = `headline: ${mean.toFixed(1)} % scutoids (exact method`;
  expect(csv).toContain(`# ${headlineLine}`);
  expect(csv).toContain(
    `mean of 5 realizations (seeds 3–7), 95 % CI ${low.toFixed(1)}–${high.toFixed(1)} %; realization 1 (seed 3, drawn): ${drawn.toFixed(1)} %`,
  );
  expect(csv).toMatch(/^# engine: exact engine \(engine setting "auto": /m);
  const ply = (await downloadExport(page, 'ply')).text;
  expect(ply).toContain(`comment ${headlineLine}`);
  expect(ply).toContain('comment engine: exact engine');
  const png = readPngText(new Uint8Array((await downloadExport(page, 'png')).bytes));
  expect(JSON.parse(png['tissue-sheet:headline'])).toEqual(json.headline);
  expect(png['tissue-sheet:engine']).toBe('exact');
  expect(png['tissue-sheet:method']).toBe('exact');
  const vtk = (await downloadExport(page, 'vtk')).text.split('\n')[1];
  expect(vtk).toContain(`exact engine, exact adjacency, ${mean.toFixed(1)} % scutoids (mean n=5, 95% CI ${low.toFixed(1)}-${high.toFixed(1)})`);
  const svg = (await downloadExport(page, 'svg')).text;
  expect(svg).toContain(headlineLine);

  // The CLI with the same configuration and n prints the same headline.
  const cli = cliRun<typeof json>(json.config, ['--realizations', '5']).result;
  expect(cli.headline.realizationValues).toEqual(json.headline.realizationValues);
  expect(cli.headline.percentScutoids).toBeCloseTo(mean, 10);
  expect(cli.headline.ci95[0]).toBeCloseTo(low, 10);
});

test('a control raises n (typed as a person types); n = 1 says it is one realization; a bad n is refused in words', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await waitForHeadline(page);
  const number = page.locator('#percent-scutoids');
  const drawn = await number.getAttribute('data-drawn');
  const before = await runs(page);
  await typeInto(page, '#realizations', '8');
  await page.locator('#realizations').blur();
  await expect(number).toHaveAttribute('data-realizations', '8', { timeout: 120_000 });
  await waitForHeadline(page);
  await expect(page.locator('#headline-ci')).toContainText('n = 8');
  await expect(page.locator('#headline-realizations')).toContainText('seeds 3–10');
  // The drawn realization did not change, and nothing was run again for it.
  await expect(number).toHaveAttribute('data-drawn', drawn!);
  expect(await runs(page)).toBe(before);
  const json = JSON.parse((await downloadExport(page, 'json')).text);
  expect(json.headline.realizationSeeds).toEqual([3, 4, 5, 6, 7, 8, 9, 10]);

  await typeInto(page, '#realizations', '1');
  await page.locator('#realizations').blur();
  await expect(number).toHaveAttribute('data-realizations', '1');
  await expect(number).toHaveAttribute('data-value', drawn!);
  await expect(page.locator('#headline-ci')).toHaveText('(one realization, n = 1: no confidence interval)');
  await expect(page.locator('#headline-realizations')).toContainText('One realization (seed 3)');
  const single = JSON.parse((await downloadExport(page, 'json')).text);
  expect(single.headline.realizations).toBe(1);
  expect(single.headline.ci95).toBeNull();
  expect((await downloadExport(page, 'cells')).text).toContain('one realization (seed 3)');

  await typeInto(page, '#realizations', '0');
  await page.locator('#realizations').blur();
  await expect(page.locator('#error')).toContainText('Realizations: must be a whole number of realizations from 1 to 100');
  await expect(page.locator('#realizations')).toHaveAttribute('aria-invalid', 'true');
});

test("the element's result event carries the headline over its realizations attribute", async ({ page }) => {
  await page.goto('/examples/element.html');
  const detail = await page.evaluate(async (config) => {
    const el = document.createElement('tissue-sheet') as HTMLElement & { config: unknown };
    el.setAttribute('manual', '');
    el.setAttribute('realizations', '3');
    el.config = config;
    document.body.append(el);
    const event = new Promise<CustomEvent>((resolve) => el.addEventListener('result', (e) => resolve(e as CustomEvent), { once: true }));
    await (el as unknown as { run(): Promise<unknown> }).run();
    const { headline, percentScutoids } = (await event).detail;
    return { headline, percentScutoids };
  }, SMALL);
  expect(detail.headline.realizations).toBe(3);
  expect(detail.headline.realizationSeeds).toEqual([3, 4, 5]);
  expect(detail.headline.realizationValues[0]).toBe(detail.percentScutoids);
  expect(detail.headline.ci95).toHaveLength(2);
});

test('the address carries n: a link with realizations=3 shows the mean of 3; raising n writes it; reloading keeps it', async ({ page }) => {
  await page.goto(`${linkTo(SMALL)}&realizations=3`);
  await waitForRun(page);
  await expect(page.locator('#realizations')).toHaveValue('3');
  await waitForHeadline(page);
  await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-realizations', '3');
  await typeInto(page, '#realizations', '6');
  await page.locator('#realizations').blur();
  await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-realizations', '6', { timeout: 120_000 });
  expect(new URL(page.url()).searchParams.get('realizations')).toBe('6');
  const mean = await page.locator('#percent-scutoids').getAttribute('data-value');
  await page.reload();
  await waitForRun(page);
  await waitForHeadline(page);
  await expect(page.locator('#realizations')).toHaveValue('6');
  await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-value', mean!);
  // The default n is left out of the address.
  await typeInto(page, '#realizations', '5');
  await page.locator('#realizations').blur();
  await expect.poll(() => new URL(page.url()).searchParams.get('realizations')).toBeNull();
});
