import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { decodeCellsFile, withCellRecords, type CellsFileRecord, type ResultCellTables } from '../src/run/cellTables';
import type { SheetResult } from '../src/run';
import { openParsed } from '../src/app/model/project';
import { exportText, type ExportRequest } from '../src/app/model/exportFiles';
import { viewStack } from '../src/view/stack';
import { downloadExport, linkTo, unrolledWhitePixels, waitForRun } from './appHelpers';
import { runCli, tempDir } from './cli';
import { installLongTaskObserver, takeLongTasks } from './pages/longTasks';

/**
 * Issue 27: a big CLI result (25,000 cells, over the 20,000 above which the page draws texels)
 * opens and picks with the main thread free: the side file, the label images and the pictures
 * are made in a worker, the records when read, the cell table shows only the rows in view, and
 * a pick lays the cell's outline over the pictures instead of repainting them; the scutoid
 * highlight's pictures and the exports are made in the worker holding the result. Checked against
 * the files the CLI wrote (decoded here, in Node), the exports byte for byte against the page's
 * own builders run here on those files (what the main thread wrote before).
 */
const CONFIG = {
  surface: { kind: 'tube', radius: 300, length: 2400 },
  resolution: 1024,
  cells: 25_000,
  seed: 3,
  lloyd: { maxIterations: 1 },
  sheet: { surfaceRatio: 1.5 },
};
/**
 * Longest main-thread task allowed (ms). The page's own work is cut into tasks under 50 ms; what
 * is left is the browser's (a frame's raster on SwiftShader, the worker's reply decoded), which a
 * loaded 2-core machine stretches: a few tasks just over 50 ms are allowed, none of the seconds
 * opening took before (2.9 s at 100,000 cells, docs/benchmark.md).
 */
const LONGEST_MS = 200;
const OVER_50_MS_AT_MOST = 3;

interface Files {
  dir: string;
  json: string;
  side: string;
  data: SheetResult & { cellsFile: CellsFileRecord };
  bytes: Uint8Array;
  tables: ResultCellTables;
  surfaces: string[];
}

function writeResult(): Files {
  const dir = tempDir('bigresult');
  const configPath = join(dir, 'config.json');
  writeFileSync(configPath, JSON.stringify(CONFIG));
  const json = join(dir, 'big.json');
  runCli(['run', configPath, '--out', json, '--cells-file', '--realizations', '1'], { timeout: 240_000 });
  const data = JSON.parse(readFileSync(json, 'utf8')) as SheetResult & { cellsFile: CellsFileRecord };
  const side = join(dir, 'big.cells.bin');
  const bytes = new Uint8Array(readFileSync(side));
  const tables = decodeCellsFile(data.cellsFile, bytes);
  const last = data.surfaces[data.surfaces.length - 1]?.name;
  return { dir, json, side, data, bytes, tables, surfaces: [last === 'apical' ? 'basal' : 'apical', ...data.surfaces.map((s) => s.name)] };
}

const longTasks = takeLongTasks;
const frames = (page: Page, n: number) =>
  page.evaluate(
    (n) =>
      new Promise<void>((resolve) => {
        let left = n;
        const tick = () => (--left <= 0 ? resolve() : requestAnimationFrame(tick));
        requestAnimationFrame(tick);
      }),
    n,
  );

test("a 25,000-cell result opens, picks, toggles its scutoid stripes and exports without long main-thread tasks; its table, picked cell and files are the file's", async ({
  page,
}) => {
  test.setTimeout(300_000);
  const files = writeResult();
  const n = files.tables.cells.count;
  expect(n).toBe(CONFIG.cells);
  await installLongTaskObserver(page);
  await page.goto('/');
  await waitForRun(page);
  await longTasks(page);

  await page.locator('#open-file').setInputFiles([files.json, files.side]);
  await expect(page.locator('#status')).toContainText('Opened big.json + big.cells.bin', { timeout: 120_000 });
  // The pictures upload a band per frame: let them finish.
  await frames(page, 30);
  const opening = await longTasks(page);
  expect(Math.max(0, ...opening), `tasks while opening: ${opening.join(', ')} ms`).toBeLessThan(LONGEST_MS);
  expect(opening.filter((d) => d > 50).length, `tasks while opening: ${opening.join(', ')} ms`).toBeLessThanOrEqual(OVER_50_MS_AT_MOST);

  // The table: a bounded number of rows in the DOM, and they are the file's cells.
  await page.locator('#cells-title').click();
  const box = page.locator('#cell-table');
  await expect(box).toBeVisible();
  // Opening the details redraws the rows in the next frame (cellTableView.ts).
  await frames(page, 3);
  const rows = box.locator('tbody tr:not(.spacer)');
  expect(await rows.count()).toBeGreaterThan(0);
  expect(await rows.count()).toBeLessThanOrEqual(100);
  await expect(box.locator('table')).toHaveAttribute('aria-rowcount', String(n + 1));
  const rowHeight = await box.evaluate((el) => el.querySelector('tbody tr:not(.spacer)')!.getBoundingClientRect().height);
  expect(rowHeight).toBeGreaterThan(0);
  await box.evaluate((el, top) => (el.scrollTop = top), rowHeight * 12_345);
  await frames(page, 3);
  const shown = await rows.evaluateAll((trs) => trs.map((tr) => [...tr.children].map((c) => c.textContent ?? '')));
  expect(shown.length).toBeLessThanOrEqual(100);
  const ids = shown.map((cells) => Number(cells[0]));
  expect(ids).toContain(12_345);
  ids.forEach((id, k) => expect(id).toBe(ids[0] + k));
  const analysis = files.tables.analyses[0];
  const header = await box.locator('thead th').allTextContents();
  const column = (name: string) => header.indexOf(name);
  for (const cells of shown) {
    const id = Number(cells[0]);
    expect(Number(cells[column('valid')])).toBe(analysis.valid[id]);
    expect(Number(cells[column('scutoid')])).toBe(analysis.scutoid[id]);
    files.surfaces.forEach((name, k) => expect(Number(cells[column(`sides_${name}`)])).toBe(analysis.sides[k * n + id]));
    expect(Number(cells[column('u_um')])).toBeCloseTo(files.tables.cells.surface[2 * id], 3);
    expect(Number(cells[column('v_um')])).toBeCloseTo(files.tables.cells.surface[2 * id + 1], 3);
  }

  // Picking: the cell panel names the file's cell, its sides and the neighbours it wins and loses.
  await page.locator('#reset-camera').click();
  await page.locator('#view3d').scrollIntoViewIfNeeded();
  await frames(page, 2);
  const view = (await page.locator('#view3d').boundingBox())!;
  await longTasks(page);
  for (const [fx, fy] of [
    [0.5, 0.5],
    [0.42, 0.55],
  ]) {
    await page.evaluate(() => document.querySelector('#cell-info')!.removeAttribute('data-cell'));
    await page.mouse.click(view.x + fx * view.width, view.y + fy * view.height);
    await expect(page.locator('#cell-info')).toHaveAttribute('data-cell', /^\d+$/);
    const id = Number(await page.locator('#cell-info').getAttribute('data-cell'));
    expect(id).toBeLessThan(n);
    await expect(page.locator('#cell-info')).toContainText(`basal ${analysis.sides[id]}`);
    const neighbours = (table: ResultCellTables['cells']) =>
      new Set(Array.from(table.neighbourIds.subarray(table.neighbourOffsets[id], table.neighbourOffsets[id + 1])));
    const seeded = neighbours(files.tables.cells);
    const other = neighbours(files.tables.surfaces[files.tables.surfaces.length - 1]);
    const ids = (text: string | null) => (text ?? '').split(' ').filter(Boolean).map(Number);
    expect(ids(await page.locator('#cell-info').getAttribute('data-won'))).toEqual([...other].filter((c) => !seeded.has(c)).sort((a, b) => a - b));
    expect(ids(await page.locator('#cell-info').getAttribute('data-lost'))).toEqual([...seeded].filter((c) => !other.has(c)).sort((a, b) => a - b));
    // The table follows the pick.
    await expect(box.locator('tr.picked th').first()).toHaveText(String(id));
  }
  await frames(page, 3);
  const picking = await longTasks(page);
  expect(Math.max(0, ...picking), `tasks while picking: ${picking.join(', ')} ms`).toBeLessThan(LONGEST_MS);
  expect(picking.filter((d) => d > 50).length, `tasks while picking: ${picking.join(', ')} ms`).toBeLessThanOrEqual(OVER_50_MS_AT_MOST);
  // The picked cell is white on every unrolled surface (a patch over the picture).
  const white = await unrolledWhitePixels(page);
  expect(white.every((c) => c > 5)).toBe(true);

  // The scutoid stripes off and on again: the worker's pictures, shown without long tasks.
  const unrolledSum = () =>
    page.evaluate(() =>
      [...document.querySelectorAll<HTMLCanvasElement>('#unrolled canvas')].map((c) => {
        const d = c.getContext('2d')!.getImageData(0, 0, c.width, c.height).data;
        let sum = 0;
        for (let k = 0; k < d.length; k += 4) sum += d[k];
        return sum;
      }),
    );
  const striped = await unrolledSum();
  for (const on of [false, true]) {
    await longTasks(page);
    await page.locator('#highlight').setChecked(on);
    await expect(page.locator('body')).toHaveAttribute('data-stripes', on ? 'on' : 'off', { timeout: 60_000 });
    await frames(page, 30);
    const toggling = await longTasks(page);
    expect(Math.max(0, ...toggling), `tasks while toggling: ${toggling.join(', ')} ms`).toBeLessThan(LONGEST_MS);
    expect(toggling.filter((d) => d > 50).length, `tasks while toggling: ${toggling.join(', ')} ms`).toBeLessThanOrEqual(OVER_50_MS_AT_MOST);
    const sums = await unrolledSum();
    if (on) expect(sums).toEqual(striped);
    else sums.forEach((sum, k) => expect(sum).not.toBe(striped[k]));
  }

  // The exports, built in the worker: the bytes the page's builders make of the CLI's files here.
  const opened = openParsed(withCellRecords(files.data, files.tables), 'big.json');
  if (opened.kind !== 'result') throw new Error(`opened as ${opened.kind}`);
  const stack = viewStack(opened.output);
  const picked = await page.locator('body').getAttribute('data-selected-cell');
  const savedFiles: string[] = [];
  await longTasks(page);
  for (const kind of ['ply', 'vtk', 'svg', 'json', 'project'] as const) {
    const file = await downloadExport(page, kind);
    if (kind === 'json' || kind === 'project') {
      savedFiles.push(join(files.dir, file.name));
      writeFileSync(savedFiles[savedFiles.length - 1], file.bytes);
    }
    const saved = kind === 'project' ? (JSON.parse(file.text) as { view: ExportRequest['view']; sections?: Record<string, unknown>; savedAt: string }) : null;
    const request: ExportRequest = saved
      ? { kind, view: saved.view, sections: saved.sections, savedAt: saved.savedAt }
      : { kind, widthMm: Number(await page.locator('#figure-width').inputValue()) };
    expect(file.text === exportText(stack, request), `${kind} export equals the page's builder`).toBe(true);
  }
  await frames(page, 3);
  const exporting = await longTasks(page);
  expect(Math.max(0, ...exporting), `tasks while exporting: ${exporting.join(', ')} ms`).toBeLessThan(LONGEST_MS);
  expect(exporting.filter((d) => d > 50).length, `tasks while exporting: ${exporting.join(', ')} ms`).toBeLessThanOrEqual(OVER_50_MS_AT_MOST);

  // The saved project and result JSON (cells inline: 28 and 51 MB) open again, parsed in the worker.
  for (const path of savedFiles.reverse()) {
    await page.evaluate(() => (document.querySelector('#status')!.textContent = ''));
    await longTasks(page);
    await page.locator('#open-file').setInputFiles([path]);
    await expect(page.locator('#status')).toContainText(/^Opened /, { timeout: 120_000 });
    await frames(page, 30);
    const reopening = await longTasks(page);
    expect(Math.max(0, ...reopening), `tasks while opening ${path}: ${reopening.join(', ')} ms`).toBeLessThan(LONGEST_MS);
    expect(reopening.filter((d) => d > 50).length, `tasks while opening ${path}: ${reopening.join(', ')} ms`).toBeLessThanOrEqual(OVER_50_MS_AT_MOST);
    await expect(page.locator('#percent-scutoids')).toHaveAttribute('data-drawn', /\d/);
    if (path.endsWith('.tissue-sheet.json')) {
      await expect(page.locator('#status')).toContainText('Opened project');
      await expect(page.locator('body')).toHaveAttribute('data-selected-cell', picked!);
    }
  }
});

test('a 25,000-cell result made in the page: its scutoid stripes and exports are made in the worker it is handed to, without long main-thread tasks', async ({
  page,
}) => {
  test.setTimeout(300_000);
  await installLongTaskObserver(page);
  await page.goto(linkTo(CONFIG));
  await waitForRun(page);
  await frames(page, 30);
  await longTasks(page);
  for (const on of [false, true]) {
    await page.locator('#highlight').setChecked(on);
    await expect(page.locator('body')).toHaveAttribute('data-stripes', on ? 'on' : 'off', { timeout: 60_000 });
  }
  const files = new Map<string, string>();
  for (const kind of ['ply', 'svg', 'json'] as const) files.set(kind, (await downloadExport(page, kind)).text);
  await frames(page, 3);
  const tasks = await longTasks(page);
  expect(Math.max(0, ...tasks), `tasks while toggling and exporting: ${tasks.join(', ')} ms`).toBeLessThan(LONGEST_MS);
  expect(tasks.filter((d) => d > 50).length, `tasks while toggling and exporting: ${tasks.join(', ')} ms`).toBeLessThanOrEqual(OVER_50_MS_AT_MOST);
  // The files are of this result: its 25,000 cells, its configuration and seed.
  const json = JSON.parse(files.get('json')!) as SheetResult;
  expect(json.cells.length).toBe(CONFIG.cells);
  expect(json.config.seed).toBe(CONFIG.seed);
  expect(json.cells[12_345].id).toBe(12_345);
  expect(files.get('ply')).toMatch(/^ply\n/);
  expect(files.get('ply')).toContain(`"seed":${CONFIG.seed}`);
  expect(files.get('svg')).toContain('<svg');
});
