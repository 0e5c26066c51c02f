import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import {
  measureVolume,
  volumeModelDrawing,
  type MeasuredResult,
  type ShellMeshes,
  type VolumeMeasuredResult,
  type VolumeModelDrawing,
} from '../src/core/measure';
import { parseCsv } from '../src/core/sweep';
import { readPngText } from '../tests/app/pngRead';
import { png16, randomSites, rasterizeVoronoi } from '../tests/measure/images';
import { writeTiff } from '../tests/measure/tiffWriter';
import { download, expectNoLongTasks } from './appHelpers';
import { runCli, tempDir } from './cli';
import { installLongTaskObserver, takeLongTasks } from './pages/longTasks';
import { labelData, permutedLabels, shellVolume, volumePages } from '../tests/measure/volumes';

/**
 * Issue 28 in the page, and issue 26's measure items, as a person does them:
 * - choose one 3D label TIFF without calibration: the page asks for the voxel size in its own
 *   fields (never assumed); typed in, the volume is measured in a worker (no main-thread task
 *   over 50 ms) and gives the numbers `tissue-sheet measure --volume --compare` gives; a cell
 *   picked on a surface shows its neighbours on both sides and its 3D shape; the per-cell CSV,
 *   the JSON and the figure are parsed back and compared with the screen and the CLI; the
 *   project file keeps it, and reopening it in a fresh page shows the same numbers.
 * - the model of the same geometry is drawn below the tissue (its first realization, every cell on
 *   both surfaces), and a model cell picked there lists the neighbours on both sides that the
 *   core's volumeModelDrawing gives for the CLI's comparison; the 3D view's PNG includes it; the
 *   project file draws it again.
 * - two label images chosen in a file dialog's (alphabetical) order, apical first: the page
 *   warns; the file's layer picker reassigns them, the warning goes, the CSV follows the screen,
 *   and the project file keeps the reassigned order.
 * The volume: 24 cells on an ellipsoidal shell (tests/measure/volumes.ts), voxels 0.5 x 0.5 x 0.75 µm.
 */

const small = { surface: { kind: 'tube', radius: 128 / (2 * Math.PI), length: 256 }, resolution: 128, cells: 60, seed: 3, lloyd: { maxIterations: 2 } };
const VOXEL = { x: 0.5, y: 0.5, z: 0.75 };

interface Inputs {
  dir: string;
  cli: VolumeMeasuredResult;
  /** The model's first realization as the core draws it from the CLI's comparison (what the page must show). */
  model: VolumeModelDrawing;
}

function makeVolume(dir: string): Inputs {
  const shell = shellVolume({ voxel: VOXEL, a: 9, b: 8, c: 7, h: 3, sites: 24, seed: 2, margin: 2 });
  const labels = permutedLabels(24, 3, 7, 5);
  writeFileSync(join(dir, 'shell.tif'), writeTiff(volumePages(shell, labelData(shell, labels, 16), 16) as never));
  const out = join(dir, 'cli.json');
  runCli([
    'measure',
    '--volume',
    join(dir, 'shell.tif'),
    '--out',
    out,
    '--voxel-size',
    `${VOXEL.x},${VOXEL.y},${VOXEL.z}`,
    '--compare',
    '--realizations',
    '3',
    '--seed',
    '1',
    '--force',
  ]);
  const cli = JSON.parse(readFileSync(out, 'utf8')) as VolumeMeasuredResult;
  let meshes: ShellMeshes | undefined;
  const bytes = new Uint8Array(readFileSync(join(dir, 'shell.tif')));
  const result = measureVolume(
    { name: 'shell.tif', read: () => bytes },
    { voxelSize: VOXEL, version: cli.software.version, onSurfaceMeshes: (m) => (meshes = m) },
  );
  const model = volumeModelDrawing(result, cli.comparison!, meshes).drawing!;
  return { dir, cli, model };
}

/** Model cell `cell`'s (1-based) neighbours on surface k, 1-based, space-separated. */
function modelNeighbours(model: VolumeModelDrawing, k: number, cell: number): string {
  const s = model.surfaces[k];
  return Array.from(s.neighbours.subarray(s.offsets[cell - 1], s.offsets[cell]), (j) => j + 1).join(' ');
}

async function openApp(page: Page): Promise<void> {
  await installLongTaskObserver(page);
  await page.goto(`/?config=${encodeURIComponent(JSON.stringify(small))}`);
  await page.waitForFunction(() => ['done', 'no-webgl', 'error'].includes(document.body.dataset.state ?? ''), null, { timeout: 120_000 });
  await page.waitForTimeout(300);
  await takeLongTasks(page);
}

/** Types into a field as a person does: focus, select all, keys. */
async function type(page: Page, selector: string, text: string): Promise<void> {
  const field = page.locator(selector);
  await field.focus();
  await page.keyboard.press('ControlOrMeta+A');
  await page.keyboard.type(text);
}

const dataValue = async (page: Page, selector: string) => Number(await page.locator(selector).getAttribute('data-value'));

/** CSV rows (comment lines skipped) as objects by header. */
function csvRows(text: string): Record<string, string>[] {
  const body = text
    .split('\r\n')
    .filter((line) => !line.startsWith('#'))
    .join('\r\n');
  const [header, ...rows] = parseCsv(body).records;
  return rows.map((row) => Object.fromEntries(header.map((h, k) => [h, row[k]])));
}

test.describe('measure a volume in the app', () => {
  let inputs: Inputs;
  test.beforeAll(() => {
    inputs = makeVolume(tempDir('volume'));
  });

  test('a 3D TIFF: voxel size asked, measured in a worker as the CLI does, picked, exported, kept in the project', async ({ page }, testInfo) => {
    const cli = inputs.cli;
    expect(cli.comparison).not.toBeNull();
    expect(cli.analyses[0].summary.validCells).toBeGreaterThan(10);
    await openApp(page);
    await type(page, '#measure-realizations', '3');
    await page.locator('#measure-files').setInputFiles(join(inputs.dir, 'shell.tif'));
    // No calibration in the file: the page asks for the voxel size in its fields, and waits.
    const alert = page.locator('#measure-alert');
    await expect(alert).toContainText('shell.tif: no voxel size in the file');
    await expect(alert).toContainText('type the voxel size (µm) in the X, Y and Z fields above');
    await expect(page.locator('#volume-voxel-x')).toBeFocused();
    await expect(page.locator('#volume-results')).toBeHidden();
    // One axis alone is refused, naming the fields.
    await type(page, '#volume-voxel-x', '0.5');
    await page.locator('#measure-again').click();
    await expect(alert).toContainText('voxel size (µm): give all three of X, Y and Z as numbers > 0 (got 0.5, empty, empty)');
    await expect(page.locator('#volume-results')).toBeHidden();
    await type(page, '#volume-voxel-y', '0.5');
    await type(page, '#volume-voxel-z', '0.75');
    await page.locator('#measure-again').click();
    await expect(page.locator('#measure')).toHaveAttribute('data-state', 'compared', { timeout: 150_000 });
    await expectNoLongTasks(page);

    // The CLI's numbers, measured and model (same seed, same realizations).
    const s = cli.analyses[0].summary;
    expect(await dataValue(page, '#volume-measured-percent')).toBe(s.percentScutoids);
    expect(await dataValue(page, '#volume-summary tr[data-key="validCells"] td:nth-of-type(1)')).toBe(s.validCells);
    expect(await dataValue(page, '#volume-summary tr[data-key="meanTransitions"] td:nth-of-type(1)')).toBe(s.meanTransitions);
    const model = cli.comparison!.model;
    expect(await dataValue(page, '#volume-model-percent')).toBe(model.percentScutoids.mean);
    const modelCell = page.locator('#volume-summary tr[data-key="percentScutoids"] td:nth-of-type(2)');
    expect(Number(await modelCell.getAttribute('data-low'))).toBe(model.percentScutoids.ci95[0]);
    expect(Number(await modelCell.getAttribute('data-high'))).toBe(model.percentScutoids.ci95[1]);
    await expect(page.locator('#volume-summary th').nth(2)).toContainText('n = 3');
    await expect(page.locator('#volume-model')).toContainText('a closed shell');
    await expect(page.locator('#volume-info')).toContainText('voxel 0.5 x 0.5 x 0.75 µm (typed in the page)');

    // The model of the same geometry drawn below the tissue: its first realization, every cell on both surfaces.
    const canvas = page.locator('#volume-canvas');
    const drawnModel = inputs.model;
    expect(drawnModel.matches).toBe(true);
    await expect(canvas).toHaveAttribute('data-layout', 'both');
    await expect(canvas).toHaveAttribute('data-model-cells', `${cli.comparison!.cells},${cli.comparison!.cells}`);
    await expect(page.locator('#volume-layout')).toHaveValue('both');
    await expect(page.locator('#volume-drawing-note')).toContainText(
      `realization 1 (seed 1), Voronoi ${cli.comparison!.bestK}, ${cli.comparison!.cells} cells`,
    );
    await expect.poll(async () => (await canvas.boundingBox())!.height).toBeGreaterThan(600);
    await page.waitForTimeout(300); // the drawing worker takes the new size before the click

    // Pick the model cell in the middle of the model's basal view (bottom row): its neighbours on both sides, as the core's.
    let box = (await canvas.boundingBox())!;
    await canvas.click({ position: { x: box.width / 6, y: (3 * box.height) / 4 } });
    const modelInfo = page.locator('#volume-model-cell');
    await expect(modelInfo).toHaveAttribute('data-cell', /^\d+$/);
    const pickedModel = Number(await modelInfo.getAttribute('data-cell'));
    expect(pickedModel).toBeGreaterThanOrEqual(1);
    expect(pickedModel).toBeLessThanOrEqual(drawnModel.cells);
    for (const [k, name] of ['basal', 'apical'].entries()) {
      const expected = modelNeighbours(drawnModel, k, pickedModel);
      expect(expected).not.toBe('');
      await expect(modelInfo).toHaveAttribute(`data-neighbours-${name}`, expected);
      await expect(modelInfo).toContainText(
        `Model ${name} (faces the ${k === 0 ? 'outside' : 'lumen'}): ${drawnModel.surfaces[k].sides[pickedModel - 1]} sides, neighbours ${expected.split(' ').join(', ')}.`,
      );
    }
    await expect(modelInfo).toContainText(
      `Model cell ${pickedModel}: ${drawnModel.valid[pickedModel - 1] ? 'valid' : 'left out'}, ${drawnModel.scutoid[pickedModel - 1] ? 'a scutoid' : 'not a scutoid'}`,
    );
    await expectNoLongTasks(page);

    // Pick the cell in the middle of the tissue's basal view (top row): its neighbours on both sides and its shape.
    box = (await canvas.boundingBox())!;
    const frames = Number(await canvas.getAttribute('data-frames'));
    await canvas.click({ position: { x: box.width / 6, y: box.height / 4 } });
    const info = page.locator('#volume-cell');
    await expect(info).toHaveAttribute('data-label', /\d+/);
    const picked = Number(await info.getAttribute('data-label'));
    const record = cli.cells.find((c) => c.label === picked)!;
    expect(record).toBeDefined();
    await expect(info).toContainText(`basal (faces the outside): ${record.sides[0]} sides`);
    await expect(info).toContainText(`neighbours ${record.neighbours[0].join(', ')}.`);
    await expect(info).toContainText(`neighbours ${record.neighbours[1].join(', ')}.`);
    await expect(info).toHaveAttribute('data-shape', /^[1-9]\d*$/, { timeout: 30_000 });
    // The picked cell is drawn white in the basal view (drawn in a worker: read from a screenshot).
    await expect.poll(async () => Number(await canvas.getAttribute('data-frames'))).toBeGreaterThan(frames);
    await page.waitForTimeout(300);
    const shot = (await canvas.screenshot()).toString('base64');
    const white = await page.evaluate(async (b64) => {
      const bitmap = await createImageBitmap(new Blob([Uint8Array.from(atob(b64), (c) => c.charCodeAt(0))], { type: 'image/png' }));
      const g = new OffscreenCanvas(bitmap.width, bitmap.height).getContext('2d')!;
      g.drawImage(bitmap, 0, 0);
      const d = g.getImageData(0, 0, Math.floor(bitmap.width / 3), Math.floor(bitmap.height / 2)).data;
      let n = 0;
      for (let k = 0; k < d.length; k += 4) if (d[k] > 200 && d[k + 1] > 200 && d[k + 2] > 190 && Math.abs(d[k] - d[k + 2]) < 12) n++;
      return n;
    }, shot);
    expect(white).toBeGreaterThan(20);
    await page.locator('#measure').screenshot({ path: process.env.VOLUME_SHOT ?? testInfo.outputPath('volume-panel.png') });

    // Exports: the JSON is the CLI's document; the CSV equals it and the screen; the figure carries provenance.
    const json = JSON.parse((await download(page, '#volume-json')).text) as VolumeMeasuredResult;
    expect(json.cells).toEqual(cli.cells);
    expect(json.analyses).toEqual(cli.analyses);
    expect(json.comparison!.model).toEqual(model);
    const csv = await download(page, '#volume-cells-csv');
    expect(csv.text).toMatch(/^# tissue-sheet measured volume/);
    expect(csv.text).toContain('voxel 0.5 x 0.5 x 0.75 µm (option');
    const rows = csvRows(csv.text);
    expect(rows.length).toBe(cli.cells.length);
    rows.forEach((row, k) => {
      const cell = cli.cells[k];
      expect(Number(row.label)).toBe(cell.label);
      expect(row.valid).toBe(cell.valid ? '1' : '0');
      expect(row.scutoid).toBe(cell.scutoid ? '1' : '0');
      expect([Number(row.sides_basal), Number(row.sides_apical)]).toEqual(cell.sides);
      expect(row.neighbour_labels_basal).toBe(cell.neighbours[0].join(' '));
      expect(row.neighbour_labels_apical).toBe(cell.neighbours[1].join(' '));
      expect(Number(row.transitions)).toBe(cell.transitions);
      expect(Number(row.volume_um3)).toBe(cell.volume);
      expect(Number(row.area_um2_basal)).toBe(cell.areas[0]);
    });
    const validRows = rows.filter((r) => r.valid === '1');
    expect(validRows.length).toBe(await dataValue(page, '#volume-summary tr[data-key="validCells"] td:nth-of-type(1)'));
    expect((100 * validRows.filter((r) => r.scutoid === '1').length) / validRows.length).toBeCloseTo(await dataValue(page, '#volume-measured-percent'), 9);
    const svg = await download(page, '#volume-figure-svg');
    expect(svg.name).toBe('tissue-sheet-measured-volume.svg');
    expect(svg.text).toContain('tissue-sheet measured volume beside the model of the same geometry');
    expect(svg.text).toMatch(/width="\d+(\.\d+)?mm"/);
    expect(svg.text).toContain('95 % CI');

    const [viewPng] = await Promise.all([page.waitForEvent('download'), page.locator('#volume-view-png').click()]);
    const pngBytes = new Uint8Array(readFileSync((await viewPng.path())!));
    expect([...pngBytes.subarray(1, 4)]).toEqual([0x50, 0x4e, 0x47]);
    const text = readPngText(pngBytes);
    expect(text['tissue-sheet:method']).toContain('contact curves in');
    expect(text.Description).toContain(`picked cell ${picked}`);
    expect(text.Description).toContain('the model of the same geometry (bottom row)');
    expect(text.Description).toContain(`picked model cell ${pickedModel}`);
    expect(JSON.parse(text['tissue-sheet:config']).model).toMatchObject({ realization: 0, seed: 1, k: cli.comparison!.bestK, cells: drawnModel.cells });

    // Kept in the project file; a fresh page opening it shows the same volume and numbers.
    const project = await download(page, '[data-export="project"]');
    const saved = JSON.parse(project.text) as { sections: { measured: { mode: string; files: unknown[] } } };
    expect(saved.sections.measured.mode).toBe('volume');
    expect(saved.sections.measured.files).toHaveLength(1);
    const projectPath = join(inputs.dir, project.name);
    writeFileSync(projectPath, project.text);
    await openApp(page);
    await expect(page.locator('#volume-results')).toBeHidden();
    await page.locator('#open-file').setInputFiles(projectPath);
    await expect(page.locator('#measure-status')).toHaveAttribute('data-reopened', 'same', { timeout: 150_000 });
    expect(await dataValue(page, '#volume-measured-percent')).toBe(s.percentScutoids);
    expect(await dataValue(page, '#volume-model-percent')).toBe(model.percentScutoids.mean);
    await expect(page.locator('#volume-voxel-z')).toHaveValue('0.75');
    await expect(page.locator('#volume-model')).toContainText('As saved in the project');
    // The model is drawn again from the saved comparison: the same realization.
    await expect(page.locator('#volume-canvas')).toHaveAttribute('data-model-cells', `${drawnModel.cells},${drawnModel.cells}`);
    await expect(page.locator('#volume-drawing-note')).toContainText(
      `Voronoi ${cli.comparison!.bestK}, ${drawnModel.cells} cells, ${drawnModel.percentScutoids.toFixed(1)} % scutoids.`,
    );
  });
});

test.describe('which file is which layer', () => {
  test('files handed over apical first are warned about, reassigned with the layer picker, exported and kept in the project', async ({ page }) => {
    const dir = tempDir('layers');
    const width = 256;
    const height = 192;
    const sites = randomSites(70, width, height, 7);
    const labels = sites.map((_, i) => 5 + 3 * i);
    writeFileSync(join(dir, 'basal.png'), png16(rasterizeVoronoi(width, height, sites, labels, true)));
    const apical = png16(
      rasterizeVoronoi(
        2 * width,
        height,
        sites.map(([x, y]) => [2 * x, y]),
        labels,
        true,
      ),
    );
    writeFileSync(join(dir, 'apical.png'), apical);
    await openApp(page);
    await type(page, '#measure-pixel-size', '0.5');
    await page.locator('#measure-periodic').check();
    await type(page, '#measure-realizations', '0');
    // A file dialog's order: alphabetical, apical first.
    await page.locator('#measure-files').setInputFiles([join(dir, 'apical.png'), join(dir, 'basal.png')]);
    await expect(page.locator('#measure')).toHaveAttribute('data-state', /measured|compared/, { timeout: 120_000 });
    const sides = page.locator('#measure-sides');
    await expect(sides).toHaveAttribute('data-warning', /names/);
    await expect(sides).toHaveAttribute('data-warning', /ratio-below-1/);
    const picker = page.locator('#measure-layer-files select[data-file="apical.png"]');
    await expect(picker).toHaveValue('0');
    // Reassign: apical.png is the apical layer.
    await picker.selectOption({ label: '2: apical' });
    await expect(page.locator('#measure-layer-files select[data-file="basal.png"]')).toHaveValue('0', { timeout: 120_000 });
    await expect(page.locator('#measure')).toHaveAttribute('data-state', /measured|compared/, { timeout: 120_000 });
    await expect(sides).toHaveAttribute('data-warning', '');
    await expect(sides).toContainText('Taken as basal: basal.png');
    const ratio = Number((await sides.textContent())!.match(/s = ([\d.]+)/)![1]);
    expect(ratio).toBeGreaterThan(1.9);
    // The CSV follows the screen.
    const json = JSON.parse((await download(page, '#measure-json')).text) as MeasuredResult;
    expect(json.inputs.layers.map((l) => l.file)).toEqual(['basal.png', 'apical.png']);
    const rows = csvRows((await download(page, '#measure-cells-csv')).text);
    expect(rows.map((r) => Number(r.label))).toEqual(json.cells.map((c) => c.label));
    expect(rows.map((r) => r.neighbour_labels_apical)).toEqual(json.cells.map((c) => c.neighbours[1].join(' ')));
    expect(await dataValue(page, '#measured-percent')).toBe(json.analyses[0].summary.percentScutoids);
    // A volume that cannot be read leaves the layers on screen, and the status says so.
    writeFileSync(join(dir, 'cut.tif'), Buffer.from([0x49, 0x49, 0x2a, 0x00, 0x08, 0x00, 0x00, 0x00, 0x01]));
    await page.locator('#measure-files').setInputFiles(join(dir, 'cut.tif'));
    await expect(page.locator('#measure-alert')).toContainText('cut.tif:');
    await expect(page.locator('#measure')).toHaveAttribute('data-state', 'shown');
    await expect(page.locator('#measure-results')).toBeVisible();
    await expect(page.locator('#measure-status')).toContainText('Not measured; the previous tissue is still shown.');
    expect(await dataValue(page, '#measured-percent')).toBe(json.analyses[0].summary.percentScutoids);
    // The project keeps the reassigned order.
    const project = await download(page, '[data-export="project"]');
    const path = join(dir, project.name);
    writeFileSync(path, project.text);
    await openApp(page);
    await page.locator('#open-file').setInputFiles(path);
    await expect(page.locator('#measure-status')).toHaveAttribute('data-reopened', 'same', { timeout: 120_000 });
    await expect(page.locator('#measure-layer-files select[data-file="basal.png"]')).toHaveValue('0');
    expect(await dataValue(page, '#measured-percent')).toBe(json.analyses[0].summary.percentScutoids);
  });
});
