import { validateAnyConfig, type Config } from '../src/core/config';

/**
 * validateAnyConfig for tests that build planes and tubes and read their planar fields (width,
 * radius, length): a closed kind fails the test here instead of surfacing later as an undefined
 * field. The library itself never narrows this way: a config becomes a surface in
 * src/core/config/surfaceLayout.ts.
 */
export function validateConfig(input: unknown): Config {
  const config = validateAnyConfig(input);
  if (config.surface.kind !== 'plane' && config.surface.kind !== 'tube') {
    throw new Error(`tests/planarConfig: "${config.surface.kind}" is not a planar surface`);
  }
  return config as Config;
}
