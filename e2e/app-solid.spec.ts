import { expect, test, type Page } from '@playwright/test';
import { download, downloadExport, linkTo, waitForRun } from './appHelpers';

/**
 * The picked cell as a 3D solid, and hover (issue 14): on a tube with a scutoid, the solid is
 * drawn (the view changes, shaded neutral pixels of the white solid appear), its cross-sections
 * have the cell's sides on each surface; hovering shows the cell the click picks at that point.
 * Pixel counts, not screenshots: SwiftShader's shading differs a little from a GPU's.
 */

const TUBE = { resolution: 128, cells: 60, seed: 5, lloyd: { maxIterations: 3 }, sheet: { surfaceRatio: 2 } };

interface Analysis {
  method: string;
  cells: { sides: number[]; scutoid: boolean; valid: boolean }[];
}

async function analysisOf(page: Page): Promise<Analysis> {
  const result = JSON.parse((await downloadExport(page, 'json')).text) as { analyses: Analysis[] };
  return result.analyses.find((a) => a.method === 'exact')!;
}

/** The 3D view's pixels: how many are neutral mid greys (the lit white solid's shading) and a digest. */
async function viewPixels(page: Page): Promise<{ neutral: number; data: number[] }> {
  return page.evaluate(() => {
    const view = document.querySelector<HTMLCanvasElement>('#view3d')!;
    const copy = document.createElement('canvas');
    copy.width = view.width;
    copy.height = view.height;
    const context = copy.getContext('2d')!;
    context.drawImage(view, 0, 0);
    const d = context.getImageData(0, 0, copy.width, copy.height).data;
    let neutral = 0;
    const data: number[] = [];
    for (let k = 0; k < d.length; k += 4) {
      const [r, g, b] = [d[k], d[k + 1], d[k + 2]];
      if (Math.max(r, g, b) - Math.min(r, g, b) <= 6 && r >= 70 && r <= 232) neutral++;
      if (k % 64 === 0) data.push(r, g, b);
    }
    return { neutral, data };
  });
}

test('a scutoid drawn as a 3D solid: keyboard toggle, sides per surface, pixels of the solid', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const analysis = await analysisOf(page);
  const id = analysis.cells.findIndex((c) => c.valid && c.scutoid && c.sides[0] !== c.sides[c.sides.length - 1]);
  expect(id).toBeGreaterThanOrEqual(0);
  const sides = analysis.cells[id].sides;

  await page.locator('#cell-id').fill(String(id));
  await page.locator('#cell-id').press('Enter');
  await expect(page.locator('body')).toHaveAttribute('data-selected-cell', String(id));
  await page.waitForTimeout(300);
  const before = await viewPixels(page);

  // Labelled, with a tooltip, operable with the keyboard.
  const box = page.getByLabel('Show picked cell as a 3D solid');
  await expect(box).toHaveAttribute('id', 'cell-solid');
  expect(await page.locator('label:has(#cell-solid)').getAttribute('title')).toBeTruthy();
  await box.focus();
  await page.keyboard.press('Space');
  await expect(box).toBeChecked();
  // Exact cross-sections: a corner per side on each surface (border edges and contacts too short
  // to count add corners), different at the two surfaces of this scutoid.
  await expect(page.locator('body')).toHaveAttribute('data-cell-solid', new RegExp(`^${id}:\\d+,\\d+$`));
  const corners = ((await page.locator('body').getAttribute('data-cell-solid')) ?? '').split(':')[1].split(',').map(Number);
  corners.forEach((c, k) => expect(c).toBeGreaterThanOrEqual(sides[k]));
  await page.waitForTimeout(300);
  const after = await viewPixels(page);
  let changed = 0;
  for (let k = 0; k < before.data.length; k++) if (Math.abs(before.data[k] - after.data[k]) > 16) changed++;
  expect(changed).toBeGreaterThan(30);
  expect(after.neutral - before.neutral).toBeGreaterThan(200);
  // Ticking the box turns the camera to the solid: it fills a good part of the view (a cell of a
  // long tube is a few pixels in the whole-sheet view); Reset camera shows the whole sheet again.
  const { width, height } = await page.evaluate(() => {
    const view = document.querySelector<HTMLCanvasElement>('#view3d')!;
    return { width: view.width, height: view.height };
  });
  expect(after.neutral).toBeGreaterThan(0.03 * width * height);
  await page.locator('#reset-camera').click();
  await page.waitForTimeout(300);
  const whole = await viewPixels(page);
  expect(whole.neutral).toBeLessThan(after.neutral / 4);
  await page.locator('#cell-solid-zoom').click();
  await page.waitForTimeout(300);
  expect((await viewPixels(page)).neutral).toBeGreaterThan(0.03 * width * height);

  // The solid as PLY: a closed, consistently oriented triangle mesh of this cell.
  const file = await download(page, '#cell-solid-ply');
  expect(file.name).toMatch(new RegExp(`cell${id}-solid\\.ply$`));
  const lines = file.text.trim().split('\n');
  const vertexCount = Number(lines.find((l) => l.startsWith('element vertex'))!.split(' ')[2]);
  const faceCount = Number(lines.find((l) => l.startsWith('element face'))!.split(' ')[2]);
  const body = lines.slice(lines.indexOf('end_header') + 1);
  expect(body.length).toBe(vertexCount + faceCount);
  for (const v of body.slice(0, vertexCount)) expect(Number(v.split(' ')[3])).toBe(id);
  const edges = new Set<string>();
  for (const f of body.slice(vertexCount)) {
    const [n, ...t] = f.split(' ').map(Number);
    expect(n).toBe(3);
    for (let e = 0; e < 3; e++) edges.add(`${t[e]},${t[(e + 1) % 3]}`);
  }
  expect(edges.size).toBe(3 * faceCount);
  for (const e of edges) expect(edges.has(e.split(',').reverse().join(','))).toBe(true);

  // Another pick moves the solid; clearing the pick removes it; unticking hides it.
  const other = analysis.cells.findIndex((c, k) => k !== id && c.valid);
  await page.locator('#cell-id').fill(String(other));
  await page.locator('#cell-id').press('Enter');
  await expect(page.locator('body')).toHaveAttribute('data-cell-solid', new RegExp(`^${other}:`));
  await page.locator('#cell-id').press('Escape');
  await expect(page.locator('body')).toHaveAttribute('data-cell-solid', '');
  await box.focus();
  await page.keyboard.press('Space');
  await expect(box).not.toBeChecked();
});

test('hover: a tooltip with the id, sides and scutoid flag of the cell a click there picks', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const analysis = await analysisOf(page);
  const view = (await page.locator('#view3d').boundingBox())!;
  const tip = page.locator('#cell-hover');
  await expect(tip).toBeHidden();
  // Points across the view; those on the sheet show the tooltip (a long tube does not fill the view).
  let checked = 0;
  for (const fy of [0.5, 0.4, 0.6, 0.3, 0.7]) {
    for (const fx of [0.5, 0.35, 0.65, 0.2, 0.8]) {
      if (checked >= 3) break;
      const x = view.x + view.width * fx;
      const y = view.y + view.height * fy;
      await page.mouse.move(x - 3, y - 3);
      await page.mouse.move(x, y, { steps: 2 });
      await page.waitForTimeout(150);
      if (await tip.isHidden()) continue;
      const hovered = Number(await tip.getAttribute('data-cell'));
      expect(hovered).toBeGreaterThanOrEqual(0);
      const cell = analysis.cells[hovered];
      await expect(tip).toContainText(`Cell ${hovered} `);
      await expect(tip).toContainText(`basal ${cell.sides[0]}`);
      await expect(tip).toContainText(!cell.valid ? 'border cell' : cell.scutoid ? '· scutoid' : 'not a scutoid');
      // The click at the same point picks the same cell.
      await page.mouse.click(x, y);
      await expect(page.locator('body')).toHaveAttribute('data-selected-cell', String(hovered));
      checked++;
    }
  }
  expect(checked).toBe(3);
  // Leaving the view hides it; a drag (button held) shows nothing.
  await page.mouse.move(view.x - 20, view.y - 20);
  await expect(tip).toBeHidden();
  await page.mouse.move(view.x + view.width / 2, view.y + view.height / 2);
  await page.mouse.down();
  await page.mouse.move(view.x + view.width / 2 + 40, view.y + view.height / 2, { steps: 4 });
  await expect(tip).toBeHidden();
  await page.mouse.up();
});
