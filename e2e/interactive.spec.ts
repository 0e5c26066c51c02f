import { readFileSync, writeFileSync } from 'node:fs';
import { join } from 'node:path';
import { expect, test, type Page } from '@playwright/test';
import { download, linkTo, runs, waitForRun } from './appHelpers';
import { runCli, tempDir } from './cli';
import { installLongTaskObserver, takeLongTasks } from './pages/longTasks';
import { readCsvTable } from '../src/core/sweep/csv';
import { readRunsCsv } from '../src/core/sweep/runner';

/**
 * Issue 15 on Debian's Chromium: the pipeline in its worker keeps the page's main thread free
 * (PerformanceObserver 'longtask': no task over 50 ms) during a run, a slider drag and a sweep;
 * a drag streams pictures; the page's sweep and `<tissue-sheet>.sweep()` give the CLI's runs and
 * aggregate; cancelling keeps the finished runs and Resume completes them. Small sizes: 128-texel
 * tubes, at most 60 cells.
 */

const small = {
  surface: { kind: 'tube', radius: 128 / (2 * Math.PI), length: 256 },
  resolution: 128,
  cells: 60,
  seed: 3,
  lloyd: { maxIterations: 4 },
  sheet: { surfaceRatio: 1.5 },
};

test.describe('the app stays responsive', () => {
  // A long task is the browser's own scheduling on a shared 2-core machine as much as ours: a
  // heavily loaded machine can push one layout past 50 ms. The limit stays; a retry measures again.
  test.describe.configure({ retries: 2 });
  test('no main-thread task over 50 ms during a run, a slider drag and a sweep; the drag streams pictures', async ({ page }) => {
    await installLongTaskObserver(page);
    await page.goto(linkTo(small));
    await waitForRun(page, 0);
    await expect(page.locator('body')).toHaveAttribute('data-compute-site', 'worker');
    await takeLongTasks(page); // loading the page (modules, WebGL contexts) is not a run

    let before = await runs(page);
    await page.locator('#run').click();
    await waitForRun(page, before);
    const duringRun = await takeLongTasks(page);

    // A drag: input events every 30 ms for 1.5 s, then the slider's change.
    before = await runs(page);
    const pictures = await page.evaluate(async () => {
      const slider = document.querySelector<HTMLInputElement>('input[name="sheet.surfaceRatio"]')!;
      const seen = new Set<string>();
      const observer = new MutationObserver(() => seen.add(document.body.dataset.runs ?? ''));
      observer.observe(document.body, { attributes: true, attributeFilter: ['data-runs'] });
      for (let k = 0; k <= 50; k++) {
        slider.value = String(1.2 + (k * 2) / 50);
        slider.dispatchEvent(new Event('input', { bubbles: true }));
        await new Promise((resolve) => setTimeout(resolve, 30));
      }
      slider.dispatchEvent(new Event('change', { bubbles: true }));
      observer.disconnect();
      return seen.size;
    });
    await waitForRun(page, before);
    await expect(page.locator('input[name="sheet.surfaceRatio"]')).toHaveValue('3.2');
    // The drag showed drafts (one pixel per texel); once it settles the pictures are drawn in
    // full: the unrolled basal surface at twice its texels (exactScale(surface, 2) here).
    const basal = page.locator('#unrolled canvas').first();
    const texels = Number(/(\d+) x \d+ texels/.exec((await basal.getAttribute('aria-label')) ?? '')?.[1]);
    expect(texels).toBeGreaterThan(0);
    await expect.poll(() => basal.evaluate((c: HTMLCanvasElement) => c.width), { timeout: 10_000 }).toBe(2 * texels);
    const duringDrag = await takeLongTasks(page);

    await page.locator('[name="sweep-to"]').fill('2.5');
    await page.locator('[name="sweep-steps"]').fill('3');
    await page.locator('[name="sweep-realizations"]').fill('2');
    await page.locator('[data-sweep="run"]').click();
    await expect(page.locator('#sweep')).toHaveAttribute('data-done', '6', { timeout: 120_000 });
    const duringSweep = await takeLongTasks(page);
    await expect(page.locator('#chart-sweep')).toHaveAttribute('data-points', '3');

    console.log(
      `long tasks (ms): run ${JSON.stringify(duringRun)}, drag ${JSON.stringify(duringDrag)} (${pictures} pictures during the drag), sweep ${JSON.stringify(duringSweep)}`,
    );
    expect(pictures).toBeGreaterThan(1);
    for (const tasks of [duringRun, duringDrag, duringSweep]) expect(Math.max(0, ...tasks)).toBeLessThan(50);
  });

  test('a cancelled sweep keeps its finished runs; Resume computes the rest; the downloads are the CLI files', async ({ page }) => {
    await page.goto(linkTo(small));
    await waitForRun(page, 0);
    await page.locator('[name="sweep-to"]').fill('2.5');
    await page.locator('[name="sweep-steps"]').fill('2');
    await page.locator('[name="sweep-realizations"]').fill('3');
    // Cancel as soon as two runs are finished (in the page: the runs are fast).
    await page.evaluate(() => {
      const sweep = document.querySelector<HTMLElement>('#sweep')!;
      new MutationObserver((_changes, observer) => {
        if (Number(sweep.dataset.finished ?? 0) < 2) return;
        observer.disconnect();
        sweep.querySelector<HTMLButtonElement>('[data-sweep="cancel"]')!.click();
      }).observe(sweep, { attributes: true, attributeFilter: ['data-finished'] });
    });
    await page.locator('[data-sweep="run"]').click();
    await expect(page.locator('#sweep')).toHaveAttribute('data-state', 'cancelled', { timeout: 60_000 });
    const kept = readRunsCsv((await download(page, '[data-sweep="runs-csv"]')).text).rows;
    expect(kept.length).toBeGreaterThanOrEqual(2);
    expect(kept.length).toBeLessThan(6);

    await page.locator('[data-sweep="resume"]').click();
    await expect(page.locator('#sweep')).toHaveAttribute('data-state', 'done', { timeout: 120_000 });
    const all = readRunsCsv((await download(page, '[data-sweep="runs-csv"]')).text);
    expect(all.rows).toHaveLength(6);
    // The kept rows are the first ones of the file, unchanged.
    expect(all.rows.slice(0, kept.length)).toEqual(kept);
    expect(new Set(all.rows.map((r) => r.key)).size).toBe(6);
    expect(all.header.slice(0, 4)).toEqual(['key', 'sheet.surfaceRatio', 'realization', 'seed']);
    // Seeded reuse: realization outer, ratio inner (the CLI's order).
    const aggregate = readCsvTable((await download(page, '[data-sweep="aggregate-csv"]')).text);
    expect(aggregate.rows.map((r) => [r['sheet.surfaceRatio'], r.runs])).toEqual([
      ['1', '3'],
      ['2.5', '3'],
    ]);
  });
});

test.describe('<tissue-sheet>.sweep()', () => {
  const spec = {
    base: {
      surface: { kind: 'tube', radius: 128 / (2 * Math.PI), length: 256 },
      resolution: 128,
      cells: 40,
      seed: 9,
      engine: 'exact',
      lloyd: { maxIterations: 2 },
      sheet: { thickness: 0 },
    },
    vary: { 'sheet.surfaceRatio': [1.5, 2.5] },
    realizations: 2,
    seedMode: 'per-realization',
  };

  test.beforeEach(async ({ page }) => {
    await page.goto('/e2e/pages/interactive.html');
    await expect(page).toHaveTitle('ready');
  });

  const sweep = (page: Page, input: unknown) =>
    page.evaluate(
      (input) => (window as unknown as { tissueSheetInteractive: { sweep(i: unknown): Promise<Record<string, unknown>> } }).tissueSheetInteractive.sweep(input),
      input,
    );

  test('gives the runs and the aggregate of `tissue-sheet sweep` for the same spec, with a sweep-progress event per run', async ({ page }) => {
    const inPage = await sweep(page, { spec });
    const dir = tempDir('sweep');
    writeFileSync(join(dir, 'spec.json'), JSON.stringify(spec));
    runCli(['sweep', join(dir, 'spec.json'), '--out', join(dir, 'out')]);
    const cliRuns = readRunsCsv(readFileSync(join(dir, 'out', 'runs.csv'), 'utf8'));
    const cliAggregate = readFileSync(join(dir, 'out', 'aggregate.csv'), 'utf8');

    console.log(
      `element sweep: ${(inPage.runs as unknown[]).length} runs in ${Math.round(inPage.ms as number)} ms, long tasks ${JSON.stringify(inPage.longTasks)}`,
    );
    expect(inPage.header).toEqual(cliRuns.header);
    const byKey = (rows: Record<string, string>[]) => Object.fromEntries(rows.map((r) => [r.key, r]));
    expect(byKey(inPage.runs as Record<string, string>[])).toEqual(byKey(cliRuns.rows));
    expect(inPage.aggregateCsv).toBe(cliAggregate);
    expect((inPage.aggregate as { points: unknown[] }).points).toHaveLength(2);
    expect((inPage.progress as { hasRow: boolean }[]).filter((p) => p.hasRow)).toHaveLength(4);
    expect(inPage.aborted).toBe(false);
    expect(Math.max(0, ...(inPage.longTasks as number[]))).toBeLessThan(50);
  });

  test("spreads a Voronoi k x ratio grid over a pool of Web Workers with the CLI's reuse and the CLI's rows", async ({ page }) => {
    // 2 Voronoi k x 2 ratios x 3 realizations: 3 Lloyd runs (one per realization), each serving
    // both k and both ratios on one worker.
    const grid = { ...spec, vary: { 'lloyd.maxIterations': [0, 2], 'sheet.surfaceRatio': [1.5, 2.5] }, realizations: 3 };
    const cores = await page.evaluate(() => navigator.hardwareConcurrency);
    const inPage = await sweep(page, { spec: grid, workers: 2 });
    const dir = tempDir('sweep-pool');
    writeFileSync(join(dir, 'spec.json'), JSON.stringify(grid));
    runCli(['sweep', join(dir, 'spec.json'), '--out', join(dir, 'out')]);
    console.log(`pool sweep: ${(inPage.runs as unknown[]).length} runs on ${inPage.workers} workers (${cores} cores) in ${Math.round(inPage.ms as number)} ms`);
    expect(inPage.workers).toBe(2);
    // By default the pool leaves one core to the page.
    const byDefault = await sweep(page, { spec: grid });
    expect(byDefault.workers).toBe(Math.max(1, Math.min(cores - 1, 8, 3)));
    expect(byDefault.runsCsv).toBe(inPage.runsCsv);
    expect(inPage.runsCsv).toBe(readFileSync(join(dir, 'out', 'runs.csv'), 'utf8'));
    expect(inPage.aggregateCsv).toBe(readFileSync(join(dir, 'out', 'aggregate.csv'), 'utf8'));
    expect((inPage.progress as { hasRow: boolean }[]).filter((p) => p.hasRow)).toHaveLength(12);
    expect(Math.max(0, ...(inPage.longTasks as number[]))).toBeLessThan(50);
  });

  test('aborting keeps the finished runs; resuming from their runs.csv completes the same sweep', async ({ page }) => {
    const full = await sweep(page, { spec });
    const cut = await sweep(page, { spec, abortAfter: 1 });
    expect(cut.aborted).toBe(true);
    const kept = cut.runs as Record<string, string>[];
    expect(kept.length).toBeGreaterThanOrEqual(1);
    expect(kept.length).toBeLessThan(4);
    const resumed = await sweep(page, { spec, resume: cut.runsCsv });
    expect(resumed.skipped).toBe(kept.length);
    expect(resumed.completed).toBe(4 - kept.length);
    const sorted = (rows: unknown) => [...(rows as Record<string, string>[])].sort((a, b) => a.key.localeCompare(b.key));
    expect(sorted(resumed.runs)).toEqual(sorted(full.runs));
    expect(resumed.aggregateCsv).toBe(full.aggregateCsv);
  });

  test("the worker's pictures are the views' own: exact cells in full, painted label images in drafts", async ({ page }) => {
    const config = {
      surface: { kind: 'tube', radius: 128 / (2 * Math.PI), length: 256 },
      resolution: 128,
      cells: 40,
      seed: 4,
      lloyd: { maxIterations: 2 },
      sheet: { surfaceRatio: 2 },
    };
    const rows = await page.evaluate(
      (config) =>
        (window as unknown as { tissueSheetInteractive: { pictures(c: unknown): Promise<Record<string, unknown>[]> } }).tissueSheetInteractive.pictures(config),
      config,
    );
    console.log(`worker pictures: ${JSON.stringify(rows)}`);
    // basal and apical, each for the 3D view's texture and the unrolled diagram
    expect(rows).toHaveLength(4);
    for (const row of rows) {
      expect(row.full).toBe('ImageBitmap');
      expect(row.fullDiffering).toBeLessThanOrEqual(1e-3);
      expect(row.draftDiffering).toBe(0);
    }
    // Full pictures at the views' scales; drafts at one pixel per texel.
    for (const row of rows as { grid: number[]; scale: number; fullSize: number[]; draftSize: number[] }[]) {
      expect(row.fullSize).toEqual(row.grid.map((n) => Math.round(n * row.scale)));
      expect(row.draftSize).toEqual(row.grid);
      expect(row.scale).toBeGreaterThan(1);
    }
  });

  test('a bad spec is refused with the field named, before any run', async ({ page }) => {
    const result = await page.evaluate(() =>
      (window as unknown as { tissueSheetInteractive: { badSweep(s: unknown): Promise<{ name: string; message: string }> } }).tissueSheetInteractive.badSweep({
        base: { cells: 40 },
        vary: { 'sheet.ratio': [1, 2] },
      }),
    );
    expect(result.name).toBe('SweepSpecError');
    expect(result.message).toMatch(/^vary\["sheet.ratio"\]: "ratio" is not a field/);
  });
});
