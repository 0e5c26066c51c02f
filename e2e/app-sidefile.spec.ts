import { copyFileSync, mkdirSync, readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { linkTo, runs, waitForRun } from './appHelpers';
import { runCli, tempDir } from './cli';

/**
 * Issue 27: `tissue-sheet run --cells-file` writes RESULT.json + RESULT.cells.bin; the page opens
 * the pair chosen together (its statistics and cells are the file's, nothing runs) and refuses
 * one file alone with a message naming the other.
 */
const TUBE = { resolution: 128, cells: 60, seed: 6, lloyd: { maxIterations: 3 }, sheet: { surfaceRatio: 2 } };

interface Result {
  cells: { id: number; neighbours: { id: number }[] }[];
  analyses: { method: string; summary: { percentScutoids: number } }[];
}

async function resultOf(page: Page): Promise<Result> {
  const [file] = await Promise.all([page.waitForEvent('download'), page.locator('[data-export="json"]').click()]);
  return JSON.parse(readFileSync(await file.path(), 'utf8')) as Result;
}

test('a result with its cells side file opens when both files are chosen; one alone names the other', async ({ page }) => {
  const dir = tempDir('sidefile');
  const configPath = join(dir, 'config.json');
  writeFileSync(configPath, JSON.stringify({ ...TUBE, seed: 12 }));
  const cli = (args: string[]) => runCli(['run', configPath, ...args]);
  cli(['--out', join(dir, 'plain.json')]);
  cli(['--out', join(dir, 'big.json'), '--cells-file']);
  const plain = JSON.parse(readFileSync(join(dir, 'plain.json'), 'utf8')) as Result;

  await page.goto(linkTo(TUBE));
  await waitForRun(page);
  const before = await runs(page);
  await page.locator('#open-file').setInputFiles(join(dir, 'big.json'));
  await expect(page.locator('#error')).toContainText('big.json: its cells are in the side file big.cells.bin');
  await page.locator('#open-file').setInputFiles(join(dir, 'big.cells.bin'));
  await expect(page.locator('#error')).toContainText('big.cells.bin is a cells side file: choose it together with its result JSON (big.json');
  // A side file cut short is refused, and the status says nothing was opened (not "Decoding ...").
  const cut = join(dir, 'cut');
  mkdirSync(cut);
  copyFileSync(join(dir, 'big.json'), join(cut, 'big.json'));
  const side = readFileSync(join(dir, 'big.cells.bin'));
  writeFileSync(join(cut, 'big.cells.bin'), side.subarray(0, side.length >> 1));
  await page.locator('#open-file').setInputFiles([join(cut, 'big.json'), join(cut, 'big.cells.bin')]);
  await expect(page.locator('#error')).toContainText('big.cells.bin');
  await expect(page.locator('#status')).toContainText('Not opened (big.json + big.cells.bin); the result on screen is as it was.');
  expect(await runs(page)).toBe(before);

  await page.locator('#open-file').setInputFiles([join(dir, 'big.cells.bin'), join(dir, 'big.json')]);
  await expect(page.locator('#status')).toContainText('Opened big.json + big.cells.bin');
  await expect(page.locator('#status')).toContainText('exact cells of its sites');
  expect(await runs(page)).toBe(before);
  const exact = plain.analyses.find((a) => a.method === 'exact')!;
  expect(Number(await page.locator('#percent-scutoids').getAttribute('data-drawn'))).toBe(exact.summary.percentScutoids);
  expect((await resultOf(page)).cells).toEqual(plain.cells);
});
