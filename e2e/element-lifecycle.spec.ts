import { expect, test } from '@playwright/test';
import { openElementExample } from './elementHelpers';

/**
 * `<tissue-sheet>` over its life in a page: elements added and removed give their WebGL context
 * back (a browser keeps about 16 and silently drops the oldest beyond that), an element moved in
 * the DOM draws again, and a context lost anyway is said (an `error` event and the status line),
 * never a silently blank view. Tiny runs (30 cells).
 */

const SMALL = { cells: '30', resolution: '64', iterations: '2', radius: '20', length: '256', 'surface-ratio': '2', realizations: '1' };

test('removed elements release their WebGL context; a long-lived element keeps its view, moved or not, and says when its context is lost', async ({ page }) => {
  await openElementExample(page, { waitForRuns: false });
  const outcome = await page.evaluate(async (small) => {
    const make = (attributes: Record<string, string>) => {
      const element = document.createElement('tissue-sheet') as HTMLElement & { run(): Promise<unknown> };
      for (const [k, v] of Object.entries(attributes)) element.setAttribute(k, v);
      return element;
    };
    const glOf = (element: HTMLElement) => element.shadowRoot!.querySelector('canvas')!.getContext('webgl2')!;
    const resultOf = (element: HTMLElement) => new Promise((resolve) => element.addEventListener('result', resolve, { once: true }));
    const keep = make({ ...small, id: 'keep' });
    const errors: { message: string; name: string }[] = [];
    keep.addEventListener('error', (e) => errors.push((e as unknown as CustomEvent).detail));
    let first = resultOf(keep);
    document.body.append(keep);
    await first;
    // More elements than the browser keeps contexts, each added (its view made) and removed.
    for (let i = 0; i < 24; i++) {
      const temporary = make({ ...small, manual: '', seed: String(i + 2) });
      document.body.append(temporary);
      await new Promise((resolve) => requestAnimationFrame(resolve));
      temporary.remove();
    }
    await new Promise((resolve) => setTimeout(resolve, 500));
    const keptAfterMany = !glOf(keep).isContextLost();
    // Moved in the DOM: its view is made again and draws.
    first = resultOf(keep);
    keep.remove();
    document.body.prepend(keep);
    await first;
    const movedAlive = !glOf(keep).isContextLost();
    const blob = (await (keep as unknown as { toBlob(): Promise<Blob> }).toBlob()).size;
    const errorsBefore = errors.length;
    // A context lost anyway is said.
    const lose = glOf(keep).getExtension('WEBGL_lose_context')!;
    lose.loseContext();
    await new Promise((resolve) => setTimeout(resolve, 300));
    const status = keep.shadowRoot!.querySelector('.status')!.textContent;
    return { keptAfterMany, movedAlive, blob, errorsBefore, errors, status };
  }, SMALL);
  expect(outcome.keptAfterMany).toBe(true);
  expect(outcome.movedAlive).toBe(true);
  expect(outcome.blob).toBeGreaterThan(1000);
  expect(outcome.errorsBefore).toBe(0);
  expect(outcome.errors).toHaveLength(1);
  expect(outcome.errors[0].name).toBe('WebGLContextLostError');
  expect(outcome.errors[0].message).toContain('lost its WebGL context');
  expect(outcome.status).toContain('lost its WebGL context');
});

test('set after connection: an unknown attribute warns, a bad density and a config that is not an object are refused naming them', async ({ page }) => {
  await openElementExample(page, { waitForRuns: false });
  const outcome = await page.evaluate(async (small) => {
    const element = document.createElement('tissue-sheet') as HTMLElement & { run(): Promise<unknown>; config: unknown; configError: string | null };
    for (const [k, v] of Object.entries({ ...small, manual: '' })) element.setAttribute(k, v);
    const events: { type: string; detail: { message: string; field?: string; attribute?: string; suggestion?: string } }[] = [];
    for (const type of ['warning', 'error']) element.addEventListener(type, (e) => events.push({ type, detail: (e as unknown as CustomEvent).detail }));
    document.body.append(element);
    const tick = () => new Promise((resolve) => setTimeout(resolve, 50));
    await tick();
    const status = () => element.shadowRoot!.querySelector('.status')!.textContent;
    element.setAttribute('cels', '5');
    await tick();
    const afterUnknown = { events: events.splice(0), status: status() };
    element.setAttribute('cels', '6'); // the same unknown attribute: said once
    await tick();
    const again = events.splice(0);
    element.removeAttribute('cels');
    element.setAttribute('density', 'gausian');
    const density = await element.run().then(
      () => 'ran',
      (e: Error & { field?: string }) => ({ name: e.name, field: e.field, message: e.message }),
    );
    const densityEvents = events.splice(0);
    element.removeAttribute('density');
    let setter: unknown = 'did not throw';
    try {
      element.config = 5;
    } catch (e) {
      setter = { name: (e as Error).name, field: (e as { field?: string }).field, message: (e as Error).message };
    }
    const configEvents = events.splice(0);
    const stillRuns = await element.run().then(
      () => 'ran',
      (e: Error) => e.message,
    );
    return { afterUnknown, again, density, densityEvents, setter, configEvents, stillRuns, statusAfter: status() };
  }, SMALL);
  expect(outcome.afterUnknown.events).toEqual([
    { type: 'warning', detail: { message: 'unknown attribute "cels" ignored (did you mean "cells"?)', attribute: 'cels', suggestion: 'cells' } },
  ]);
  expect(outcome.afterUnknown.status).toContain('unknown attribute "cels" ignored');
  expect(outcome.again).toEqual([]);
  const densityMessage = 'density: must be one of "uniform", "linear", "gaussian", "stripes", "image" (got "gausian")';
  expect(outcome.density).toEqual({ name: 'ConfigError', field: 'density.kind', message: densityMessage });
  expect(outcome.densityEvents.map((e) => [e.type, e.detail.message, e.detail.field])).toEqual([['error', densityMessage, 'density.kind']]);
  expect(outcome.setter).toMatchObject({ name: 'ConfigError', field: 'config' });
  expect((outcome.setter as { message: string }).message).toMatch(/^config: expected a configuration object \(or null\), got a number/);
  expect(outcome.configEvents.map((e) => [e.type, e.detail.field])).toEqual([['error', 'config']]);
  expect(outcome.stillRuns).toBe('ran');
  expect(outcome.statusAfter).not.toContain('cels');
});
