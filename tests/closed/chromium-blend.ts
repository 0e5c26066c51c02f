// Checks the closed-surface engine's additive-blend centroid path in headless Chromium
// (SwiftShader has EXT_float_blend; headless-gl does not), against the readback path on the
// same labels. Not part of `vitest run` (it needs Chromium): `npx tsx tests/closed/chromium-blend.ts`.
import { chromium } from '@playwright/test';
import { createServer } from 'vite';
import { chromiumArgs } from '../../playwright.config';

const server = await createServer({ server: { port: 5176, strictPort: true }, logLevel: 'error', optimizeDeps: { entries: ['tests/closed/page/*.html'] } });
await server.listen();
const browser = await chromium.launch({ executablePath: process.env.CHROMIUM_PATH ?? '/usr/bin/chromium', args: chromiumArgs });
let failed = false;
try {
  const page = await browser.newPage();
  page.on('console', (message) => console.error(`chromium: ${message.text()}`));
  await page.goto('http://127.0.0.1:5176/tests/closed/page/closed.html');
  await page.waitForFunction(() => document.title === 'ready', undefined, { timeout: 120_000 });
  const result = await page.evaluate(() => (window as unknown as { closedTest: { compare(n: number, c: number): unknown } }).closedTest.compare(64, 200));
  const r = result as { paths: string[]; worstCentroid: number; worstEnergy: number; energies: number[]; increases: number; capabilities: { renderer: string; floatBlend: boolean } };
  console.log(`renderer ${r.capabilities.renderer}, floatBlend ${r.capabilities.floatBlend}, paths ${r.paths.join(' / ')}`);
  console.log(`blend vs readback, ellipsoid 80:40:40 µm, n = 64, 200 sites: worst centroid difference ${r.worstCentroid.toExponential(2)} µm, worst relative energy difference ${r.worstEnergy.toExponential(2)}`);
  console.log(`blend-path Lloyd (omega = 1), 15 iterations: energy ${r.energies[0].toExponential(4)} -> ${r.energies.at(-1)!.toExponential(4)}, increases ${r.increases}`);
  failed = !(r.paths[0] === 'blend' && r.worstCentroid <= 1e-3 && r.worstEnergy <= 1e-4 && r.increases === 0);
} finally {
  await browser.close();
  await server.close();
}
console.log(failed ? 'FAILED' : 'ok');
process.exit(failed ? 1 : 0);
