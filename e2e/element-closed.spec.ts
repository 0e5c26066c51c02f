import { expect, test } from '@playwright/test';
import { openElementExample } from './elementHelpers';

/**
 * `<tissue-sheet>` on closed surfaces (Debian's Chromium, SwiftShader): surface="sphere",
 * "ellipsoid", "mesh" with `src` or the `meshFile` property. Small runs (32 texels per cube-face
 * edge, 80 cells, 2 Lloyd iterations).
 */

/** A small sphere (32 texels per cube-face edge, 80 cells, 2 Lloyd iterations), run on demand. */
const SPHERE = { manual: '', surface: 'sphere', radius: '50', resolution: '32', cells: '80', iterations: '2', thickness: '15' };

test('sphere, ellipsoid and mesh (meshFile, src) attributes; a genus-1 mesh fires an error and the view stays', async ({ page }) => {
  await openElementExample(page);
  const outcome = await page.evaluate(async (attributes) => {
    const element = document.createElement('tissue-sheet');
    for (const [name, value] of Object.entries(attributes)) element.setAttribute(name, value);
    document.body.append(element);
    const errors: { message: string; field?: string }[] = [];
    element.addEventListener('error', (e) => errors.push(e.detail));
    const sphere = await element.run();
    const sphereConfig = element.config;

    element.setAttribute('surface', 'ellipsoid');
    for (const [name, value] of Object.entries({ a: '80', b: '40', c: '40' })) element.setAttribute(name, value);
    const ellipsoid = await element.run();

    element.setAttribute('surface', 'mesh');
    element.setAttribute('scale', '50');
    element.setAttribute('thickness', '5');
    const data = await (await fetch('/meshes/organoid.ply')).arrayBuffer();
    element.meshFile = { data, name: 'my-organoid.ply' };
    const mesh = await element.run();
    const blob = await element.toBlob();

    element.meshFile = null;
    element.setAttribute('src', '/meshes/torus.ply');
    const failed = await element.run().then(
      () => 'resolved',
      (e: Error) => e.name,
    );
    return {
      sphere: { kind: sphere.closed?.kind, percent: sphere.analyses[0].summary.percentScutoids, cells: sphere.cells.length, n: sphere.closed?.n },
      sphereConfig,
      ellipsoid: { kind: ellipsoid.closed?.kind, axes: ellipsoid.config.surface },
      mesh: { src: mesh.closed?.mesh?.src, vertices: mesh.closed?.mesh?.vertices },
      blobSize: blob.size,
      failed,
      errors,
      stillShown: element.result?.closed?.mesh?.src,
      caption: element.shadowRoot!.querySelector('.status')!.textContent,
    };
  }, SPHERE);
  expect(outcome.sphere).toEqual({ kind: 'sphere', percent: 0, cells: 80, n: 32 });
  expect(outcome.sphereConfig.surface).toEqual({ kind: 'sphere', radius: 50 });
  expect(outcome.ellipsoid).toEqual({ kind: 'ellipsoid', axes: { kind: 'ellipsoid', a: 80, b: 40, c: 40 } });
  expect(outcome.mesh).toEqual({ src: 'my-organoid.ply', vertices: 2562 });
  expect(outcome.blobSize).toBeGreaterThan(2000);
  expect(outcome.failed).toBe('ConfigError');
  expect(outcome.errors).toHaveLength(1);
  expect(outcome.errors[0].field).toBe('surface.src');
  expect(outcome.errors[0].message).toContain('surface.src: /meshes/torus.ply: genus 1: this mesh has a hole through it');
  expect(outcome.stillShown).toBe('my-organoid.ply');
  expect(outcome.caption).toContain('genus 1');
});

test('cell-hover: the cell under the pointer on a sphere, null once the pointer leaves', async ({ page }) => {
  await openElementExample(page);
  await page.evaluate(async (attributes) => {
    const element = document.createElement('tissue-sheet');
    element.id = 'hover-sphere';
    for (const [name, value] of Object.entries(attributes)) element.setAttribute(name, value);
    element.style.cssText = 'position:fixed;left:0;top:0;width:400px;height:300px;z-index:100;display:block';
    document.body.append(element);
    const events: unknown[] = [];
    (window as unknown as { hoverEvents: unknown[] }).hoverEvents = events;
    element.addEventListener('cell-hover', (e) => events.push((e as CustomEvent).detail));
    await element.run();
  }, SPHERE);
  const canvas = page.locator('#hover-sphere').locator('canvas').first();
  const box = (await canvas.boundingBox())!;
  await page.mouse.move(box.x + box.width / 2 - 4, box.y + box.height / 2 - 4);
  await page.mouse.move(box.x + box.width / 2, box.y + box.height / 2, { steps: 3 });
  await page.waitForFunction(() => (window as unknown as { hoverEvents: unknown[] }).hoverEvents.length > 0);
  const first = (await page.evaluate(() => (window as unknown as { hoverEvents: unknown[] }).hoverEvents[0])) as { cell: number; surface: number };
  expect(first.cell).toBeGreaterThanOrEqual(0);
  expect(first.cell).toBeLessThan(80);
  // The outer surface (apical, index 1) faces the camera at the sphere's centre.
  expect(first.surface).toBe(1);
  await page.mouse.move(box.x + box.width + 50, box.y + box.height + 50);
  await page.waitForFunction(() => {
    const events = (window as unknown as { hoverEvents: unknown[] }).hoverEvents;
    return events[events.length - 1] === null;
  });
});
