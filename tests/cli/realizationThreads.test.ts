/**
 * `tissue-sheet run`'s realization threads (src/cli/realizationThreads.ts), with a stand-in
 * thread module (tests/cli/fixtures/realizationThread.mjs) that computes fake headlines, fails or
 * exits on purpose: the headline is the same whichever thread computed what, a realization that
 * fails in a thread fails the whole headline with its error (as the CLI's error class), and a
 * thread lost after taking a realization hands it back to the main thread.
 */
import { describe, expect, it } from 'vitest';
import type { Headline } from '../../src/core/analysis/headline';
import { combineHeadlines } from '../../src/core/analysis/realizations';
import { ConfigError, type Config } from '../../src/core/config';
import type { GpuCapabilities } from '../../src/gpu/context';
import { RealizationThreads } from '../../src/cli/realizationThreads';

const ENTRY = new URL('./fixtures/realizationThread.mjs', import.meta.url).href;
const SEEDS = [11, 12, 13, 14, 15, 16];
const CAPABILITIES = { renderer: 'none' } as unknown as GpuCapabilities;

/** The fake headline the fixture computes for a seed, made here independently of it. */
function fake(seed: number): Headline {
  return {
    method: 'exact',
    protocol: 'default',
    percentScutoids: seed % 7,
    meanTransitions: seed % 3,
    meanNeighbours3D: 6 + (seed % 2),
  } as unknown as Headline;
}

const sleep = (ms: number) => new Promise((resolve) => setTimeout(resolve, ms));

async function headlineWith(fixture: string, threads: number, runHere: (seed: number, index: number) => Promise<Headline | null>, taken?: Int32Array) {
  const fromThreads: number[] = [];
  const config = { fixture, taken } as unknown as Config;
  const pool = new RealizationThreads(threads, config, SEEDS, CAPABILITIES, {}, (index) => fromThreads.push(index), ENTRY);
  try {
    const headline = await pool.headline(fake(SEEDS[0]), runHere, new AbortController().signal);
    return { headline, fromThreads };
  } finally {
    await pool.close();
  }
}

describe('RealizationThreads', () => {
  const expected = combineHeadlines(SEEDS.map(fake), SEEDS);

  it('combines the realizations in seed order whichever thread computed them', async () => {
    const here: number[] = [];
    // The main thread is slow, so the threads take most realizations.
    const { headline, fromThreads } = await headlineWith('ok', 2, async (seed, index) => {
      here.push(index);
      await sleep(150);
      return fake(seed);
    });
    expect(headline).toEqual(expected);
    expect([...here, ...fromThreads].sort()).toEqual([1, 2, 3, 4, 5]);
    expect(fromThreads.length).toBeGreaterThan(0);
  });

  it('fails with the error of a realization that failed in a thread, as the CLI class', async () => {
    const run = headlineWith('fail', 1, async (seed) => {
      await sleep(200);
      return fake(seed);
    });
    await expect(run).rejects.toThrow(ConfigError);
    await expect(run).rejects.toThrow(/realization \d failed on purpose/);
  });

  it('computes on the main thread a realization that a lost thread had taken', async () => {
    const taken = new Int32Array(new SharedArrayBuffer(4));
    const here: number[] = [];
    const { headline, fromThreads } = await headlineWith(
      'exit',
      1,
      async (seed, index) => {
        here.push(index);
        // Wait until the thread has taken one (and died with it), so the hand-back is exercised.
        for (let t = 0; Atomics.load(taken, 0) === 0 && t < 100; t++) await sleep(20);
        return fake(seed);
      },
      taken,
    );
    const lost = Atomics.load(taken, 0) - 1;
    expect(lost).toBeGreaterThan(0);
    expect(fromThreads).toEqual([]);
    expect(here.sort()).toEqual([1, 2, 3, 4, 5]);
    expect(here).toContain(lost);
    expect(headline).toEqual(expected);
  });
});
