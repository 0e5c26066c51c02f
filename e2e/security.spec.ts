import { readFileSync, readdirSync } from 'node:fs';
import { deflateSync } from 'node:zlib';
import { expect, test, type Page } from '@playwright/test';
import { injectedScriptRuns, linkTo, smallTube } from './appHelpers';

/**
 * Issue 19 under the app's Content-Security-Policy (index.html): no 'unsafe-eval' (validators are
 * precompiled), connect-src 'self'. Every shipped example runs with no violation (the app: every
 * run config of examples/*.json; the element: examples/element.html served with the same policy),
 * an injected inline script and eval do not run, an approved foreign source is fetched by the
 * relay frame only after the click, and density images are size-checked from their header.
 */

const SMALL = smallTube(3, 2, 2);

/** The app's policy, read from index.html (the element's page is served with the same one). */
function appPolicy(): string {
  const html = readFileSync('index.html', 'utf8');
  const match = html.match(/http-equiv="Content-Security-Policy"\s+content="([^"]+)"/);
  if (!match) throw new Error('index.html has no Content-Security-Policy meta');
  return match[1];
}

/** Collects every securitypolicyviolation of the page and its frames. */
async function watchViolations(page: Page): Promise<string[]> {
  const violations: string[] = [];
  await page.exposeFunction('reportViolation', (v: string) => violations.push(v));
  await page.addInitScript(() => {
    document.addEventListener('securitypolicyviolation', (e) =>
      (window as unknown as { reportViolation(v: string): void }).reportViolation(`${e.violatedDirective} ${e.blockedURI} ${e.sourceFile}:${e.lineNumber}`),
    );
  });
  return violations;
}

async function waitForRun(page: Page): Promise<void> {
  await page.waitForFunction(() => document.body.dataset.state === 'done' && Number(document.body.dataset.runs ?? 0) > 0, undefined, { timeout: 150_000 });
}

function crc32(bytes: Uint8Array): number {
  let crc = ~0;
  for (const byte of bytes) {
    crc ^= byte;
    for (let k = 0; k < 8; k++) crc = (crc >>> 1) ^ (0xedb88320 & -(crc & 1));
  }
  return ~crc >>> 0;
}

/** A PNG: signature, IHDR (8-bit grey), one IDAT of `rows` (filter byte + pixels per row), IEND. */
function png(width: number, height: number, rows?: Uint8Array, idat?: Uint8Array): Buffer {
  const chunk = (type: string, data: Uint8Array) => {
    const head = Buffer.alloc(8);
    head.writeUInt32BE(data.length, 0);
    head.write(type, 4, 'latin1');
    const crc = Buffer.alloc(4);
    crc.writeUInt32BE(crc32(Buffer.concat([head.subarray(4), data])), 0);
    return Buffer.concat([head, data, crc]);
  };
  const ihdr = Buffer.alloc(13);
  ihdr.writeUInt32BE(width, 0);
  ihdr.writeUInt32BE(height, 4);
  ihdr[8] = 8; // bit depth
  ihdr[9] = 0; // grey
  const raw = rows ?? new Uint8Array(0);
  return Buffer.concat([
    Buffer.from([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]),
    chunk('IHDR', ihdr),
    chunk('IDAT', idat ?? deflateSync(raw)),
    chunk('IEND', new Uint8Array(0)),
  ]);
}

test('the policy has no unsafe-eval and no other origin; eval and an injected inline script do not run', async ({ page }) => {
  const policy = appPolicy();
  expect(policy).toContain("script-src 'self';");
  expect(policy).not.toContain('unsafe-eval');
  expect(policy).not.toMatch(/https?:/);
  const violations = await watchViolations(page);
  // A script of the page's own origin (allowed to run) that tries eval and new Function: page.evaluate
  // itself is not bound by the page's policy, a script the page loads is.
  await page.route('**/__eval-probe.js', (route) =>
    route.fulfill({
      contentType: 'text/javascript',
      body: "var r = {}; try { r.evalRan = eval('1 + 1') === 2; } catch (e) { r.evalRan = false; } try { r.functionRan = new Function('return 2')() === 2; } catch (e) { r.functionRan = false; } window.__probe = r;",
    }),
  );
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  expect(violations).toEqual([]);
  const attempts = await page.evaluate(async () => {
    const script = document.createElement('script');
    script.textContent = 'window.__injected = true;';
    document.body.append(script);
    const probe = document.createElement('script');
    probe.src = '/__eval-probe.js';
    await new Promise((resolve) => {
      probe.onload = resolve;
      probe.onerror = resolve;
      document.body.append(probe);
    });
    await new Promise((r) => setTimeout(r, 100));
    const w = window as unknown as { __injected?: boolean; __probe?: { evalRan: boolean; functionRan: boolean } };
    return { inline: w.__injected === true, ...w.__probe };
  });
  expect(attempts).toEqual({ inline: false, evalRan: false, functionRan: false });
  expect(violations.some((v) => v.startsWith('script-src'))).toBe(true);
});

const runConfigs = readdirSync('examples')
  .filter((name) => name.endsWith('.json'))
  .map((name) => ({ name, json: JSON.parse(readFileSync(`examples/${name}`, 'utf8')) as Record<string, unknown> }))
  .filter(({ json }) => !('base' in json)); // sweep specs have a base config; run configs do not

for (const { name, json } of runConfigs) {
  test(`the app runs examples/${name} under its policy with no violation`, async ({ page }) => {
    const violations = await watchViolations(page);
    await page.goto(linkTo(json));
    await waitForRun(page);
    await expect(page.locator('#percent-scutoids')).not.toHaveText('–');
    expect(violations).toEqual([]);
  });
}

test('the element runs examples/element.html under the same policy with no violation', async ({ page }) => {
  const policy = appPolicy();
  await page.route('**/examples/element.html', async (route) => {
    const response = await route.fetch();
    await route.fulfill({ response, headers: { ...response.headers(), 'content-security-policy': policy } });
  });
  const violations = await watchViolations(page);
  await page.goto('/examples/element.html');
  for (const id of ['bare', 'wide']) {
    await expect(page.locator(`#${id}`)).toHaveAttribute('data-done', 'true', { timeout: 150_000 });
    await expect(page.locator(`#${id}-out`)).toContainText('% scutoids');
  }
  expect(violations).toEqual([]);
  // The policy is in force on that page: an inline script does not run there either.
  expect(await injectedScriptRuns(page)).toBe(false);
});

test('an approved foreign density image is fetched by the relay frame, after the click, with no violation', async ({ page }) => {
  const width = 16;
  const rows = new Uint8Array(width * (width + 1));
  for (let y = 0; y < width; y++) for (let x = 0; x < width; x++) rows[y * (width + 1) + 1 + x] = x * 16;
  const image = png(width, width, rows);
  const requests: { url: string; frame: string }[] = [];
  await page.route(
    (url) => url.hostname === 'foreign.example',
    (route) => {
      requests.push({ url: route.request().url(), frame: route.request().frame().url() });
      return route.fulfill({ status: 200, body: image, headers: { 'content-type': 'image/png', 'access-control-allow-origin': '*' } });
    },
  );
  const violations = await watchViolations(page);
  await page.goto(linkTo({ ...SMALL, density: { kind: 'image', src: 'https://foreign.example/lab/density.png' } }));
  const question = page.locator('#source-question');
  await expect(question).toContainText('from foreign.example');
  await page.waitForTimeout(1000);
  expect(requests).toEqual([]);
  await question.getByRole('button', { name: /Load/ }).click();
  await waitForRun(page);
  expect(requests.length).toBe(1);
  expect(requests[0].url).toBe('https://foreign.example/lab/density.png');
  expect(new URL(requests[0].frame).pathname).toBe('/source-relay.html');
  expect(violations).toEqual([]);
});

for (const [what, bytes, expected] of [
  ['a PNG declaring 20000 x 20000 pixels', png(20000, 20000), /20000 x 20000 pixels is more than the \d+ the page decodes/],
  ['a truncated PNG', png(64, 64, new Uint8Array(65 * 64).fill(200)).subarray(0, 60), /truncated PNG/],
  // Whole chunks, valid CRCs, but image data that is no zlib stream: the browser drew it black
  // and the run went on with a uniform density; the page decodes PNGs as the CLI does.
  ['a PNG whose image data is corrupt', png(64, 64, undefined, new Uint8Array([1, 2, 3])), /corrupt PNG/],
] as const) {
  test(`a link's density image is refused from its header: ${what}`, async ({ page }) => {
    const src = `data:image/png;base64,${Buffer.from(bytes).toString('base64')}`;
    await page.goto(linkTo({ ...SMALL, density: { kind: 'image', src } }));
    const alert = page.locator('[role="alert"]:visible');
    await expect(alert.first()).toContainText(expected, { timeout: 30_000 });
    await expect(alert.first()).toContainText('density.src');
    expect(Number((await page.locator('body').getAttribute('data-runs')) ?? 0)).toBe(0);
  });
}
