import { afterAll } from 'vitest';
import type { GpuContext } from '../../src/gpu/context';
import { createHeadlessContext } from '../../src/node/headless';

/** One headless-gl context per test file, disposed when the file is done. */
export function useHeadlessContext(): GpuContext {
  const context = createHeadlessContext();
  afterAll(() => context.dispose());
  return context;
}

/** Fraction of texels whose GPU label differs from the reference. */
export function mislabeledFraction(gpu: ArrayLike<number>, reference: ArrayLike<number>): number {
  let wrong = 0;
  for (let i = 0; i < reference.length; i++) if (gpu[i] !== reference[i]) wrong++;
  return wrong / reference.length;
}
