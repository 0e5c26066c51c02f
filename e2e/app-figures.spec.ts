import { writeFileSync } from 'node:fs';
import { expect, test, type Page } from '@playwright/test';
import { download, downloadExport, linkTo, smallTube, waitForRun } from './appHelpers';
import { tempDir } from './cli';
import { readPngDpi, readPngText } from '../tests/app/pngRead';
import { parseCsv } from '../src/core/sweep/csv';
import { join } from 'node:path';
import { png16, randomSites, rasterizeVoronoi } from '../tests/measure/images';

/**
 * Issue 26, figures a journal takes: the cell figure, the sweep chart and the Flintstones fit as
 * SVG (printed at the chosen width in mm) and PNG (at the chosen DPI); legends whose swatches and
 * texts never overlap; axis labels with units, n and CI, the numbers shown; provenance (version,
 * configuration, seed, engine, method) in the files' metadata.
 */

const SMALL = smallTube(2, 3, 1.5);

type Box = { x: number; y: number; width: number; height: number; what: string };

/** The bounding boxes of every legend swatch and text, measured by the browser. */
async function legendBoxes(page: Page, svg: string): Promise<Box[]> {
  return page.evaluate((text) => {
    const host = document.createElement('div');
    host.innerHTML = text.replace(/^<\?xml[^>]*>/, '');
    document.body.append(host);
    const boxes = [...host.querySelectorAll<SVGGraphicsElement>('.legend-swatch, .legend-text')].map((el) => {
      const b = el.getBBox();
      return { x: b.x, y: b.y, width: b.width, height: b.height, what: el.textContent || el.getAttribute('class') || '' };
    });
    host.remove();
    return boxes;
  }, svg);
}

function overlaps(boxes: Box[]): string[] {
  const out: string[] = [];
  for (let i = 0; i < boxes.length; i++) {
    for (let j = i + 1; j < boxes.length; j++) {
      const a = boxes[i];
      const b = boxes[j];
      if (a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height) out.push(`${a.what} / ${b.what}`);
    }
  }
  return out;
}

function svgSize(svg: string): { widthMm: number; heightMm: number; box: number[] } {
  return {
    widthMm: Number(/<svg[^>]* width="([\d.]+)mm"/.exec(svg)![1]),
    heightMm: Number(/<svg[^>]* height="([\d.]+)mm"/.exec(svg)![1]),
    box: /viewBox="([^"]+)"/.exec(svg)![1].split(' ').map(Number),
  };
}

test('the cell figure: SVG printed at the chosen width, the headline on it, a legend that overlaps nothing, the border swatch as the cells are drawn', async ({
  page,
}) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await page.waitForFunction(() => document.body.dataset.headline === 'complete', undefined, { timeout: 120_000 });
  await page.locator('#figure-width').fill('120');
  const svg = (await downloadExport(page, 'svg')).text;
  if (process.env.FIGURE_DIR) writeFileSync(`${process.env.FIGURE_DIR}/cells.svg`, svg);
  const size = svgSize(svg);
  expect(size.widthMm).toBe(120);
  expect(size.heightMm).toBeCloseTo((120 * size.box[3]) / size.box[2], 2);
  // 1 printed mm is this many µm (not "1 µm = 1 mm").
  const perMm = Number(/data-units-per-mm="([\d.]+)"/.exec(svg)![1]);
  expect(perMm).toBeCloseTo(size.box[2] / 120, 2);
  expect(svg).toContain('data-units="µm"');
  const mean = Number(await page.locator('#percent-scutoids').getAttribute('data-value'));
  expect(svg).toMatch(new RegExp(`<text id="headline"[^>]*>${mean.toFixed(1)} % scutoids \\(mean of n = 5, 95 % CI`));
  expect(overlaps(await legendBoxes(page, svg))).toEqual([]);
  expect(svg).toMatch(/<rect x="[\d.-]+" y="[\d.-]+" width="[\d.]+" height="[\d.]+" fill="#282828"\/><rect class="legend-swatch"[^>]*fill-opacity="0.35"/);
  const meta = JSON.parse(
    /<metadata id="tissue-sheet-provenance">([^<]*)<\/metadata>/
      .exec(svg)![1]
      .replace(/&quot;/g, '"')
      .replace(/&amp;/g, '&'),
  );
  expect(meta.engine.name).toBe('exact');
  expect(meta.method).toBe('exact');
  expect(meta.headline.realizations).toBe(5);
  expect(meta.seed).toBe(2);
});

test('the sweep chart and the Flintstones fit as SVG and PNG: units, n, CI, numbers, provenance, nothing overlapping', async ({ page }) => {
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await page.locator('[name="sweep-field"]').selectOption('sheet.surfaceRatio');
  await page.locator('[name="sweep-from"]').fill('1');
  await page.locator('[name="sweep-to"]').fill('4');
  await page.locator('[name="sweep-steps"]').fill('4');
  await page.locator('[name="sweep-realizations"]').fill('2');
  await page.locator('[data-sweep="run"]').click();
  await page.locator('#sweep[data-done="8"]').waitFor({ timeout: 120_000 });
  await expect(page.locator('[data-sweep="fit-svg"]')).toBeEnabled();
  await page.locator('#figure-width').fill('90');
  await page.locator('#figure-dpi').selectOption('600');

  if (process.env.FIGURE_DIR) writeFileSync(`${process.env.FIGURE_DIR}/runs.csv`, (await download(page, '[data-sweep="runs-csv"]')).bytes);
  const chart = (await download(page, '[data-sweep="chart-svg"]')).text;
  expect(svgSize(chart).widthMm).toBe(90);
  expect(chart).toContain('>% scutoids (of valid cells)</text>');
  expect(chart).toContain('>Surface ratio R_outer / R_inner</text>');
  const notes = [...chart.matchAll(/<text class="note"[^>]*>([^<]*)<\/text>/g)].map((m) => m[1]).join(' ');
  expect(notes).toContain('n = 2 realizations per point');
  expect(notes).toContain('95 % confidence interval of the mean (Student&apos;s t)');
  expect(chart).toContain('exact method: mean % scutoids, 95 % CI band');
  expect([...chart.matchAll(/<text class="value"/g)]).toHaveLength(4);
  expect(chart).toContain('class="band"');
  expect(overlaps(await legendBoxes(page, chart))).toEqual([]);
  const meta = JSON.parse(
    /<metadata id="tissue-sheet-provenance">([^<]*)<\/metadata>/
      .exec(chart)![1]
      .replace(/&quot;/g, '"')
      .replace(/&amp;/g, '&'),
  );
  expect(meta.engine).toBe('exact engine');
  expect(meta.method).toBe('exact');
  expect(meta.config.vary['sheet.surfaceRatio']).toEqual([1, 2, 3, 4]);

  const png = await download(page, '[data-sweep="chart-png"]');
  if (process.env.FIGURE_DIR) writeFileSync(`${process.env.FIGURE_DIR}/sweep-chart.png`, png.bytes);
  expect(png.name).toBe('tissue-sheet-sweep-chart-600dpi.png');
  expect(readPngDpi(new Uint8Array(png.bytes))).toBeCloseTo(600, 1);
  expect(png.bytes.readUInt32BE(16)).toBe(Math.round((90 / 25.4) * 600));
  const text = readPngText(new Uint8Array(png.bytes));
  expect(text['tissue-sheet:engine']).toBe('exact engine');
  expect(text['tissue-sheet:method']).toBe('exact');
  expect(JSON.parse(text['tissue-sheet:config']).base.cells).toBe(60);

  const fit = (await download(page, '[data-sweep="fit-svg"]')).text;
  expect(fit).toContain('>mean 3D neighbours n3D (cells)</text>');
  expect(fit).toContain('>surface ratio s = R_outer / R_inner</text>');
  expect(fit).toMatch(/class="note"[^>]*>Voronoi 4: /);
  expect(overlaps(await legendBoxes(page, fit))).toEqual([]);
  const fitPng = await download(page, '[data-sweep="fit-png"]');
  if (process.env.FIGURE_DIR) writeFileSync(`${process.env.FIGURE_DIR}/fit.png`, fitPng.bytes);
  expect(readPngDpi(new Uint8Array(fitPng.bytes))).toBeCloseTo(600, 1);
});

test('the measured-vs-model comparison as SVG and PNG: bars per layer, the model line, both % scutoids, provenance', async ({ page }) => {
  const dir = tempDir('figures-measure');
  const sites = randomSites(60, 256, 192, 7);
  const labels = sites.map((_, i) => 5 + i);
  writeFileSync(join(dir, 'basal.png'), png16(rasterizeVoronoi(256, 192, sites, labels, true)));
  writeFileSync(
    join(dir, 'apical.png'),
    png16(
      rasterizeVoronoi(
        512,
        192,
        sites.map(([x, y]) => [2 * x, y]),
        labels,
        true,
      ),
    ),
  );
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await page.locator('#measure-pixel-size').fill('0.5');
  await page.locator('#measure-periodic').check();
  await page.locator('#measure-realizations').fill('2');
  await page.locator('#measure-files').setInputFiles([join(dir, 'basal.png'), join(dir, 'apical.png')]);
  await expect(page.locator('#measure')).toHaveAttribute('data-state', 'compared', { timeout: 120_000 });
  await page.locator('#figure-width').fill('85');
  const svg = (await download(page, '#measure-figure-svg')).text;
  expect(svgSize(svg).widthMm).toBe(85);
  expect(svg).toContain('>% of valid cells</text>');
  expect(svg).toContain('>sides (cells with n sides)</text>');
  expect(svg).toMatch(/data-label="measured basal \(basal.png\)"/);
  expect(svg).toMatch(/data-label="model Voronoi \d+, basal, mean of 2 realizations"/);
  const notes = [...svg.matchAll(/<text class="note"[^>]*>([^<]*)<\/text>/g)].map((m) => m[1]).join(' ');
  const measured = Number(await page.locator('#measured-percent').getAttribute('data-value'));
  expect(notes).toContain(`Measured: ${measured.toFixed(1)} % scutoids`);
  expect(notes).toMatch(/% scutoids \(mean ± SD over n = 2 realizations\)/);
  expect(overlaps(await legendBoxes(page, svg))).toEqual([]);
  const png = await download(page, '#measure-figure-png');
  expect(readPngDpi(new Uint8Array(png.bytes))).toBeCloseTo(300, 1);
  const text = readPngText(new Uint8Array(png.bytes));
  expect(text['tissue-sheet:method']).toContain('pixel-based adjacency');
  expect(JSON.parse(text['tissue-sheet:config']).model.realizations).toBe(2);
  if (process.env.FIGURE_DIR) writeFileSync(`${process.env.FIGURE_DIR}/measured.png`, png.bytes);

  // The measured tissue's per-cell CSV parses back to the page's numbers.
  const csv = (await download(page, '#measure-cells-csv')).text;
  expect(csv).toMatch(/^# tissue-sheet measured tissue, per-cell table/);
  expect(csv).toContain('# layers (the first is basal): basal: basal.png; apical: apical.png');
  const [header, ...records] = parseCsv(
    csv
      .split(/\r?\n/)
      .filter((l) => !l.startsWith('#'))
      .join('\r\n'),
  ).records;
  for (const column of ['label', 'valid', 'scutoid', 'sides_basal', 'sides_apical', 'won', 'lost', 'transitions', 'area_um2_basal', 'neighbour_labels_apical'])
    expect(header).toContain(column);
  const rows = records.filter((r) => r.length === header.length).map((r) => Object.fromEntries(r.map((v, k) => [header[k], v])));
  const valid = rows.filter((r) => r.valid === '1');
  const scutoids = valid.filter((r) => r.scutoid === '1');
  expect(Number(((100 * scutoids.length) / valid.length).toFixed(6))).toBeCloseTo(measured, 6);
});

test('measure: the page says which file it takes as basal and warns when s < 1 (files handed over apical first)', async ({ page }) => {
  const dir = tempDir('figures-sides');
  const sites = randomSites(60, 256, 192, 7);
  const labels = sites.map((_, i) => 5 + i);
  writeFileSync(
    join(dir, 'basal.png'),
    png16(
      rasterizeVoronoi(
        512,
        192,
        sites.map(([x, y]) => [2 * x, y]),
        labels,
        true,
      ),
    ),
  );
  writeFileSync(join(dir, 'apical.png'), png16(rasterizeVoronoi(256, 192, sites, labels, true)));
  await page.goto(linkTo(SMALL));
  await waitForRun(page);
  await page.locator('#measure-pixel-size').fill('0.5');
  await page.locator('#measure-periodic').check();
  await page.locator('#measure-realizations').fill('0');
  // A file dialog hands them over alphabetically: apical.png first.
  await page.locator('#measure-files').setInputFiles([join(dir, 'apical.png'), join(dir, 'basal.png')]);
  const sides = page.locator('#measure-sides');
  await expect(sides).toContainText('Taken as basal: apical.png; as apical: basal.png', { timeout: 120_000 });
  await expect(sides).toHaveAttribute('data-warning', 'names');
  await expect(sides).toContainText('the file taken as basal is named apical.png');
  // Reversed: basal.png (the wider, as in a gland) is basal, and s < 1 is said, never silent.
  await page.locator('#measure-reverse').click();
  await expect(sides).toContainText('Taken as basal: basal.png; as apical: apical.png', { timeout: 120_000 });
  await expect(sides).toHaveAttribute('data-warning', 'ratio-below-1');
  await expect(sides).toContainText('s = 0.500 < 1');
});
