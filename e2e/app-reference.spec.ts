import { expect, test } from '@playwright/test';
import { linkTo, runSweep, smallTube, waitForRun } from './appHelpers';

const HEADER = 'curve,label,kind,quantity,source,x,percent,sd,n';
const USER_SOURCE = 'digitised by hand for this test from no paper at all (test data)';
const csv = (rows: string[]) => ({ name: '', mimeType: 'text/csv', buffer: Buffer.from([HEADER, ...rows].join('\n') + '\n') });

/** Reference curves over the sweep chart (docs/reference-curves.md). */
test('reference curves: the shipped set after a ratio sweep, a user CSV with its source, a bad file refused', async ({ page }) => {
  const small = smallTube(2, 3, 1.5);

  await page.goto(linkTo(small));
  await waitForRun(page);
  const overlay = page.locator('#reference-curves');
  const shipped = overlay.locator('[name="reference-shipped"]');
  const load = overlay.locator('[name="reference-load"]');
  const sources = overlay.locator('[data-reference="sources"] li');
  const notes = overlay.locator('[data-reference="notes"]');
  const alert = overlay.locator('[role="alert"]');
  // No sweep yet: the shipped set is not offered.
  await expect(shipped).toBeDisabled();

  await runSweep(page, 'sheet.surfaceRatio', 1, 3, 3);

  // The shipped set: Voronoi 4 (this configuration's lloyd.maxIterations + 1), dashed, with its
  // own legend entry and its source listed; the configuration differences said in words.
  await expect(shipped).toBeEnabled();
  await shipped.check();
  await expect(overlay).toHaveAttribute('data-drawn', '1');
  await expect(page.locator('#chart-sweep')).toHaveAttribute('data-reference-curves', '1');
  await expect(page.locator('#chart-sweep .u-legend')).toContainText('tissue-sheet, Voronoi 4 (model)');
  await expect(sources).toHaveCount(1);
  await expect(sources.first()).toContainText('computed by tissue-sheet');
  await expect(sources.first()).toContainText('not numbers taken from the paper');
  await expect(sources.first()).toContainText('tissue-sheet, Voronoi 4 (model)');
  await expect(notes).toContainText(
    "1 of 26 curves drawn; not drawn: x is voronoiK, the sweep varies surfaceRatio (17); held at another voronoiK than the sweep's voronoiK = 4 (8)",
  );
  await expect(notes).toContainText('cells 200 there, 60 here');
  await expect(notes).toContainText('compare the trend, not the values');
  // The chart's own points are still the runs' three ratios.
  await expect(page.locator('#chart-sweep')).toHaveAttribute('data-points', '3');

  // The shipped points carry SD and n = 20: each has its 95 % CI error bar.
  const bars = async () => Number(await page.locator('#chart-sweep').getAttribute('data-reference-error-bars'));
  await expect.poll(bars).toBeGreaterThan(3);
  const shippedBars = await bars();

  // A user's CSV: its curve is added with its source.
  await load.setInputFiles({
    ...csv([`paper,My digitised curve,data,surfaceRatio,"${USER_SOURCE}",1,0,,`, `paper,My digitised curve,data,surfaceRatio,"${USER_SOURCE}",2,55.5,4.2,20`]),
    name: 'digitised.csv',
  });
  await expect(overlay).toHaveAttribute('data-drawn', '2');
  await expect(page.locator('#chart-sweep .u-legend')).toContainText('My digitised curve (data)');
  await expect(sources).toHaveCount(2);
  await expect(sources.nth(1)).toContainText(USER_SOURCE);
  await expect(alert).toBeHidden();
  // Error bars: the point with SD 4.2 and n 20 gets its 95 % CI (t(0.975, 19) = 2.093:
  // 55.5 ± 1.97), the point without has none, and the notes say which curve has them.
  await expect.poll(bars).toBe(shippedBars + 1);
  await expect(notes).toContainText('My digitised curve: error bars (95 % CI of the mean, from SD and n) on 1 of 2 points');
  await expect(notes).toContainText('tissue-sheet, Voronoi 4: error bars are the 95 % CI of the mean');
  await load.setInputFiles({ ...csv([`bare,Bare curve,data,surfaceRatio,"${USER_SOURCE}",1.5,20,,`]), name: 'bare.csv' });
  await expect(notes).toContainText('Bare curve: no error bars (its file gives no SD and n ≥ 2 for its points)');
  expect(await bars()).toBe(shippedBars + 1);

  // A bad file: a specific message in role=alert, and what was shown stays.
  await load.setInputFiles({ ...csv([`bad,Bad,data,surfaceRatio,"${USER_SOURCE}",1,150,,`]), name: 'bad.csv' });
  await expect(alert).toBeVisible();
  await expect(alert).toContainText('bad.csv: line 2, column percent: 150 is outside 0..100');
  await expect(overlay).toHaveAttribute('data-drawn', '3');

  // A curve over another quantity is not drawn, and the page says why.
  await load.setInputFiles({ ...csv([`byk,By k,data,voronoiK,"${USER_SOURCE}",1,10,,`]), name: 'by-k.csv' });
  await expect(notes).toContainText('by-k.csv: no curve drawn (x is voronoiK, the sweep varies surfaceRatio (1))');
  await expect(overlay).toHaveAttribute('data-drawn', '3');

  // The downloads hold the runs only.
  const download = page.waitForEvent('download');
  await page.locator('[data-sweep="runs-csv"]').click();
  const text = await (await (await download).createReadStream()).toArray();
  const runsCsv = Buffer.concat(text).toString();
  expect(runsCsv.split(/\r?\n/).filter(Boolean)).toHaveLength(4);
  expect(runsCsv).not.toContain('digitised');
  expect(runsCsv).not.toContain('Voronoi 4');
});
