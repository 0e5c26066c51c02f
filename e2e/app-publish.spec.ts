import { writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { downloadExport, linkTo, runs, unrolledWhitePixels, waitForRun } from './appHelpers';
import { cliRun, runCli, tempDir } from './cli';
import { readPngDpi, readPngText } from '../tests/app/pngRead';
import { SIDE_COLORS } from '../src/view/sideColors';

/**
 * Publish and look (issue 14): VTK, SVG, figure PNG, project files, a CLI result opened in the
 * page, the picked cell, keyboard and labels, the palette; a failed and a cancelled run. Every
 * export is parsed back here and compared with the result JSON the page itself exports.
 */

const TUBE = { resolution: 128, cells: 60, seed: 5, lloyd: { maxIterations: 3 }, sheet: { surfaceRatio: 2 } };
const SPHERE = { resolution: 24, cells: 60, seed: 3, lloyd: { maxIterations: 2 }, surface: { kind: 'sphere', radius: 50 }, sheet: { thickness: 10 } };

interface Result {
  config: unknown;
  cells: { id: number; position: number[]; surface: number[] }[];
  surfaces: unknown[];
  analyses: {
    method: string;
    cells: { sides: number[]; scutoid: boolean; valid: boolean; won: number; lost: number }[];
    summary: { percentScutoids: number };
  }[];
}

async function resultOf(page: Page): Promise<Result> {
  return JSON.parse((await downloadExport(page, 'json')).text) as Result;
}

const exact = (result: Result) => result.analyses.find((a) => a.method === 'exact')!;

/** A small reader of legacy ASCII VTK POLYDATA (the subset ParaView's reader needs from us). */
function parseVtk(text: string): { title: string; points: number; polygons: number[][]; data: Record<string, number[]> } {
  const lines = text.split('\n');
  expect(lines[0]).toMatch(/^# vtk DataFile Version \d\.\d$/);
  expect(lines[1].length).toBeLessThanOrEqual(256);
  expect(lines[2]).toBe('ASCII');
  expect(lines[3]).toBe('DATASET POLYDATA');
  const tokens = lines.slice(4).join(' ').split(/\s+/).filter(Boolean);
  let at = 0;
  const next = () => tokens[at++];
  expect(next()).toBe('POINTS');
  const points = Number(next());
  expect(next()).toBe('float');
  for (let k = 0; k < 3 * points; k++) expect(Number.isFinite(Number(next()))).toBe(true);
  expect(next()).toBe('POLYGONS');
  const count = Number(next());
  const size = Number(next());
  const polygons: number[][] = [];
  let used = 0;
  for (let p = 0; p < count; p++) {
    const n = Number(next());
    const poly = Array.from({ length: n }, () => Number(next()));
    for (const index of poly) expect(index >= 0 && index < points).toBe(true);
    polygons.push(poly);
    used += n + 1;
  }
  expect(used).toBe(size);
  expect(next()).toBe('CELL_DATA');
  expect(Number(next())).toBe(count);
  const data: Record<string, number[]> = {};
  while (at < tokens.length) {
    expect(next()).toBe('SCALARS');
    const name = next();
    expect(next()).toBe('int');
    expect(next()).toBe('1');
    expect(next()).toBe('LOOKUP_TABLE');
    expect(next()).toBe('default');
    data[name] = Array.from({ length: count }, () => Number(next()));
  }
  return { title: lines[1], points, polygons, data };
}

test('VTK and SVG exports parse back to the result: every cell on every surface, its sides and flags', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const result = await resultOf(page);
  const analysis = exact(result);
  const n = result.cells.length;
  const surfaces = result.surfaces.length + 1;

  const vtk = await downloadExport(page, 'vtk');
  expect(vtk.name).toBe('tissue-sheet-tube-seed5-cells.vtk');
  const parsed = parseVtk(vtk.text);
  expect(parsed.title).toContain('seed 5');
  expect(parsed.polygons).toHaveLength(n * surfaces);
  for (let k = 0; k < parsed.polygons.length; k++) {
    const id = parsed.data.cell_id[k];
    const surface = parsed.data.surface[k];
    expect(parsed.data.sides[k]).toBe(analysis.cells[id].sides[surface]);
    expect(parsed.data.scutoid[k]).toBe(analysis.cells[id].scutoid ? 1 : 0);
    expect(parsed.data.valid[k]).toBe(analysis.cells[id].valid ? 1 : 0);
    // An exact cell has as many corners as sides, plus the corners where it meets an open end.
    expect(parsed.polygons[k].length).toBeGreaterThanOrEqual(3);
  }
  for (let s = 0; s < surfaces; s++) {
    const ids = parsed.data.cell_id.filter((_, k) => parsed.data.surface[k] === s).sort((a, b) => a - b);
    expect(ids).toEqual(Array.from({ length: n }, (_, i) => i));
  }

  const svg = (await downloadExport(page, 'svg')).text;
  expect(svg).toContain('<svg xmlns="http://www.w3.org/2000/svg"');
  const config = /<metadata id="tissue-sheet-config">([^<]*)<\/metadata>/
    .exec(svg)![1]
    .replace(/&quot;/g, '"')
    .replace(/&amp;/g, '&');
  expect(JSON.parse(config)).toEqual(result.config);
  const polygons = [
    ...svg.matchAll(
      /<polygon data-cell="(\d+)" data-surface="(\d+)" data-sides="(\d+)" data-scutoid="(\d)" data-valid="(\d)"( data-copy="1")? points="([^"]+)"/g,
    ),
  ];
  const primary = polygons.filter((m) => !m[6]);
  expect(primary).toHaveLength(n * surfaces);
  for (const m of primary) {
    const [id, surface, sides, scutoid] = [Number(m[1]), Number(m[2]), Number(m[3]), Number(m[4])];
    expect(sides).toBe(analysis.cells[id].sides[surface]);
    expect(scutoid).toBe(analysis.cells[id].scutoid ? 1 : 0);
    // The polygon surrounds its site (µm, y up in the file: SVG y = height - v).
    const points = m[7].split(' ').map((p) => p.split(',').map(Number));
    expect(points.length).toBeGreaterThanOrEqual(3);
  }
  const bar = Number(/id="scale-bar" data-length-um="([\d.]+)"/.exec(svg)![1]);
  expect([1, 2, 5].some((d) => Math.abs(bar / 10 ** Math.floor(Math.log10(bar)) - d) < 1e-9)).toBe(true);
});

test('figure PNG: chosen DPI in pHYs, pixel width from mm and DPI, provenance in tEXt', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const result = await resultOf(page);
  await page.locator('#figure-dpi').selectOption('150');
  await page.locator('#figure-width').fill('120');
  const png = await downloadExport(page, 'figure');
  expect(png.name).toBe('tissue-sheet-tube-seed5-figure-150dpi.png');
  const bytes = new Uint8Array(png.bytes);
  expect(readPngDpi(bytes)).toBeCloseTo(150, 1);
  const width = png.bytes.readUInt32BE(16);
  expect(width).toBe(Math.round((120 / 25.4) * 150));
  const text = readPngText(bytes);
  expect(JSON.parse(text['tissue-sheet:config'])).toEqual(result.config);
  expect(text.Description).toContain('scale bar');
  // Not blank: the cells' colours are in it (read back in the page).
  const colours = await page.evaluate(
    async (data) => {
      const image = await createImageBitmap(new Blob([new Uint8Array(data)], { type: 'image/png' }));
      const canvas = new OffscreenCanvas(image.width, image.height);
      const context = canvas.getContext('2d')!;
      context.drawImage(image, 0, 0);
      const pixels = context.getImageData(0, 0, image.width, image.height).data;
      const seen = new Set<string>();
      for (let k = 0; k < pixels.length; k += 4 * 97) seen.add(`${pixels[k]},${pixels[k + 1]},${pixels[k + 2]}`);
      return [...seen];
    },
    [...png.bytes],
  );
  const rgb = (hex: string) => [1, 3, 5].map((k) => parseInt(hex.slice(k, k + 2), 16)).join(',');
  expect(SIDE_COLORS.filter((c) => colours.includes(rgb(c))).length).toBeGreaterThanOrEqual(3);
});

test('a saved project restores the exact view; a result JSON from the CLI opens and is drawn from its cells', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  // The headline over its realizations is in before the result is saved.
  await page.waitForFunction(() => document.body.dataset.headline === 'complete', undefined, { timeout: 120_000 });
  const result = await resultOf(page);
  // Change the view: pick a cell, hide the basal surface, orbit the camera.
  await page.locator('#cell-id').fill('7');
  await page.locator('#cell-id').press('Enter');
  await expect(page.locator('#cell-info')).toHaveAttribute('data-cell', '7');
  await page.locator('#surface-toggles input').first().uncheck();
  const box = (await page.locator('#view3d').boundingBox())!;
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2);
  await page.mouse.down();
  await page.mouse.move(box.x + box.width / 2 + 80, box.y + box.height / 2 + 30, { steps: 5 });
  await page.mouse.up();
  await page.waitForTimeout(300);
  const before = await page.locator('#view3d').screenshot();
  const info = await page.locator('#cell-info').textContent();
  const project = await downloadExport(page, 'project');
  expect(project.name).toBe('tissue-sheet-tube-seed5.tissue-sheet.json');
  const dir = tempDir('publish');
  const projectPath = join(dir, project.name);
  writeFileSync(projectPath, project.bytes);

  // A fresh page with another configuration, then the project.
  await page.goto(linkTo({ ...TUBE, seed: 9 }));
  await waitForRun(page);
  const runsBefore = await runs(page);
  await page.locator('#open-file').setInputFiles(projectPath);
  await expect(page.locator('#status')).toContainText('Opened project');
  expect(await runs(page)).toBe(runsBefore); // nothing ran
  await expect(page.locator('#cell-info')).toHaveText(info!);
  await expect(page.locator('#surface-toggles input').first()).not.toBeChecked();
  await page.waitForTimeout(300);
  expect(await page.locator('#view3d').screenshot()).toEqual(before);
  expect(await resultOf(page)).toEqual(result);
  expect(new URL(page.url()).searchParams.get('config')).not.toBeNull();
  expect(JSON.parse(new URL(page.url()).searchParams.get('config')!)).toEqual(result.config);

  // The CLI's result JSON: statistics are the file's, pictures its exact cells; nothing runs.
  const { result: cli, resultPath } = cliRun<Result>({ ...TUBE, seed: 11 });
  await page.locator('#open-file').setInputFiles(resultPath);
  await expect(page.locator('#status')).toContainText('exact cells of its sites');
  expect(await runs(page)).toBe(runsBefore);
  expect(Number(await page.locator('#percent-scutoids').getAttribute('data-drawn'))).toBe(exact(cli).summary.percentScutoids);
  const shown = await resultOf(page);
  expect(shown.cells).toEqual(cli.cells);

  // A file that is not a result: one line, the view stays.
  const badPath = join(dir, 'bad.json');
  writeFileSync(badPath, JSON.stringify({ software: { name: 'other' } }));
  await page.locator('#open-file').setInputFiles(badPath);
  await expect(page.locator('#error')).toContainText('bad.json: software.name is not "tissue-sheet"');
  expect((await resultOf(page)).cells).toEqual(cli.cells);
});

test('a CLI result of a closed surface is run again from its configuration, and says whether it reproduced the file', async ({ page }) => {
  const dir = tempDir('publish');
  const configPath = join(dir, 'sphere.json');
  const resultPath = join(dir, 'sphere-result.json');
  writeFileSync(configPath, JSON.stringify(SPHERE));
  try {
    runCli(['run', configPath, '--out', resultPath]);
  } catch (error) {
    test.skip(true, `the CLI could not run a sphere here (no headless-gl?): ${String((error as Error).message).split('\n')[0]}`);
  }
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const before = await runs(page);
  await page.locator('#open-file').setInputFiles(resultPath);
  await waitForRun(page, before);
  await expect(page.locator('#status')).toContainText('run again');
  await expect(page.locator('#status')).toContainText(/reproduced the file's sites|differ from the file's/);
});

test('a picked cell: its id, sides per surface, neighbours won and lost (matching the analysis), white on every surface', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const result = await resultOf(page);
  const analysis = exact(result);
  // Click the middle of the first unrolled canvas; the info names a cell.
  const canvas = page.locator('#unrolled canvas').first();
  await canvas.click({ position: { x: 30, y: 40 } });
  const id = Number(await page.locator('#cell-info').getAttribute('data-cell'));
  expect(id).toBeGreaterThanOrEqual(0);
  const won = ((await page.locator('#cell-info').getAttribute('data-won')) ?? '').split(' ').filter(Boolean);
  const lost = ((await page.locator('#cell-info').getAttribute('data-lost')) ?? '').split(' ').filter(Boolean);
  // Default protocol, no layers: the analysis counts won and lost between the two surfaces.
  expect(won.length).toBe(analysis.cells[id].won);
  expect(lost.length).toBe(analysis.cells[id].lost);
  const sides = analysis.cells[id].sides;
  await expect(page.locator('#cell-info')).toContainText(`basal ${sides[0]}`);
  await expect(page.locator('body')).toHaveAttribute('data-selected-cell', String(id));
  // White on every unrolled surface: each canvas now has white pixels.
  const white = await unrolledWhitePixels(page);
  expect(white.every((c) => c > 20)).toBe(true);
  // A click in the 3D view picks too (the sheet fills the view's centre).
  const box = (await page.locator('#view3d').boundingBox())!;
  await page.mouse.click(box.x + box.width / 2, box.y + box.height / 2);
  expect(Number(await page.locator('body').getAttribute('data-selected-cell'))).toBeGreaterThanOrEqual(0);
  // Escape in the field clears.
  await page.locator('#cell-id').focus();
  await page.keyboard.press('Escape');
  await expect(page.locator('body')).toHaveAttribute('data-selected-cell', '-1');
});

test('accessible: the canvas takes the focus, every control has a name, the palette survives colour blindness', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  await page.locator('#view3d').focus();
  expect(await page.evaluate(() => document.activeElement?.id)).toBe('view3d');
  const unnamed = await page.evaluate(() =>
    // Controls, and the pictures a user can pick cells in (the charts' canvases are uPlot's).
    [...document.querySelectorAll<HTMLElement>('button, input, select, textarea, #view3d, #unrolled canvas')]
      .filter((el) => !el.closest('[hidden]') && !(el instanceof HTMLInputElement && el.type === 'hidden'))
      .filter((el) => {
        const labelled = (el as HTMLInputElement).labels?.length || el.getAttribute('aria-label') || el.getAttribute('aria-labelledby') || el.title;
        const text = el.tagName === 'BUTTON' ? el.textContent?.trim() : '';
        return !labelled && !text;
      })
      .map((el) => el.outerHTML.slice(0, 80)),
  );
  expect(unnamed).toEqual([]);
  // Keyboard: Tab reaches the new export buttons and Enter presses them.
  await page.locator('[data-export="vtk"]').focus();
  const [file] = await Promise.all([page.waitForEvent('download'), page.keyboard.press('Enter')]);
  expect(file.suggestedFilename()).toMatch(/\.vtk$/);

  // Every pair of side colours stays apart under simulated protanopia, deuteranopia and
  // tritanopia (Machado, Oliveira & Fernandes 2009, severity 1), CIE76 ΔE in CIELAB.
  for (const [name, m] of Object.entries(CVD)) {
    const labs = SIDE_COLORS.map((hex) => lab(simulate(hex, m)));
    let worst = Infinity;
    for (let i = 0; i < labs.length; i++)
      for (let j = i + 1; j < labs.length; j++) worst = Math.min(worst, Math.hypot(...labs[i].map((v, k) => v - labs[j][k])));
    expect(worst, `closest side colours under ${name}`).toBeGreaterThanOrEqual(15);
  }
});

test('a failed run and a cancelled run leave the result, the page and the link as they were', async ({ page }) => {
  await page.goto('/');
  await page.evaluate(() => localStorage.clear());
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const url = page.url();
  const percent = await page.locator('#percent-scutoids').getAttribute('data-drawn');
  // Failed: a run the page refuses (a hundred million cells) typed in the form.
  const cancelBefore = await runs(page);
  await page.evaluate(() => {
    const field = document.querySelector<HTMLInputElement>('input[name="cells"]');
    if (!field) throw new Error('no cells field');
    field.value = '100000000';
    field.dispatchEvent(new Event('input', { bubbles: true }));
    field.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await expect(page.locator('#error')).toBeVisible({ timeout: 20_000 });
  expect(page.url()).toBe(url);
  await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-drawn', percent!);
  expect(await runs(page)).toBe(cancelBefore);

  // Cancelled: a long run, cancelled at its first iteration.
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const runsBefore = await runs(page);
  await page.evaluate(() => {
    const field = document.querySelector<HTMLInputElement>('input[name="lloyd.maxIterations"]');
    if (!field) throw new Error('no iterations field');
    field.value = '400';
    field.dispatchEvent(new Event('change', { bubbles: true }));
  });
  await page.waitForFunction(() => document.body.dataset.state === 'running', undefined, { timeout: 20_000 });
  await page.locator('#cancel').click();
  await page.waitForFunction(() => document.body.dataset.state === 'cancelled', undefined, { timeout: 20_000 });
  expect(page.url()).toBe(url);
  expect(await runs(page)).toBe(runsBefore);
  await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-drawn', percent!);
  const shown = await resultOf(page);
  expect((shown.config as { lloyd: { maxIterations: number } }).lloyd.maxIterations).toBe(3);
});

test('screenshots at a fixed seed: exact cell borders on a tube, the picked cell, closed surface shading', async ({ page }) => {
  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const mask = [page.locator('#status')];
  await expect(page.locator('#view3d')).toHaveScreenshot('publish-tube-view.png', { mask });
  await page.locator('#cell-id').fill('12');
  await page.locator('#cell-id').press('Enter');
  await expect(page.locator('#unrolled')).toHaveScreenshot('publish-tube-unrolled-picked.png');
  await page.goto(linkTo(SPHERE));
  await waitForRun(page);
  await expect(page.locator('#view3d')).toHaveScreenshot('publish-sphere-view.png');
});

const CVD: Record<string, number[][]> = {
  protanopia: [
    [0.152286, 1.052583, -0.204868],
    [0.114503, 0.786281, 0.099216],
    [-0.003882, -0.048116, 1.051998],
  ],
  deuteranopia: [
    [0.367322, 0.860646, -0.227968],
    [0.280085, 0.672501, 0.047413],
    [-0.01182, 0.04294, 0.968881],
  ],
  tritanopia: [
    [1.255528, -0.076749, -0.178779],
    [-0.078411, 0.930809, 0.147602],
    [0.004733, 0.691367, 0.3039],
  ],
};

function simulate(hex: string, m: number[][]): number[] {
  const linear = [1, 3, 5].map((k) => {
    const c = parseInt(hex.slice(k, k + 2), 16) / 255;
    return c <= 0.04045 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4;
  });
  return m.map((row) => Math.max(0, Math.min(1, row[0] * linear[0] + row[1] * linear[1] + row[2] * linear[2])));
}

function lab([r, g, b]: number[]): number[] {
  const x = (0.4124 * r + 0.3576 * g + 0.1805 * b) / 0.95047;
  const y = 0.2126 * r + 0.7152 * g + 0.0722 * b;
  const z = (0.0193 * r + 0.1192 * g + 0.9505 * b) / 1.08883;
  const f = (t: number) => (t > 0.008856 ? Math.cbrt(t) : 7.787 * t + 16 / 116);
  return [116 * f(y) - 16, 500 * (f(x) - f(y)), 200 * (f(y) - f(z))];
}
