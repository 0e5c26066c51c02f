import { deflateSync } from 'node:zlib';
import { expect, test, type Page } from '@playwright/test';
import { downloadExport, linkTo, waitForRun } from './appHelpers';

/**
 * The address and "Copy link" describe the result on screen: its configuration as the form
 * holds it (a default resolution kept null) and its number of realizations, whether typed in
 * #realizations (an invalid value changes neither the screen nor the address) or brought by an
 * opened project or result file. A link's own problems are said as the link's ("This link asks
 * ...", the link alert), whatever the surface. Tiny runs (30 cells, 2 Lloyd iterations).
 */

const TINY = { surface: { kind: 'tube', radius: 20, length: 200 }, cells: 30, seed: 5, lloyd: { maxIterations: 2 }, sheet: { surfaceRatio: 2 } };

const param = (href: string, name: string) => new URL(href).searchParams.get(name);

async function copiedLink(page: Page): Promise<string> {
  await page.locator('#share').click();
  return (await page.locator('#share').getAttribute('data-link'))!;
}

async function setRealizations(page: Page, value: string): Promise<void> {
  await page.locator('#realizations').fill(value);
  await page.locator('#realizations').blur();
}

test('#realizations: an invalid value is refused and leaves the address; a valid one is the address and the link, its error gone', async ({
  page,
  context,
}) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.goto(linkTo(TINY));
  await waitForRun(page);
  const number = page.locator('#percent-scutoids');
  await expect(number).toHaveAttribute('data-realizations', '5', { timeout: 120_000 });
  // A link keeps a default resolution null (chosen from the surface), as the address does.
  expect(JSON.parse(param(await copiedLink(page), 'config')!).resolution ?? null).toBeNull();

  await setRealizations(page, '0');
  await expect(page.locator('#error')).toContainText('Realizations');
  await expect(page.locator('#realizations')).toHaveAttribute('aria-invalid', 'true');
  expect(param(page.url(), 'realizations')).toBeNull(); // the screen still shows n = 5, the default
  await expect(number).toHaveAttribute('data-realizations', '5');

  await setRealizations(page, '3');
  await expect(number).toHaveAttribute('data-realizations', '3', { timeout: 120_000 });
  expect(param(page.url(), 'realizations')).toBe('3');
  await expect(page.locator('#error')).toBeHidden();
  await expect(page.locator('#realizations')).not.toHaveAttribute('aria-invalid', 'true');
  expect(param(await copiedLink(page), 'realizations')).toBe('3');
});

test('an opened project or result file sets #realizations and the address to its n', async ({ page, context }) => {
  await context.grantPermissions(['clipboard-read', 'clipboard-write']);
  await page.goto(`${linkTo(TINY)}&realizations=3`);
  await waitForRun(page);
  await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-realizations', '3', { timeout: 120_000 });
  await expect(page.locator('body')).toHaveAttribute('data-headline', 'complete', { timeout: 120_000 });
  const files = { project: await downloadExport(page, 'project'), json: await downloadExport(page, 'json') };
  for (const [kind, file] of Object.entries(files)) {
    // A page at the default (5), then the file saved with n = 3.
    await page.goto(linkTo({ ...TINY, seed: 9 }));
    await waitForRun(page);
    await expect(page.locator('#realizations')).toHaveValue('5');
    await page.locator('#open-file').setInputFiles({ name: file.name, mimeType: 'application/json', buffer: file.bytes });
    await expect(page.locator('#status')).toContainText(/^Opened /);
    await expect(page.locator('#percent-scutoids'), kind).toHaveAttribute('data-realizations', '3');
    await expect(page.locator('#realizations'), kind).toHaveValue('3');
    expect(param(page.url(), 'realizations'), kind).toBe('3');
    expect(param(await copiedLink(page), 'realizations'), kind).toBe('3');
  }
});

/** A PNG whose header declares `width` x `height` gray pixels (its data is not the image's). */
function declaredPng(width: number, height: number): Buffer {
  const crc32 = (bytes: Buffer) => {
    let crc = 0xffffffff;
    for (const byte of bytes) {
      crc ^= byte;
      for (let k = 0; k < 8; k++) crc = crc & 1 ? 0xedb88320 ^ (crc >>> 1) : crc >>> 1;
    }
    return (crc ^ 0xffffffff) >>> 0;
  };
  const chunk = (type: string, data: Buffer) => {
    const body = Buffer.concat([Buffer.from(type, 'latin1'), data]);
    const length = Buffer.alloc(4);
    length.writeUInt32BE(data.length);
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(body));
    return Buffer.concat([length, body, crc]);
  };
  const header = Buffer.alloc(13);
  header.writeUInt32BE(width, 0);
  header.writeUInt32BE(height, 4);
  header[8] = 8; // bit depth; colour type 0: gray
  const signature = Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);
  return Buffer.concat([signature, chunk('IHDR', header), chunk('IDAT', deflateSync(Buffer.alloc(10))), chunk('IEND', Buffer.alloc(0))]);
}

test("a link's foreign mesh and its unusable density image are said as the link's", async ({ page }) => {
  let foreign = 0;
  await page.route(
    (url) => url.hostname === '10.1.2.3',
    (route) => {
      foreign += 1;
      return route.abort();
    },
  );
  await page.goto(
    linkTo({ surface: { kind: 'mesh', src: 'http://10.1.2.3:8080/evil.ply', scale: 50 }, cells: 30, lloyd: { maxIterations: 2 }, sheet: { thickness: 5 } }),
  );
  await expect(page.locator('#source-question')).toBeVisible();
  await expect(page.locator('#source-question')).toContainText('This link asks to load a mesh, /evil.ply, from 10.1.2.3:8080');
  expect(foreign).toBe(0);

  const src = `data:image/png;base64,${declaredPng(100_000, 100_000).toString('base64')}`;
  await page.goto(linkTo({ ...TINY, density: { kind: 'image', src } }));
  await expect(page.locator('#link-alert')).toBeVisible({ timeout: 60_000 });
  await expect(page.locator('#link-alert')).toContainText("This link's configuration was not run: density.src");
  await expect(page.locator('#link-alert')).toContainText('100000 x 100000 pixels');
  await expect(page.locator('#error')).toBeHidden();
  await expect(page.locator('body')).toHaveAttribute('data-state', 'refused');
});
