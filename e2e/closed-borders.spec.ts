import { decode } from 'fast-png';
import { expect, test, type Page } from '@playwright/test';
import { downloadExport, linkTo, waitForRun } from './appHelpers';
import { SIDE_COLORS } from '../src/view/sideColors';

/**
 * Closed surfaces are drawn per fragment (issue 14, "Look"): each pixel shows the cell whose
 * site is nearest to its point (src/view/closedCandidates.ts), with one-pixel borders, instead
 * of colours interpolated between texels. Checked on the page's own pixels: away from borders
 * every lit pixel is exactly a legend colour, and it is the colour of the cell a click there
 * picks (and hover names); blended colours are confined to the thin borders.
 */

const SPHERE = { resolution: 24, cells: 60, seed: 3, lloyd: { maxIterations: 2 }, surface: { kind: 'sphere', radius: 50 }, sheet: { thickness: 10 } };
const PALETTE = SIDE_COLORS.map((hex) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16)));

interface Result {
  analyses: { method: string; cells: { sides: number[] }[] }[];
}

async function resultOf(page: Page): Promise<Result> {
  return JSON.parse((await downloadExport(page, 'json')).text) as Result;
}

/** Index of the legend colour `rgb` is (each channel within 3), or -1. */
function paletteIndex(rgb: number[]): number {
  return PALETTE.findIndex((c) => c.every((v, k) => Math.abs(v - rgb[k]) <= 3));
}

test('a sphere is drawn per fragment: lit pixels are legend colours, the cell a click picks, borders one pixel wide', async ({ page }) => {
  await page.goto(linkTo(SPHERE));
  await waitForRun(page);
  // The page settles first: the headline over realizations (and its lines) changes the layout
  // around the view once the other realizations are in, which moves the canvas under a picture
  // taken before.
  await page.waitForFunction(() => document.body.dataset.headline === 'complete', null, { timeout: 120_000 });
  const result = await resultOf(page);
  const canvas = page.locator('#view3d');
  const box = (await canvas.boundingBox())!;
  const png = decode(await canvas.screenshot()); // 8-bit RGB or RGBA
  const at = (x: number, y: number) => [0, 1, 2].map((c) => png.data[png.channels * (y * png.width + x) + c]);
  const background = at(2, 2);
  const isBackground = (rgb: number[]) => rgb.every((v, k) => Math.abs(v - background[k]) <= 6);
  const isDark = (rgb: number[]) => Math.max(...rgb) < 90;

  // Blended pixels (neither a legend colour, nor a border's dark, nor background) only where a
  // border is drawn: within a pixel of a dark one. Per-vertex colours blurred them over a texel.
  let surface = 0,
    stray = 0;
  for (let y = 1; y < png.height - 1; y++) {
    for (let x = 1; x < png.width - 1; x++) {
      const rgb = at(x, y);
      if (isBackground(rgb)) continue;
      surface++;
      if (paletteIndex(rgb) >= 0 || isDark(rgb)) continue;
      let nearDark = false;
      for (let dy = -1; dy <= 1 && !nearDark; dy++) for (let dx = -1; dx <= 1 && !nearDark; dx++) nearDark = isDark(at(x + dx, y + dy));
      // Shaded pixels towards the limb are legend colours times a light factor: skip the rim.
      const rim = [
        [-3, 0],
        [3, 0],
        [0, -3],
        [0, 3],
      ].some(([dx, dy]) => isBackground(at(x + dx, y + dy)));
      if (!nearDark && !rim) stray++;
    }
  }
  expect(surface).toBeGreaterThan(10_000);
  expect(stray / surface).toBeLessThan(0.08);

  // Lit pixels well inside a cell: the click there picks the cell whose colour they are.
  const analysis = result.analyses.find((a) => a.method === 'exact') ?? result.analyses[0];
  const shown = analysis.cells[0].sides.length - 1; // the outer (apical) surface faces the camera
  const probes: { x: number; y: number; colour: number }[] = [];
  for (let y = 20; y < png.height - 20 && probes.length < 24; y += 13) {
    for (let x = 20; x < png.width - 20 && probes.length < 24; x += 17) {
      const colour = paletteIndex(at(x, y));
      if (colour < 0) continue;
      let uniform = true;
      for (let dy = -3; dy <= 3 && uniform; dy++) for (let dx = -3; dx <= 3 && uniform; dx++) uniform = paletteIndex(at(x + dx, y + dy)) === colour;
      if (uniform) probes.push({ x, y, colour });
    }
  }
  expect(probes.length).toBeGreaterThan(10);
  const tip = page.locator('#cell-hover');
  for (const [k, probe] of probes.entries()) {
    const x = box.x + probe.x + 0.5,
      y = box.y + probe.y + 0.5;
    if (k < 4) {
      // Hover names the same cell as the click (same rule as the drawing).
      await page.mouse.move(x - 2, y - 2);
      await page.mouse.move(x, y, { steps: 2 });
      await expect(tip).toBeVisible();
    }
    const hovered = k < 4 ? Number(await tip.getAttribute('data-cell')) : null;
    await page.mouse.click(x, y);
    const picked = Number(await page.locator('#cell-id').inputValue());
    if (hovered !== null) expect(hovered).toBe(picked);
    const sides = analysis.cells[picked].sides[shown];
    expect(Math.max(0, Math.min(sides, 10) - 3), `pixel (${probe.x}, ${probe.y}) → cell ${picked}`).toBe(probe.colour);
  }
});
